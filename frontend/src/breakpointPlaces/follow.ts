// Breakpoints that follow what they are on (issue 22): a POU's breakpoints take its new name; an ST line's
// breakpoint moves with its line as text is inserted or deleted above it; one whose POU, network, element or
// line is gone is dropped with a message, never left pointing at something else. Pure: the debug store
// applies the results and the workspace says when the project changed.
import type { Pou, Project } from "../generated/api";
import { describeBreakpoint, type Breakpoint } from "../debug/breakpoints";
import { breakpointBody, describePlace } from "./place";

/** `bp` of POU `oldName` (case-insensitive) as a breakpoint of `newName`; others unchanged. */
export const renamedPou = (bp: Breakpoint, oldName: string, newName: string): Breakpoint =>
  bp.pou.toUpperCase() === oldName.toUpperCase() ? { ...bp, pou: newName } : bp;

/** A line breakpoint of `pou`'s own text moved by `move` (old line -> new line, null: the line was deleted). */
export function movedLine(bp: Breakpoint, pou: string, move: (line: number) => number | null): Breakpoint | null {
  if (!("line" in bp) || bp.body || bp.pou.toUpperCase() !== pou.toUpperCase()) return bp;
  const line = move(bp.line);
  return line === null ? null : { ...bp, line };
}

/** Every `id` in a diagram body (networks, elements, nodes, steps: they all carry one). */
function idsOf(value: unknown, into = new Set<string>()): Set<string> {
  if (Array.isArray(value)) value.forEach((v) => idsOf(v, into));
  else if (value && typeof value === "object") {
    for (const [key, v] of Object.entries(value)) {
      if (key === "id" && typeof v === "string") into.add(v);
      else idsOf(v, into);
    }
  }
  return into;
}

/** Why `bp` points at nothing in `project` (its POU, network, element or line is gone), or null while it is there.
 * A breakpoint in an SFC action or transition (`body`) is left to that editor. */
export function goneBecause(bp: Breakpoint, project: Project, before?: Project): string | null {
  const find = (p: Project | undefined): Pou | undefined =>
    (p?.pous ?? []).find((x) => x.name.toUpperCase() === bp.pou.toUpperCase());
  const pou = find(project);
  const old = find(before);
  // Named as the user last saw it: the network's number and label, the element's operand, the line's text.
  const part = old ? breakpointBody(bp, old) : null; // an SFC action's or transition's body, else the POU's
  const where =
    old && part ? `${old.name}, ${describePlace(bp, old, part.body, part.language)}` : describeBreakpoint(bp);
  if (!pou) return `The breakpoint at ${where} was removed: there is no POU ${bp.pou} any more.`;
  if (bp.body) return null;
  if ("line" in bp) {
    const lines = typeof pou.body === "string" ? pou.body.split("\n").length : 0;
    return bp.line <= lines
      ? null
      : `The breakpoint at ${where} was removed: ${pou.name} has no line ${bp.line} any more.`;
  }
  const id = "network" in bp ? bp.network : bp.element;
  return idsOf(pou.body).has(id)
    ? null
    : `The breakpoint at ${where} was removed: its ${"network" in bp ? "network" : "element"} was deleted.`;
}
