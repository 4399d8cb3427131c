// The halted scan: where it stands (revealed in its editor when it halts) and what to do next,
// Continue / Step network / Step statement / Step cycle / Stop, also from F5, F10, F11 and
// Shift+F5. Breakpoints are set in the editors and listed in the Breakpoints panel.
import { useEffect } from "react";
import { onlineStore, useOnline } from "../online/store";
import { describeHalt } from "./breakpoints";
import type { Place } from "./reveal";
import { debugStore, useDebug } from "./store";

/** Keys of debugging, for the shortcut help (F5 runs when not halted, see SIMULATION_KEYS). */
export const DEBUG_KEYS: [string, string][] = [
  ["F9", "Toggle a breakpoint on the selected element or network"],
  ["Click a network number", "Toggle a breakpoint on the network"],
  ["Alt+click", "Toggle a breakpoint on an element"],
  ["F5 (halted)", "Continue"],
  ["F10", "Step to the next network"],
  ["F11", "Step to the next statement"],
];

/** F5 continues a halted scan; F10/F11 step (from a stopped simulation: into the next scan). */
export function debugKey(
  e: Pick<KeyboardEvent, "key" | "altKey" | "ctrlKey" | "metaKey" | "shiftKey">,
  halted: boolean,
): (() => void) | null {
  if (e.altKey || e.ctrlKey || e.metaKey || e.shiftKey) return null;
  const debug = debugStore.getState();
  if (e.key === "F5" && halted) return debug.resume;
  if (e.key === "F10") return () => debug.step("network");
  if (e.key === "F11") return () => debug.step("statement");
  return null;
}

export interface DebugBarProps {
  /** Network ids of a POU in order (for "network 2"), empty when it has no diagram. */
  networksOf(pou: string): string[];
  /** Shows a location in its editor (opens the POU, selects the network or element, or the line). */
  reveal(target: Place): void;
}

export function DebugBar({ networksOf, reveal }: DebugBarProps) {
  const state = useOnline((s) => s.monitor.state);
  const at = useOnline((s) => s.monitor.at);
  const debug = useDebug((s) => s);
  const halted = state === "halted" && at ? at : null;

  // A new halt shows its location in the editor.
  useEffect(() => {
    if (halted) reveal({ pou: halted.pou, network: halted.network, element: halted.element, line: halted.line });
  }, [halted, reveal]);

  useEffect(() => {
    const onKey = (e: KeyboardEvent) => {
      const online = onlineStore.getState();
      if (online.phase !== "online") return;
      const run = debugKey(e, online.monitor.state === "halted");
      if (!run) return;
      e.preventDefault();
      run();
    };
    window.addEventListener("keydown", onKey);
    return () => window.removeEventListener("keydown", onKey);
  }, []);

  if (!halted) return null;
  return (
    <div className="debug-bar debug-halted" role="region" aria-label="Debugging">
      <span role="status">Halted at {describeHalt(halted, networksOf(halted.pou))}</span>
      <button type="button" onClick={debug.resume} title="Continue (F5)">
        Continue
      </button>
      <button type="button" onClick={() => debug.step("network")} title="Step to the next network (F10)">
        Step network
      </button>
      <button type="button" onClick={() => debug.step("statement")} title="Step to the next statement (F11)">
        Step statement
      </button>
      <button type="button" onClick={() => debug.step("cycle")} title="Run to the end of this scan">
        Step cycle
      </button>
      <button type="button" onClick={onlineStore.getState().stop} title="Stop the simulation (Shift+F5)">
        Stop
      </button>
    </div>
  );
}
