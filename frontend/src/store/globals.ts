// The global variables as the Global variables table has them: where one is declared, and the project
// without one (the delete dialog's step; what still uses it is listed there first, tree/refactor.ts).
import type { Project } from "../generated/api";
import { parseDeclarations, printDeclarations } from "../iec/declarations";

const same = (a: string, b: string) => a.toUpperCase() === b.toUpperCase();

/** The line global `name` is declared on in the VAR_GLOBAL text, or null (no such row, or text the table
 * cannot read). */
export function globalLine(text: string, name: string): number | null {
  const parsed = parseDeclarations(text);
  return (parsed.ok && parsed.rows.find((r) => same(r.name, name))?.line) || null;
}

/** The project without global `name`, the rest printed as the table prints it; unchanged when the text is
 * none the table can read (the table is read-only then). */
export function withoutGlobalIn(project: Project, name: string): Project {
  const parsed = parseDeclarations(project.globals ?? "");
  if (!parsed.ok) return project;
  return { ...project, globals: printDeclarations(parsed.rows.filter((r) => !same(r.name, name))) };
}
