// Paths a trace can record, for the path input's autocomplete: every BOOL or numeric variable of
// every program (PROGRAM.var), the globals (by name), and the BOOL/numeric inputs and outputs of
// function block instances (PROGRAM.inst.Q), from the symbols endpoint and the library.
import type { LibraryEntry, SymbolInfo, SymbolTable } from "../generated/api";
import { ALIASES, ELEMENTARY } from "../iec/vocabulary";

/** Every elementary type but STRING (a trace plots numbers), by any of its names (iec/vocabulary.ts). */
const TRACEABLE = new Set([...ELEMENTARY, ...Object.keys(ALIASES)].filter((t) => (ALIASES[t] ?? t) !== "STRING"));

export const traceable = (type: string): boolean => TRACEABLE.has(type.trim().toUpperCase());

function members(prefix: string, symbol: SymbolInfo, blocks: ReadonlyMap<string, LibraryEntry>): string[] {
  if (traceable(symbol.type)) return [`${prefix}${symbol.name}`];
  const block = blocks.get(symbol.type.trim().toUpperCase());
  if (!block) return [];
  return [...block.inputs, ...block.outputs]
    .filter((pin) => traceable(pin.type))
    .map((pin) => `${prefix}${symbol.name}.${pin.name}`);
}

/** Candidate paths, programs first in the order given, then globals; no repeats. */
export function traceCandidates(programs: readonly SymbolTable[], library: readonly LibraryEntry[]): string[] {
  const blocks = new Map(library.filter((e) => e.kind === "function_block").map((e) => [e.name.toUpperCase(), e]));
  const out = new Set<string>();
  for (const table of programs) {
    for (const symbol of table.symbols) {
      if (symbol.var_class === "VAR_EXTERNAL") continue; // a global: listed by its own name below
      for (const path of members(`${table.pou}.`, symbol, blocks)) out.add(path);
    }
  }
  for (const table of programs)
    for (const symbol of table.globals) for (const path of members("", symbol, blocks)) out.add(path);
  return [...out];
}
