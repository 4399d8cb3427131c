// Project operations on the working copy: rename everywhere, what refers to a name, duplicate (the
// server's st/refactor.py does the ST-aware work, statelessly), and the small pure facts the tree's
// menus need (is a POU empty, how a reference is shown, a watch path after a rename).
import { http, unwrap } from "../api/client";
import type { Reference } from "../generated/api";
import type { Pou, Project } from "../generated/api";
import { panelChange } from "../hmi/history";
import { globalLine, globalsText } from "../store/globals";
import { gvlTab } from "../store/gvls";
import { typeLines } from "../store/types";

/** A use of a name in this browser's session, not in the project: a watch list row, a traced variable or the
 * trace's trigger. */
export interface SessionUse {
  part: "watch" | "trace" | "trigger";
  text: string;
}

/** A place that uses a name: in the project (the server finds it) or in the session. */
export type Use = Reference | SessionUse;

/** The working copy with `oldName` renamed to `newName` in every POU, diagram, task and test file. */
export const renameEverywhere = (project: Project, oldName: string, newName: string) =>
  unwrap(http.POST("/api/refactor/rename", { body: { project, old_name: oldName, new_name: newName } }));

/** The working copy with method or property `oldName` of function block `pou` called `newName`, with its overrides
 * and every call (issue 25 item 5). */
export const renameMemberEverywhere = (project: Project, pou: string, oldName: string, newName: string) =>
  unwrap(http.POST("/api/refactor/rename-member", { body: { project, pou, old_name: oldName, new_name: newName } }));

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

/** Every place that uses global variable `name`, its own declaration left out (store/globals.ts globalLine). */
export async function globalReferences(
  project: Project,
  name: string,
  list: string | null = null,
): Promise<Reference[]> {
  const own = globalLine(globalsText(project, list), name);
  const declaration = (r: Reference) =>
    r.line === own && (list === null ? r.part === "globals" : r.part === "gvl" && r.file === `gvls/${list}`);
  return (await referencesTo(project, name)).filter((r) => !declaration(r));
}

/** The watch list rows, traced variables and trace trigger whose path starts with `name` (a global or a program). */
export function sessionUses(
  name: string,
  watch: readonly string[],
  traced: readonly string[],
  trigger = "",
): SessionUse[] {
  const uses = (part: SessionUse["part"], paths: readonly string[]) =>
    paths.filter((p) => renamedPath(p, name, "") !== p).map((text) => ({ part, text }));
  return [...uses("watch", watch), ...uses("trace", traced), ...uses("trigger", trigger ? [trigger] : [])];
}

/** The engine's POUs a rename renames, as [old, new] pairs for the breakpoints on them: a POU itself, or a method
 * `F.M` and its overrides (the changes list each declaration as part "method"). */
export function renamedPous(
  current: string,
  next: string,
  isPou: boolean,
  changes: readonly Reference[],
): [string, string][] {
  if (isPou) return [[current, next]];
  return changes
    .filter((c) => c.part === "method" && (c.text ?? "").startsWith("METHOD "))
    .map((c) => [`${c.pou}.${c.member}`, `${c.pou}.${next}`]);
}

/** The working copy with a copy of POU `name` called `newName`. */
export const duplicated = async (project: Project, name: string, newName: string) =>
  (await unwrap(http.POST("/api/refactor/duplicate", { body: { project, name, new_name: newName } }))).project;

const inSession = (use: Use): use is SessionUse =>
  use.part === "watch" || use.part === "trace" || use.part === "trigger";

/** Where a reference is, in the words of the project tree ("Main, declarations line 2", "task Fast", "Watch list"). */
export function describeReference(use: Use): string {
  if (inSession(use)) return { watch: "Watch list", trace: "Trace", trigger: "Trace trigger" }[use.part];
  const r: Reference = use;
  if (r.part === "panel") return `panel ${r.panel}, widget ${r.element}`;
  if (r.part === "method") return `${r.pou}`; // listed with its text: "METHOD Bump"
  if (r.part === "task") return `task ${r.task}`;
  if (r.part === "test") return `${r.file} line ${r.line}`;
  if (r.part === "globals") return `Global variables line ${r.line}`;
  if (r.part === "gvl") return `${r.file?.slice("gvls/".length)} line ${r.line}`;
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

/** A watch or trace path after `oldName` (a program or global) became `newName`: its first name only, in any
 * case as IEC names are case-insensitive (MAIN.x -> Plant.x, Arr[1] -> Table[1]); other paths stay as typed.
 * The server renames operator panels' paths the same way (st/refactor.py _PATH_HEAD). */
export function renamedPath(path: string, oldName: string, newName: string): string {
  const head = /^[A-Za-z_][A-Za-z0-9_]*(?=$|[.[])/.exec(path)?.[0];
  return head?.toUpperCase() === oldName.toUpperCase() ? newName + path.slice(head.length) : path;
}

/** The project parts (as the unsaved-changes list names them) a rename's changes touch outside the POUs. */
export function changedParts(changes: readonly Reference[]): string[] {
  const parts = new Set<string>();
  for (const c of changes) {
    if (c.part === "globals") parts.add("part:globals");
    else if (c.part === "gvl" && c.file) parts.add(gvlTab(c.file.slice("gvls/".length)));
    else if (c.part === "types") parts.add("part:types");
    else if (c.part === "task") parts.add("part:tasks");
    else if (c.part === "test" && c.file) parts.add(c.file);
    else if (c.part === "panel" && c.panel) parts.add(panelChange(c.panel));
  }
  return [...parts];
}
