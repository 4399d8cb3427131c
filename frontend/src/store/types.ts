// The user types of a project's TYPE text, as the Types editor lists them, and the templates it adds
// (STRUCT, enumeration, array, subrange, alias: IEC 61131-3 2.3.3), and the members of a STRUCT as table rows.
import type { Project } from "../generated/api";
import { parseDeclarations, printDeclarations, type DeclRow } from "../iec/declarations";
import { copyName, identifierProblem } from "../iec/identifier";

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

/** A type's declaration: its row, and where it is in the text (from its name to its closing ';'). */
interface TypeDeclaration extends TypeRow {
  start: number;
  end: number;
  /** Where its TYPE ... END_TYPE block is. */
  block: { start: number; end: number };
}

function typeDeclarations(text: string): TypeDeclaration[] {
  const body = blankComments(text);
  const found: TypeDeclaration[] = [];
  const block = /\bTYPE\b([\s\S]*?)\bEND_TYPE\b/gi;
  for (let b = block.exec(body); b; b = block.exec(body)) {
    const start = b.index + 4;
    // STRUCT members are no types: blank them, keeping offsets.
    const top = b[1]!.replace(/\bSTRUCT\b[\s\S]*?\bEND_STRUCT\b/gi, (s) => "STRUCT" + " ".repeat(s.length - 6));
    // `name :` (not an enumeration value's or an initial value's `:=`)
    const decl = /(?:^|[;\s])([A-Za-z_][A-Za-z0-9_]*)\s*:(?!=)\s*(STRUCT\b|\(|ARRAY\b|[A-Za-z_][A-Za-z0-9_]*\s*\(|)/gi;
    for (let m = decl.exec(top); m; m = decl.exec(top)) {
      const at = start + m.index + m[0].indexOf(m[1]!);
      const head = m[2]!.toUpperCase();
      // `INT (0..100)` is a subrange, `INT (Slow := 1, Fast)` an enumeration with its base type first (IEC ed. 3)
      const values = top.slice(m.index + m[0].length, top.indexOf(")", m.index + m[0].length));
      const kind: TypeKind =
        head === "STRUCT"
          ? "struct"
          : head === "ARRAY"
            ? "array"
            : head === "("
              ? "enum"
              : head
                ? values.includes("..")
                  ? "subrange"
                  : "enum"
                : "alias";
      const semicolon = top.indexOf(";", m.index + m[0].length);
      const end = semicolon < 0 ? start + top.length : start + semicolon + 1;
      const line = text.slice(0, at).split("\n").length;
      found.push({ name: m[1]!, kind, line, start: at, end, block: { start: b.index, end: b.index + b[0].length } });
    }
  }
  return found;
}

/** The types declared at the top level of the TYPE blocks, with their kind and line. */
export function typeRows(text: string): TypeRow[] {
  return typeDeclarations(text).map(({ name, kind, line }) => ({ name, kind, line }));
}

const declarationOf = (text: string, name: string) =>
  typeDeclarations(text).find((d) => d.name.toUpperCase() === name.toUpperCase());

/** The first and last line of type `name`'s own declaration (its uses there are no references), or null. */
export function typeLines(text: string, name: string): { first: number; last: number } | null {
  const found = declarationOf(text, name);
  return found ? { first: found.line, last: text.slice(0, found.end).split("\n").length } : null;
}

/** CODESYS's `{attribute 'pack_mode' := 'N'}` (with the blanks after it) ending right at `end`, or null. */
function packModeBefore(text: string, end: number): { start: number; end: number; pragma: string } | null {
  const found = /\{\s*attribute\s+'pack_mode'\s*:=\s*'[^']*'\s*\}\s*$/i.exec(text.slice(0, end));
  return found ? { start: found.index, end, pragma: found[0].trim() } : null;
}

/** The pack_mode pragma a declaration has (the backend's st/pragmas.py): right above its name, or above its
 * block's TYPE when it is the block's first declaration. It goes and comes with the declaration, so no other
 * type takes it over. */
function packModeOf(text: string, found: TypeDeclaration) {
  const first = !blankComments(text.slice(found.block.start + 4, found.start)).trim();
  return packModeBefore(text, found.start) ?? (first ? packModeBefore(text, found.block.start) : null);
}

/** `text` without type `name`'s declaration (and its pack_mode pragma); a TYPE block left empty goes too. */
export function withoutType(text: string, name: string): string {
  const found = declarationOf(text, name);
  if (!found) return text;
  const packMode = packModeOf(text, found);
  if (packMode) return withoutType(text.slice(0, packMode.start) + text.slice(packMode.end), name);
  const lineStart = text.lastIndexOf("\n", found.start - 1) + 1;
  const from = text.slice(lineStart, found.start).trim() ? found.start : lineStart;
  const to = /^[ \t]*\n/.exec(text.slice(found.end))?.[0].length ?? 0;
  const rest = text.slice(0, from) + text.slice(found.end + to);
  const block = { start: found.block.start, end: found.block.end - (found.end + to - from) };
  const inside = blankComments(rest.slice(block.start + 4, block.end - 8));
  if (inside.trim()) return rest;
  // the block is empty now: drop it with the blank lines around it
  const joined = [rest.slice(0, block.start).trimEnd(), rest.slice(block.end).trim()].filter(Boolean).join("\n\n");
  return joined ? `${joined}\n` : "";
}

/** `text` with a copy of type `name` called `copy` declared right after it, or null when there is no `name`. */
export function withTypeCopy(text: string, name: string, copy: string): string | null {
  const found = declarationOf(text, name);
  if (!found) return null;
  const lineStart = text.lastIndexOf("\n", found.start - 1) + 1;
  const indent = /^[ \t]*/.exec(text.slice(lineStart))![0];
  const packMode = packModeOf(text, found);
  const pragma = packMode ? `${packMode.pragma}\n${indent}` : "";
  const declaration = copy + text.slice(found.start + found.name.length, found.end);
  return `${text.slice(0, found.end)}\n${indent}${pragma}${declaration}${text.slice(found.end)}`;
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

/** The project without type `name` (what still uses it no longer compiles: the delete dialog lists it). */
export const withoutTypeIn = (project: Project, name: string): Project => ({
  ...project,
  types: withoutType(project.types ?? "", name),
});

/** Types and POUs share one namespace (a variable's type may name either): the names a new type may not take. */
const takenNames = (project: Project) => [
  ...typeRows(project.types ?? "").map((r) => r.name),
  ...(project.pous ?? []).map((p) => p.name),
];

/** The name a copy of type `name` gets unless the user types another. */
export const typeCopyName = (project: Project, name: string): string => copyName(takenNames(project), name);

/** The project with a copy of type `name` called `copy` declared right after it, or why not. */
export function withTypeCopyIn(project: Project, name: string, copy: string): Project | string {
  const wanted = copy.trim();
  const taken = takenNames(project).find((t) => t.toUpperCase() === wanted.toUpperCase());
  const problem = identifierProblem(wanted) ?? (taken ? `There is already a type or POU called ${taken}.` : null);
  if (problem) return problem;
  const types = withTypeCopy(project.types ?? "", name, wanted);
  return types === null ? `There is no type ${name}.` : { ...project, types };
}
