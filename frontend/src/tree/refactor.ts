// Project operations on the working copy: rename everywhere, what refers to a name, duplicate (the
// server's st/refactor.py does the ST-aware work, statelessly), and the small pure facts the tree's
// menus need (is a POU empty, how a reference is shown, a watch path after a rename).
import { http, unwrap } from "../api/client";
import type { Reference } from "../generated/api";
import type { Pou, Project } from "../generated/api";
import { typeLines } from "../store/types";

/** The working copy with `oldName` renamed to `newName` in every POU, diagram, task and test file. */
export const renameEverywhere = (project: Project, oldName: string, newName: string) =>
  unwrap(http.POST("/api/refactor/rename", { body: { project, old_name: oldName, new_name: newName } }));

/** Every place in the working copy that uses `name` (what deleting it would break). */
export const referencesTo = async (project: Project, name: string) =>
  (await unwrap(http.POST("/api/refactor/references", { body: { project, name } }))).references;

/** Every place that uses type `name`, its own declaration left out (store/types.ts typeLines). */
export async function typeReferences(project: Project, name: string): Promise<Reference[]> {
  const own = typeLines(project.types ?? "", name);
  const isOwn = (r: Reference) =>
    r.part === "types" && own !== null && r.line != null && r.line >= own.first && r.line <= own.last;
  return (await referencesTo(project, name)).filter((r) => !isOwn(r));
}

/** The working copy with a copy of POU `name` called `newName`. */
export const duplicated = async (project: Project, name: string, newName: string) =>
  (await unwrap(http.POST("/api/refactor/duplicate", { body: { project, name, new_name: newName } }))).project;

/** Where a reference is, in the words of the project tree ("Main, declarations line 2", "task Fast"). */
export function describeReference(r: Reference): string {
  if (r.part === "task") return `task ${r.task}`;
  if (r.part === "test") return `${r.file} line ${r.line}`;
  if (r.part === "globals") return `Global variables line ${r.line}`;
  if (r.part === "types") return `Types line ${r.line}`;
  if (r.part === "step") return `${r.pou}, a step's action ${r.text}`;
  if (r.part === "network") {
    const label = r.network_label ? ` "${r.network_label}"` : "";
    return `${r.pou}, network ${r.network_number}${label}`;
  }
  if (r.part === "extends" || r.part === "implements") return `${r.pou}`; // listed with its text: "F EXTENDS B"
  const owner = r.member ? `${r.pou}.${r.member}` : r.pou;
  if (r.part === "return type") return `${owner}, ${r.member ? "type" : "result type"}`;
  return `${owner}, ${r.part} line ${r.line}`;
}

/** A POU with no variables and no body yet: it may change its kind freely. */
export function isEmptyPou(pou: Pou): boolean {
  const declared = (pou.declarations ?? "")
    .replace(/\(\*[\s\S]*?\*\)|\/\/[^\n]*/g, "")
    .replace(/\b(VAR_INPUT|VAR_OUTPUT|VAR_IN_OUT|VAR_TEMP|VAR|END_VAR)\b/gi, "")
    .trim();
  const body = pou.body;
  // An SFC chart always has its initial step: it is not empty.
  const empty =
    typeof body === "string" ? body.trim() === "" : !body || ("networks" in body && (body.networks ?? []).length === 0);
  return declared === "" && empty;
}

/** A watch path after `oldName` (a program or global) became `newName`: the first part only, as IEC names
 * are case-insensitive (MAIN.x -> Plant.x); other paths stay as typed. */
export function renamedPath(path: string, oldName: string, newName: string): string {
  const [first = "", ...rest] = path.split(".");
  return first.toUpperCase() === oldName.toUpperCase() ? [newName, ...rest].join(".") : path;
}

/** The project parts (as the unsaved-changes list names them) a rename's changes touch outside the POUs. */
export function changedParts(changes: readonly Reference[]): string[] {
  const parts = new Set<string>();
  for (const c of changes) {
    if (c.part === "globals") parts.add("part:globals");
    else if (c.part === "types") parts.add("part:types");
    else if (c.part === "task") parts.add("part:tasks");
    else if (c.part === "test" && c.file) parts.add(c.file);
  }
  return [...parts];
}
