// The global variables as the Global variables table has them (those of no list, or of one global variable
// list): where one is declared, and the project without one (the delete dialog's step; what still uses it is
// listed there first, tree/refactor.ts).
import type { Project } from "../generated/api";
import { parseDeclarations, printDeclarations } from "../iec/declarations";
import { gvlOf, withGvlChange } from "./gvls";

const same = (a: string, b: string) => a.toUpperCase() === b.toUpperCase();

/** The line global `name` is declared on in the VAR_GLOBAL text, or null (no such row, or text the table
 * cannot read). */
export function globalLine(text: string, name: string): number | null {
  const parsed = parseDeclarations(text);
  return (parsed.ok && parsed.rows.find((r) => same(r.name, name))?.line) || null;
}

/** The VAR_GLOBAL text of the global variable list `list`, or of the globals of no list (`list` null). */
export const globalsText = (project: Project, list: string | null): string =>
  (list === null ? project.globals : gvlOf(project, list)?.text) ?? "";

/** The project without global `name` (of the global variable list `list`, or of no list), the rest printed as
 * the table prints it; unchanged when the text is none the table can read (the table is read-only then). */
export function withoutGlobalIn(project: Project, name: string, list: string | null = null): Project {
  const parsed = parseDeclarations(globalsText(project, list));
  if (!parsed.ok) return project;
  const text = printDeclarations(parsed.rows.filter((r) => !same(r.name, name)));
  return list === null ? { ...project, globals: text } : withGvlChange(project, gvlOf(project, list)!.name, { text });
}
