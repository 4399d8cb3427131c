// The project's own parts besides POUs and test files: the global variables, the types, the tasks and the
// vendor libraries it uses.
// Each opens in a tab of its name (no POU is called so: POU names have no space), and a diagnostic
// of one (file "globals" or "types", or a JSON path into the tasks) reveals that tab.
import type { Diagnostic } from "../generated/api";

export const PROJECT_PARTS = ["Global variables", "Types", "Tasks", "Library manager"] as const;
export type ProjectPart = (typeof PROJECT_PARTS)[number];

export const isProjectPart = (tab: string): tab is ProjectPart => (PROJECT_PARTS as readonly string[]).includes(tab);

/** The part a diagnostic is in, or null for a POU's or test file's. */
export function partOf(d: Diagnostic): ProjectPart | null {
  if (d.file === "globals") return "Global variables";
  if (d.file === "types") return "Types";
  if (d.json_path?.startsWith("$.tasks")) return "Tasks";
  if (d.json_path?.startsWith("$.libraries")) return "Library manager";
  return null;
}

/** The index of the task a diagnostic's JSON path points into ($.tasks[2].interval -> 2), or null. */
export function taskIndexOf(d: Diagnostic): number | null {
  const m = /^\$\.tasks\[(\d+)\]/.exec(d.json_path ?? "");
  return m ? Number(m[1]) : null;
}
