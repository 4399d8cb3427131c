// The methods and properties of a function block as the browser edits them (issue 25): pure operations on the
// POU, each giving the new POU or the reason it is refused (names are IEC identifiers, unique among the FB's
// methods and properties, case-insensitively, as the checker requires).
import type { Accessor, Method, Pou, Property } from "../generated/api";
import type { Access } from "../tree/modifiers";

export type MemberKind = "method" | "property";

/** Who may call a method or use a property, per access specifier (IEC 61131-3 ed. 3, CODESYS); the Methods tab's
 * choices. A Record, so a specifier added to the model (backend model/project.py MethodAccess) fails to compile here. */
export const ACCESS_MEANING: Record<Access, string> = {
  PUBLIC: "any code may use it",
  PRIVATE: "only its own function block or program",
  PROTECTED: "its function block and those derived from it (a program: only itself)",
  INTERNAL: "code of this project (its namespace)",
};

/** A method or function block made FINAL or ABSTRACT: the two exclude each other (what is FINAL cannot be left to
 * a derived FB to implement), so setting one clears the other. */
export function withModifier<T extends { final?: boolean; abstract?: boolean }>(
  item: T,
  which: "final" | "abstract",
  on: boolean,
): T {
  const other = which === "final" ? "abstract" : "final";
  return { ...item, [which]: on, ...(on ? { [other]: false } : {}) };
}
export type Edited = { ok: true; pou: Pou } | { ok: false; error: string };

const IDENTIFIER = /^[A-Za-z_][A-Za-z0-9_]*$/;

/** The member called `name` (case-insensitive), with its kind. */
export function memberOf(
  pou: Pou,
  name: string,
): { kind: "method"; member: Method } | { kind: "property"; member: Property } | null {
  const upper = name.toUpperCase();
  const method = pou.methods?.find((m) => m.name.toUpperCase() === upper);
  if (method) return { kind: "method", member: method };
  const property = pou.properties?.find((p) => p.name.toUpperCase() === upper);
  return property ? { kind: "property", member: property } : null;
}

function refused(pou: Pou, name: string, except?: string): string | null {
  if (!IDENTIFIER.test(name))
    return `${name || "An empty name"} is not an IEC identifier (letters, digits and _, not starting with a digit).`;
  const other = memberOf(pou, name);
  if (other && other.member.name.toUpperCase() !== except?.toUpperCase())
    return `${pou.name} already has a ${other.kind} called ${other.member.name}.`;
  return null;
}

/** A new method (no result, empty declarations and body) or property (INT, with an empty GET and SET). */
export function addMember(pou: Pou, kind: MemberKind, text: string): Edited {
  const name = text.trim();
  const error =
    pou.kind !== "function_block" && pou.kind !== "program"
      ? "Only a function block or a program has methods and properties."
      : refused(pou, name);
  if (error) return { ok: false, error };
  if (kind === "method") {
    const method: Method = {
      name,
      access: "PUBLIC",
      final: false,
      abstract: false,
      return_type: null,
      declarations: "",
      body: "",
    };
    return { ok: true, pou: { ...pou, methods: [...(pou.methods ?? []), method] } };
  }
  const empty: Accessor = { declarations: "", body: "" };
  const property: Property = { name, type: "INT", access: "PUBLIC", get: empty, set: empty };
  return { ok: true, pou: { ...pou, properties: [...(pou.properties ?? []), property] } };
}

/** The member renamed, its declaration only, or why not (a taken name): the Methods tab asks this first, then the
 * server renames the calls too (tree/refactor.ts renameMemberEverywhere). */
export function renameMember(pou: Pou, name: string, text: string): Edited {
  const next = text.trim();
  const error = refused(pou, next, name);
  if (error) return { ok: false, error };
  return changeMember(pou, name, (m) => ({ ...m, name: next }));
}

/** The POU without the member `name`. */
export function deleteMember(pou: Pou, name: string): Pou {
  const upper = name.toUpperCase();
  return {
    ...pou,
    methods: (pou.methods ?? []).filter((m) => m.name.toUpperCase() !== upper),
    properties: (pou.properties ?? []).filter((p) => p.name.toUpperCase() !== upper),
  };
}

/** The member `name` changed by `update` (a method's or property's fields). */
export function changeMember<T extends Method | Property>(pou: Pou, name: string, update: (member: T) => T): Edited {
  const upper = name.toUpperCase();
  const found = memberOf(pou, name);
  if (!found) return { ok: false, error: `${pou.name} has no method or property called ${name}.` };
  const apply = <M extends Method | Property>(list: M[] | undefined) =>
    (list ?? []).map((m) => (m.name.toUpperCase() === upper ? (update(m as unknown as T) as unknown as M) : m));
  return found.kind === "method"
    ? { ok: true, pou: { ...pou, methods: apply(pou.methods) } }
    : { ok: true, pou: { ...pou, properties: apply(pou.properties) } };
}

/** The file the checker names a member's text by (backend st/methods.py ``method_file``): `FB.M/body`,
 * `FB.P.GET/declarations`. */
export function memberFile(
  fb: string,
  member: string,
  part: "declarations" | "body",
  accessor?: "get" | "set",
): string {
  return `${fb}.${member}${accessor ? `.${accessor.toUpperCase()}` : ""}/${part}`;
}
