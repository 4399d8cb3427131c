// Debugging in a text editor's gutter (an ST or IL body, a method's body): the breakpoint lines of one POU of the
// engine (`Main`, or a method's `Counter.Scaled`), the line it is halted at, toggling, and breakpoints that follow
// an edit that moves their lines.
import { useMemo } from "react";
import { haltedAt } from "../online/monitor";
import { useOnline } from "../online/store";
import { describeBreakpoint } from "../debug/breakpoints";
import { movedLine } from "./follow";
import { debugStore, useDebug } from "../debug/store";

export function useTextDebug(pou: string) {
  const upper = pou.toUpperCase();
  const all = useDebug((s) => s.breakpoints);
  const lines = useMemo(
    () => all.flatMap((b) => ("line" in b && b.pou.toUpperCase() === upper ? [b.line] : [])),
    [all, upper],
  );
  const at = useOnline((s) => haltedAt(s.monitor)); // also a halt in a past scan the history shows
  return {
    breakpoints: lines,
    halted: at && at.pou.toUpperCase() === upper && at.line != null ? at.line : null,
    onToggle: (line: number) => debugStore.getState().toggle({ pou, line }),
    onLinesMoved: (move: (line: number) => number | null) =>
      debugStore.getState().follow(
        (bp) => movedLine(bp, pou, move),
        (bp) => `The breakpoint at ${describeBreakpoint(bp)} was removed: the text of its line was deleted.`,
      ),
  };
}
