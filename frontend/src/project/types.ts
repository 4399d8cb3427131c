// The user types of a project's TYPE text, as the Types editor lists them, and the templates it adds
// (STRUCT, enumeration, array, subrange, alias: IEC 61131-3 2.3.3).

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
