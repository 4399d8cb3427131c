// Autocomplete for ST: the POU's variables and the globals (from the symbols endpoint), standard
// and user functions and FB types (from /api/library). Calls insert a formal-parameter template
// (`TON1(IN := , PT := , Q => , ET => );`); an FB instance variable offers the call of its type.
// After `inst.` or `s.` it offers the members of that variable's type (FB pins, struct fields) and an FB instance's
// methods; after a program's name, its inputs and outputs and its methods (`Prog.M(...)`, CODESYS); after an
// enumeration type's `Color.` or `Color#`, its values; after `THIS^.` / `SUPER^.` and `r^.`, what they reach.
// Keywords and elementary types come last, from the backend's vocabulary (iec/vocabulary.ts).
import type { Completion, CompletionContext, CompletionResult } from "@codemirror/autocomplete";
import type { LibraryEntry, SymbolInfo } from "../generated/api";
import { ALIASES, DECLARABLE_TYPES, KEYWORDS } from "../iec/vocabulary";
import { QUALIFIER_PART as PART, reach, type Scope } from "./members";

/** The formal call of `entry` by `callee` (a function name or an FB instance). */
export function callTemplate(callee: string, entry: LibraryEntry): string {
  const params = [
    ...entry.inputs.map((p) => `${p.name} := `),
    ...entry.in_outs.map((p) => `${p.name} := `),
    ...entry.outputs.map((p) => `${p.name} => `),
  ];
  const call = `${callee}(${params.join(", ")})`;
  return entry.kind === "function_block" ? `${call};` : call;
}

const signature = (entry: LibraryEntry) =>
  `(${[...entry.inputs, ...entry.in_outs].map((p) => `${p.name}: ${p.type}`).join(", ")})` +
  (entry.return_type ? ` : ${entry.return_type}` : "");

/** Every completion for a POU, variables first; names are matched case-insensitively by CodeMirror. `project`
 * adds its programs, enumerations and INTERFACEs (projectNames). */
export function stCompletions(
  symbols: SymbolInfo[],
  library: LibraryEntry[],
  project: Pick<Scope, "interfaces" | "qualifiers"> = {},
): Completion[] {
  const byName = new Map(library.map((e) => [e.name.toUpperCase(), e]));
  const variables = symbols.map((s): Completion => {
    const fb = byName.get(s.type.toUpperCase());
    return fb?.kind === "function_block"
      ? {
          label: s.name,
          type: "variable",
          detail: s.type,
          apply: callTemplate(s.name, fb),
          info: `${s.var_class} ${s.name} : ${s.type} (inserts the call)`,
        }
      : {
          label: s.name,
          type: "variable",
          detail: s.type,
          info: `${s.var_class} ${s.name} : ${s.type}${s.comment ? ` - ${s.comment}` : ""}`,
        };
  });
  const functions = library
    .filter((e) => e.kind === "function" && !e.name.includes(".")) // a program's `Prog.M`: offered after `Prog.`
    .map((e): Completion => ({
      label: e.name,
      type: "function",
      detail: signature(e),
      apply: callTemplate(e.name, e),
      info: e.comment ?? undefined,
    }));
  const fbTypes = library
    .filter((e) => e.kind === "function_block")
    .map((e): Completion => ({ label: e.name, type: "class", detail: "function block", info: e.comment ?? undefined }));
  return [...variables, ...functions, ...fbTypes, ...projectNames(project, symbols), ...LANGUAGE_WORDS];
}

/** The project's programs (`Prog.` is followed by their inputs, outputs and methods), enumerations and INTERFACEs,
 * but those a variable's name hides. */
function projectNames(project: Pick<Scope, "interfaces" | "qualifiers">, symbols: SymbolInfo[]): Completion[] {
  const hidden = new Set(symbols.map((s) => s.name.toUpperCase()));
  const named = [...(project.qualifiers?.values() ?? [])].flatMap((q): Completion[] =>
    q.kind === "PROGRAM" || q.kind === "PLANT"
      ? [{ label: q.name, type: "namespace", detail: q.kind }]
      : q.kind === "enumeration"
        ? [{ label: q.name, type: "type", detail: "enumeration", info: `(${q.members.map((m) => m.name).join(", ")})` }]
        : [],
  );
  const interfaces = [...(project.interfaces?.values() ?? [])].map((i): Completion => ({
    label: i.name,
    type: "interface",
    detail: "INTERFACE",
  }));
  return [...named, ...interfaces].filter((c) => !hidden.has(c.label.toUpperCase()));
}

