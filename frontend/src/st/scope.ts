// The names an ST POU's editor knows while the user types: the POU's own declarations from the
// working copy when they read as a table (so a variable declared a moment ago completes and shows
// online before a save), else the saved symbol table; the globals; the library; the STRUCT types.
import { parseDeclarations } from "../declarations/model";
import type { LibraryEntry, SymbolInfo, SymbolTable } from "../generated/api";
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

export function stScope(table: SymbolTable | undefined, declarations: string, types: string, library: readonly LibraryEntry[]): Scope {
  const own = declaredSymbols(declarations) ?? table?.symbols ?? [];
  return { symbols: [...own, ...(table?.globals ?? [])], library, structs: structTypes(types) };
}
