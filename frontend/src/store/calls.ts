// What a box or block calls: a library entry (function, function block, a program's `Prog.M`), else the method
// `inst.M` of a declared function block instance (CODESYS). LD and FBD draw and bind their calls alike.
import type { LibraryEntry, SymbolInfo } from "../generated/api";

/** A library entry by the name a call writes (case-insensitive). */
export type Lookup = (call: string) => LibraryEntry | undefined;

/** The type a symbol declares for the root of an operand (`Motor`, not `T1.Q`); undefined otherwise. */
export function symbolType(text: string, symbols: readonly SymbolInfo[]): string | undefined {
  const name = text.trim().toUpperCase();
  return symbols.find((s) => s.name.toUpperCase() === name)?.type.toUpperCase();
}

/**
 * The method a block `inst.M` calls (CODESYS): `M` among the methods of the function block `inst` is declared
 * as (the library lists a user FB's PUBLIC methods); undefined when `call` names none.
 */
export function methodEntry(call: string, lookup: Lookup, symbols: readonly SymbolInfo[]): LibraryEntry | undefined {
  const dot = call.lastIndexOf(".");
  if (dot < 0) return undefined;
  const fb = symbolType(call.slice(0, dot), symbols);
  const method = call
    .slice(dot + 1)
    .trim()
    .toUpperCase();
  return (fb ? lookup(fb) : undefined)?.methods?.find((m) => m.name.toUpperCase() === method);
}

/**
 * What the block picker offers beside the library: `inst.M` for each PUBLIC method of every instance in `symbols` of
 * a function block that has methods (CODESYS), as a function entry named by the instance.
 */
export function instanceMethodEntries(symbols: readonly SymbolInfo[], lookup: Lookup): LibraryEntry[] {
  return symbols.flatMap((s) => {
    const fb = lookup(s.type);
    return fb?.kind === "function_block" ? (fb.methods ?? []).map((m) => ({ ...m, name: `${s.name}.${m.name}` })) : [];
  });
}

/** What a block calls: a function or function block of the library, else a method (`inst.M`). */
export function blockEntry(call: string, lookup: Lookup, symbols: readonly SymbolInfo[]): LibraryEntry | undefined {
  return lookup(call) ?? methodEntry(call, lookup, symbols);
}

/** What a box or block picker offers: the library, then `inst.M` for the instances' methods. */
export function pickableCalls(library: readonly LibraryEntry[], symbols: readonly SymbolInfo[], lookup: Lookup) {
  return [...library, ...instanceMethodEntries(symbols, lookup)];
}