/** The grammar's keywords and the elementary type names, ranked below the POU's own names. */
const LANGUAGE_WORDS: readonly Completion[] = [
  ...[...KEYWORDS].map((word): Completion => ({ label: word, type: "keyword", boost: -50 })),
  ...[...DECLARABLE_TYPES, ...Object.keys(ALIASES)].map((name): Completion => ({
    label: name,
    type: "type",
    detail: ALIASES[name] ?? "elementary type",
    boost: -40,
  })),
];

/**
 * What may follow `chain.` (e.g. ["Timer"] -> IN, PT, Q, ET), as members.ts `reach` finds it: the members of its
 * type or qualifier (a program's inputs and outputs, an enumeration's values, `THIS^`'s variables), then the methods
 * it calls - a function block's PUBLIC methods, or a program's (`Prog.M`); after `Color#` (separator "#") the
 * enumeration's values. Null when there is nothing.
 */
export function memberCompletions(
  chain: readonly string[],
  scope: Scope,
  separator: "." | "#" = ".",
): Completion[] | null {
  const reached = reach(chain, scope, separator);
  if (!reached) return null;
  const { members, owner } = reached;
  const methods = reached.methods ?? (reached.methodsOf ? methodsOf(reached.methodsOf, scope) : []);
  if (members.length === 0 && methods.length === 0) return null;
  // Boosted in declaration order, so the list reads like the FB's interface (inputs first), not alphabetically.
  const boost = (i: number) => -Math.min(i, 99);
  return [
    ...members.map((m, i) => ({
      label: m.name,
      type: m.kind === "value" ? "enum" : "property",
      detail: m.type,
      info: `${m.kind === "field" ? "field" : m.kind} of ${owner}`,
      boost: boost(i),
    })),
    ...methods.map((m, i) => ({
      label: m.name,
      type: "method",
      detail: signature(m),
      apply: callTemplate(m.name, m),
      info: `METHOD of ${owner}`,
      boost: boost(members.length + i),
    })),
  ];
}

/** The methods called on an instance of `owner` (named without their owner): those of the function block or
 * interface of that name, else the program's (library entries `Prog.M`). */
function methodsOf(owner: string, scope: Scope): readonly LibraryEntry[] {
  const upper = owner.trim().toUpperCase();
  const fb = scope.library.find((e) => e.kind === "function_block" && e.name.toUpperCase() === upper);
  if (fb?.methods?.length) return fb.methods;
  const itf = scope.interfaces?.get(upper);
  if (itf) return itf.methods;
  const prefix = `${upper}.`;
  return scope.library
    .filter((e) => e.kind === "function" && e.name.toUpperCase().startsWith(prefix))
    .map((e) => ({ ...e, name: e.name.slice(prefix.length) }));
}

/** What the editor completes from: the words of the POU and the members of a chain. */
export interface StCompletions {
  options: Completion[];
  /** What follows `chain.` (or `chain#`: an enumeration's values), memberCompletions. */
  members(chain: readonly string[], separator: "." | "#"): Completion[] | null;
}

/** A member being typed: `a.b.` (a part may be indexed or dereferenced: `a[i].`, `r^.`, `THIS^.`), or an
 * enumeration's `Color#`. */
const QUALIFIED = new RegExp(String.raw`(?:${PART}(?:\.${PART})*\.|[A-Za-z_][A-Za-z0-9_]*#)[A-Za-z0-9_]*`);

/** A CodeMirror completion source over `completions()` (read at each request, so it follows the symbols). */
export function stCompletionSource(completions: () => StCompletions) {
  return (context: CompletionContext): CompletionResult | null => {
    const access = context.matchBefore(QUALIFIED);
    if (access) {
      const separator = access.text.includes("#") ? "#" : ".";
      const parts = access.text.split(/[.#]/);
      const members = completions().members(parts.slice(0, -1), separator);
      if (!members) return null; // `x.` on something without members (or `T#`): nothing sensible to offer
      return { from: context.pos - parts[parts.length - 1]!.length, options: members, validFor: /^[A-Za-z0-9_]*$/ };
    }
    const word = context.matchBefore(/[A-Za-z_][A-Za-z0-9_]*/);
    if (!word && !context.explicit) return null;
    // A keyword or type typed out in full is not offered again, so Enter after `THEN` starts a new line.
    const typed = word?.text.toUpperCase();
    const options = completions().options.filter((o) => !(LANGUAGE_WORDS.includes(o) && o.label === typed));
    return { from: word ? word.from : context.pos, options, validFor: /^[A-Za-z0-9_]*$/ };
  };
}
