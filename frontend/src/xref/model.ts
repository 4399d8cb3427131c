// The cross-reference list as the panel shows it: which entry an operand names (its POU's own variable
// first, else the global), filtering, and where an access is, in words. The list itself comes from the
// backend (GET /api/projects/{name}/xref), built from the checker and the lowering: nothing here
// decides what is read or written.
import type { Diagnostic, XrefAccess, XrefEntry } from "../generated/api";

/** The variable an operand text starts from: `RunTimer` of `RunTimer.Q`, `arr` of `arr[i]`, `%IX0.0`. */
export function rootOf(operand: string): string | null {
  const text = operand.trim().replace(/^NOT\s+/i, "");
  const found = /^%[A-Za-z]+[0-9.]*|^[A-Za-z_][A-Za-z0-9_]*/.exec(text);
  return found ? found[0] : null;
}

const same = (a: string | null | undefined, b: string | null | undefined) =>
  (a ?? "").toUpperCase() === (b ?? "").toUpperCase();

/** The entry `operand` refers to inside `pou`: the POU's own variable, else the global (or its address). */
export function entryOf(entries: readonly XrefEntry[], operand: string, pou: string | null): XrefEntry | null {
  const root = rootOf(operand);
  if (!root) return null;
  return (
    entries.find((e) => e.pou && same(e.pou, pou) && same(e.name, root)) ??
    entries.find((e) => !e.pou && (same(e.name, root) || same(e.address, root))) ??
    null
  );
}

/** The columns of the cross-reference list, in the panel and in print. */
export const XREF_COLUMNS = ["Variable", "Scope", "Type", "Address", "Access", "Where"] as const;

/** A stable key of an entry (a POU's variable or a global). */
export const entryKey = (e: Pick<XrefEntry, "pou" | "name">): string => `${e.pou ?? ""}/${e.name}`.toUpperCase();

/** Entries whose name, address, type, POU or comment contains `filter` (case-insensitive). */
export function filterEntries(entries: readonly XrefEntry[], filter: string): XrefEntry[] {
  const wanted = filter.trim().toUpperCase();
  if (!wanted) return [...entries];
  return entries.filter((e) =>
    [e.name, e.address, e.type, e.pou ?? "global", e.comment].some((t) => (t ?? "").toUpperCase().includes(wanted)),
  );
}

/** Where an access is: "Main, network 3 (StartCounter)", "Blinker, line 8", "Main, declarations line 2". */
export function placeOf(a: XrefAccess): string {
  const where = a.pou ?? a.gvl ?? "globals";
  if (a.kind === "declared") return `${where}, declarations line ${a.line ?? "?"}`;
  if (a.network_number != null) return `${where}, network ${a.network_number}${a.operand ? ` (${a.operand})` : ""}`;
  if (a.line != null) return `${where}, line ${a.line}`;
  return where;
}

/**
 * The place of an access as the shell's reveal takes it (the shape of a diagnostic: POU, network, element,
 * line and the part as its file), null for the global declarations, which no POU editor shows.
 */
export function placeToReveal(a: XrefAccess): Diagnostic | null {
  if (!a.pou) return null;
  const part = a.kind === "declared" ? "declarations" : a.line != null ? "body" : null;
  return {
    code: "XREF",
    message: `${a.kind} ${a.path}`,
    severity: "info",
    pou: a.pou,
    network: a.network ?? null,
    element: a.element ?? null,
    line: a.line ?? null,
    file: part ? `${a.pou}/${part}` : null,
  };
}
