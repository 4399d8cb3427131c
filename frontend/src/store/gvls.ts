// Named global variable lists (CODESYS's GVLs, the project's `gvls`): each opens in a tab keyed `gvl:<name>` (a
// POU name never holds a ':'), edited with the global variables' editor; the pure operations of the tree's
// add, rename and delete live here. A diagnostic of one has the file `gvls/<name>`.
import type { Diagnostic, GlobalVariableList, Project } from "../generated/api";
import { parseDeclarations } from "../iec/declarations";
import { identifierProblem } from "../iec/identifier";

const PREFIX = "gvl:";
/** The text a new list starts with: one empty VAR_GLOBAL block, as CODESYS's "Add global variable list" gives. */
export const NEW_GVL_TEXT = "VAR_GLOBAL\nEND_VAR";

export const gvlTab = (name: string): string => `${PREFIX}${name}`;
export const isGvlTab = (tab: string): boolean => tab.startsWith(PREFIX);
export const gvlNameOf = (tab: string): string => tab.slice(PREFIX.length);

/** The list called `name` (IEC names ignore case). */
export const gvlOf = (project: Project | null | undefined, name: string): GlobalVariableList | undefined =>
  project?.gvls?.find((g) => g.name.toUpperCase() === name.toUpperCase());

/** The list a diagnostic is in, or null. */
export const gvlOfDiagnostic = (d: Diagnostic): string | null =>
  d.file?.startsWith("gvls/") ? d.file.slice("gvls/".length) : null;

/** Why a new list cannot be called `name` (no identifier, a list's or a POU's name), or null. */
export function newGvlProblem(project: Project, name: string): string | null {
  const wanted = name.trim();
  const notIdentifier = identifierProblem(wanted);
  if (notIdentifier) return notIdentifier;
  const list = gvlOf(project, wanted);
  if (list) return `There is already a global variable list called ${list.name}.`;
  const pou = project.pous?.find((p) => p.name.toUpperCase() === wanted.toUpperCase());
  return pou ? `There is already a POU called ${pou.name}.` : null;
}

/** The project with a new, empty list `name` after the others. */
export const withNewGvl = (project: Project, name: string): Project => ({
  ...project,
  gvls: [...(project.gvls ?? []), { name, qualified_only: false, text: NEW_GVL_TEXT }],
});

/** The project with list `name` changed. */
export const withGvlChange = (project: Project, name: string, change: Partial<GlobalVariableList>): Project => ({
  ...project,
  gvls: (project.gvls ?? []).map((g) => (g.name === name ? { ...g, ...change } : g)),
});

/** The project without list `name`. */
export const withoutGvl = (project: Project, name: string): Project => ({
  ...project,
  gvls: (project.gvls ?? []).filter((g) => g.name !== name),
});

/** The variable names (upper case) that several lists declare: each is `LIST.x` then, online too (docs/st.md). A
 * list whose text the declarations table cannot read counts with no names. */
export function sharedListVariables(gvls: readonly GlobalVariableList[]): string[] {
  const seen = new Map<string, number>();
  for (const list of gvls) {
    const parsed = parseDeclarations(list.text ?? "");
    const names = new Set(parsed.ok ? parsed.rows.map((row) => row.name.toUpperCase()) : []);
    for (const name of names) seen.set(name, (seen.get(name) ?? 0) + 1);
  }
  return [...seen].filter(([, count]) => count > 1).map(([name]) => name);
}
