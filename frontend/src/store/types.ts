// The user types of a project's TYPE text, as the Types editor lists them, and the templates it adds
// (STRUCT, enumeration, array, subrange, alias: IEC 61131-3 2.3.3), and the members of a STRUCT as table rows.
import { parseDeclarations, printDeclarations, type DeclRow } from "../iec/declarations";

export type TypeKind = "struct" | "enum" | "array" | "subrange" | "alias";

export interface TypeRow {
  name: string;
  kind: TypeKind;
  /** 1-based line of the name in the text. */
  line: number;
}

export const TYPE_KINDS: { kind: TypeKind; label: string; template(name: string): string }[] = [
  { kind: "struct", label: "STRUCT", template: (n) => `${n} : STRUCT\n        Member : BOOL;\n    END_STRUCT;` },
  { kind: "enum", label: "enumeration", template: (n) => `${n} : (Idle, Running, Fault) := Idle;` },
  { kind: "array", label: "array", template: (n) => `${n} : ARRAY[1..10] OF INT;` },
  { kind: "subrange", label: "subrange", template: (n) => `${n} : INT (0..100);` },
  { kind: "alias", label: "alias", template: (n) => `${n} : INT;` },
];

const blankComments = (text: string) => text.replace(/\(\*[\s\S]*?\*\)|\/\/[^\n]*/g, (c) => c.replace(/[^\n]/g, " "));

/** The types declared at the top level of the TYPE blocks, with their kind and line. */
export function typeRows(text: string): TypeRow[] {
  const body = blankComments(text);
  const rows: TypeRow[] = [];
  const block = /\bTYPE\b([\s\S]*?)\bEND_TYPE\b/gi;
  for (let b = block.exec(body); b; b = block.exec(body)) {
    const start = b.index + 4;
    // STRUCT members are no types: blank them, keeping offsets.
    const top = b[1]!.replace(/\bSTRUCT\b[\s\S]*?\bEND_STRUCT\b/gi, (s) => "STRUCT" + " ".repeat(s.length - 6));
    const decl = /(?:^|[;\s])([A-Za-z_][A-Za-z0-9_]*)\s*:\s*(STRUCT\b|\(|ARRAY\b|[A-Za-z_][A-Za-z0-9_]*\s*\(|)/gi;
    for (let m = decl.exec(top); m; m = decl.exec(top)) {
      const at = start + m.index + m[0].indexOf(m[1]!);
      const head = m[2]!.toUpperCase();
      const kind: TypeKind =
        head === "STRUCT" ? "struct" : head === "(" ? "enum" : head === "ARRAY" ? "array" : head ? "subrange" : "alias";
      rows.push({ name: m[1]!, kind, line: text.slice(0, at).split("\n").length });
    }
  }
  return rows;
}

/** `text` with a new type `name` of `kind` in a TYPE block of its own at the end. */
export function withNewType(text: string, name: string, kind: TypeKind): string {
  const template = TYPE_KINDS.find((k) => k.kind === kind)!.template(name);
  const block = `TYPE\n    ${template}\nEND_TYPE`;
  return text.trim() ? `${text.trimEnd()}\n\n${block}` : block;
}

/** Where the members of STRUCT type `name` are in `text` (after STRUCT, up to END_STRUCT), or null. */
function structSpan(text: string, name: string): { start: number; end: number } | null {
  const body = blankComments(text);
  const head = new RegExp(`(?:^|[;\\s])${name}\\s*:\\s*STRUCT\\b`, "i").exec(body);
  if (!head) return null;
  const start = head.index + head[0].length;
  const end = body.slice(start).search(/\bEND_STRUCT\b/i);
  return end < 0 ? null : { start, end: start + end };
}

/** The members of STRUCT type `name` as declaration rows, or null when it is no STRUCT the table can hold. */
export function structMembers(text: string, name: string): DeclRow[] | null {
  const span = structSpan(text, name);
  if (!span) return null;
  // Members are declared as variables are (IEC 61131-3 2.3.3.1): read them as one VAR block.
  const parsed = parseDeclarations(`VAR\n${text.slice(span.start, span.end)}\nEND_VAR`);
  return parsed.ok ? parsed.rows.map((r) => ({ ...r, line: undefined })) : null;
}

/** `text` with the members of STRUCT type `name` replaced by `members`, aligned in columns. */
export function withStructMembers(text: string, name: string, members: readonly DeclRow[]): string {
  const span = structSpan(text, name);
  if (!span) return text;
  const printed = printDeclarations(members.map((m) => ({ ...m, varClass: "VAR", address: "" })));
  const lines = members.length ? printed.split("\n").slice(1, -1) : [];
  return `${text.slice(0, span.start)}\n${lines.map((l) => `    ${l}\n`).join("")}    ${text.slice(span.end)}`;
}
