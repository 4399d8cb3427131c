// Paths a trace can record, for the path input's autocomplete: every BOOL or numeric variable of
// every program (PROGRAM.var), the globals (by name), and the BOOL/numeric inputs and outputs of
// function block instances (PROGRAM.inst.Q), from the symbols endpoint and the library.
import type { LibraryEntry, SymbolInfo, SymbolTable } from "../generated/api";
import { ALIASES, ELEMENTARY } from "../iec/vocabulary";

/** Every elementary type but STRING (a trace plots numbers), by any of its names (iec/vocabulary.ts). */
const TRACEABLE = new Set([...ELEMENTARY, ...Object.keys(ALIASES)].filter((t) => (ALIASES[t] ?? t) !== "STRING"));

export const traceable = (type: string): boolean => TRACEABLE.has(type.trim().toUpperCase());

/** A path a view can show with the IEC type of its value. */
export interface Candidate {
  path: string;
  type: string;
}

function members(prefix: string, symbol: SymbolInfo, blocks: ReadonlyMap<string, LibraryEntry>): Candidate[] {
  if (traceable(symbol.type)) return [{ path: `${prefix}${symbol.name}`, type: symbol.type }];
  const block = blocks.get(symbol.type.trim().toUpperCase());
  if (!block) return [];
  return [...block.inputs, ...block.outputs]
    .filter((pin) => traceable(pin.type))
    .map((pin) => ({ path: `${prefix}${symbol.name}.${pin.name}`, type: pin.type }));
}

/** Candidate paths with their types, programs first in the order given, then globals; no repeats. */
export function candidates(programs: readonly SymbolTable[], library: readonly LibraryEntry[]): Candidate[] {
  const blocks = new Map(library.filter((e) => e.kind === "function_block").map((e) => [e.name.toUpperCase(), e]));
  const out = new Map<string, Candidate>();
  const add = (found: Candidate[]) => found.forEach((c) => out.has(c.path) || out.set(c.path, c));
  for (const table of programs) {
    for (const symbol of table.symbols) {
      if (symbol.var_class === "VAR_EXTERNAL") continue; // a global: listed by its own name below
      add(members(`${table.pou}.`, symbol, blocks));
    }
  }
  for (const table of programs) for (const symbol of table.globals) add(members("", symbol, blocks));
  return [...out.values()];
}

/** Candidate paths, programs first in the order given, then globals; no repeats. */
export const traceCandidates = (programs: readonly SymbolTable[], library: readonly LibraryEntry[]): string[] =>
  candidates(programs, library).map((c) => c.path);
