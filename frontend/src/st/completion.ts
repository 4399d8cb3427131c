// Autocomplete for ST: the POU's variables and the globals (from the symbols endpoint), standard
// and user functions and FB types (from /api/library). Calls insert a formal-parameter template
// (`TON1(IN := , PT := , Q => , ET => );`); an FB instance variable offers the call of its type.
import type { Completion, CompletionContext, CompletionResult } from "@codemirror/autocomplete";
import type { LibraryEntry, SymbolInfo } from "../generated/api";

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
  `(${[...entry.inputs, ...entry.in_outs].map((p) => `${p.name}: ${p.type}`).join(", ")})` + (entry.return_type ? ` : ${entry.return_type}` : "");

/** Every completion for a POU, variables first; names are matched case-insensitively by CodeMirror. */
export function stCompletions(symbols: SymbolInfo[], library: LibraryEntry[]): Completion[] {
  const byName = new Map(library.map((e) => [e.name.toUpperCase(), e]));
  const variables = symbols.map((s): Completion => {
    const fb = byName.get(s.type.toUpperCase());
    return fb?.kind === "function_block"
      ? { label: s.name, type: "variable", detail: s.type, apply: callTemplate(s.name, fb), info: `${s.var_class} ${s.name} : ${s.type} (inserts the call)` }
      : { label: s.name, type: "variable", detail: s.type, info: `${s.var_class} ${s.name} : ${s.type}${s.comment ? ` - ${s.comment}` : ""}` };
  });
  const functions = library
    .filter((e) => e.kind === "function")
    .map((e): Completion => ({ label: e.name, type: "function", detail: signature(e), apply: callTemplate(e.name, e), info: e.comment ?? undefined }));
  const fbTypes = library
    .filter((e) => e.kind === "function_block")
    .map((e): Completion => ({ label: e.name, type: "class", detail: "function block", info: e.comment ?? undefined }));
  return [...variables, ...functions, ...fbTypes];
}

/** A CodeMirror completion source over `options()` (read at each request, so it follows the symbols). */
export function stCompletionSource(options: () => Completion[]) {
  return (context: CompletionContext): CompletionResult | null => {
    const word = context.matchBefore(/[A-Za-z_][A-Za-z0-9_]*/);
    if (!word && !context.explicit) return null;
    return { from: word ? word.from : context.pos, options: options(), validFor: /^[A-Za-z0-9_]*$/ };
  };
}
