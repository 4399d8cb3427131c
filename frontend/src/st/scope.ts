// The names an ST POU's editor knows while the user types: the POU's own declarations from the
// working copy when they read as a table (so a variable declared a moment ago completes and shows
// online before a save), else the saved symbol table; the globals; the library, with the working
// copy's function blocks in their current form; the STRUCT types.
import { parseDeclarations } from "../iec/declarations";
import type { LibraryEntry, SymbolInfo, SymbolTable } from "../generated/api";
import type { Pou, SfcBody } from "../generated/api";
import { structTypes, type Scope } from "./members";

/** The POU's own symbols from its declaration text, or null when the text does not read as a table. */
export function declaredSymbols(declarations: string): SymbolInfo[] | null {
  const parsed = parseDeclarations(declarations);
  if (!parsed.ok) return null;
  return parsed.rows.map((r) => ({
    name: r.name,
    var_class: r.varClass.split(" ")[0]!,
    type: r.type,
    initial: r.initial || null,
    address: r.address || null,
    comment: r.comment || null,
    retain: /\bRETAIN\b/.test(r.varClass),
    constant: /\bCONSTANT\b/.test(r.varClass),
  }));
}

/** A function block, function or method as the library describes it: its parameters from its `symbols`. */
export function callable(
  name: string,
  kind: LibraryEntry["kind"],
  symbols: readonly SymbolInfo[],
  returns: string | null,
): LibraryEntry {
  const pins = (varClass: string) =>
    symbols.filter((s) => s.var_class === varClass).map((s) => ({ name: s.name, type: s.type }));
  return {
    name,
    kind,
    source: "user",
    inputs: pins("VAR_INPUT"),
    outputs: pins("VAR_OUTPUT"),
    in_outs: pins("VAR_IN_OUT"),
    extensible: false,
    return_type: returns,
    comment: null,
  };
}

/**
 * The library with each function block of the working copy described by its current declarations
 * (an FB created or changed since the last save), its base's pins first (EXTENDS, as the checker lists them); an
 * FB whose text does not read as a table keeps its saved entry (and it keeps its saved methods).
 */
export function workingLibrary(library: readonly LibraryEntry[], pous: readonly Pou[]): LibraryEntry[] {
  const saved = new Map(library.map((e) => [e.name.toUpperCase(), e]));
  const working = pous.flatMap((pou): LibraryEntry[] => {
    const own = pou.kind === "function_block" ? declaredSymbols(pou.declarations ?? "") : null;
    if (!own) return [];
    const symbols = withInherited({ symbols: own, library: [], structs: new Map() }, pou, pous).symbols;
    return [
      {
        ...callable(pou.name, "function_block", symbols, null),
        methods: saved.get(pou.name.toUpperCase())?.methods ?? [], // as saved: methods are not in the declarations
      },
    ];
  });
  const replaced = new Set(working.map((e) => e.name.toUpperCase()));
  return [...library.filter((e) => !replaced.has(e.name.toUpperCase())), ...working];
}

type ChartElement = NonNullable<NonNullable<SfcBody["chart"]>["elements"]>[number];

/** The step names of a chart's elements, down its branches (a step is the element with a name). */
const stepNames = (elements: readonly ChartElement[]): string[] =>
  elements.flatMap((e) => ("branches" in e ? e.branches.flatMap(stepNames) : "name" in e ? [e.name] : []));

/** The implicit variables of an SFC POU's working chart that code reads (SFC-06, docs/sfc.md): each step of its
 * chart an SFC_STEP (`Idle.X`, `Idle.T`), each action an ACTION_CONTROL (`Fill.Q`, `Fill.A`); none for another
 * POU. */
export function chartSymbols(pou: Pou): SymbolInfo[] {
  const body = pou.language === "sfc" && typeof pou.body === "object" && "chart" in pou.body ? pou.body : null;
  const states = [
    ...stepNames(body?.chart?.elements ?? []).map((name) => ({ name, type: "SFC_STEP" })),
    ...(body?.actions ?? []).map((a) => ({ name: a.name, type: "ACTION_CONTROL" })),
  ];
  return states.map((s) => ({
    ...s,
    var_class: "VAR",
    initial: null,
    address: null,
    comment: null,
    retain: false,
    constant: false,
  }));
}

export function stScope(
  table: SymbolTable | undefined,
  declarations: string,
  types: string,
  library: readonly LibraryEntry[],
): Scope {
  const own = declaredSymbols(declarations) ?? table?.symbols ?? [];
  return { symbols: [...own, ...(table?.globals ?? [])], library, structs: structTypes(types) };
}

/** Function block (or program) `pou`, then the FBs it EXTENDS in the working copy, nearest first; a cycle or an
 * unknown base ends the walk (the check reports those). */
export function lineage(pou: Pou, pous: readonly Pou[]): Pou[] {
  const chain = [pou];
  for (let base = pou.extends?.trim().toUpperCase(); base && !chain.some((p) => p.name.toUpperCase() === base);) {
    const fb = pous.find((p) => p.kind === "function_block" && p.name.toUpperCase() === base);
    if (!fb) break;
    chain.push(fb);
    base = fb.extends?.trim().toUpperCase();
  }
  return chain;
}

/** The FB's scope with the variables of its base FBs (EXTENDS, nearest first) that it does not redeclare. */
export function withInherited(scope: Scope, pou: Pou, pous: readonly Pou[]): Scope {
  const declared = (name: string) =>
    scope.symbols.some((t) => t.var_class !== "VAR_GLOBAL" && t.name.toUpperCase() === name.toUpperCase());
  const inherited: Scope["symbols"][number][] = [];
  for (const fb of lineage(pou, pous).slice(1))
    for (const s of declaredSymbols(fb.declarations ?? "") ?? [])
      if (!declared(s.name) && !inherited.some((t) => t.name.toUpperCase() === s.name.toUpperCase())) inherited.push(s);
  // before the globals: an instance variable hides a global of the same name
  return inherited.length ? { ...scope, symbols: [...inherited, ...scope.symbols] } : scope;
}
