// The halted scan: where it stands (revealed in its editor when it halts), its call stack, and what to do next:
// Continue, Step over, Step into, Step out, Step network, Step cycle, Stop (the keys of the keymap,
// CODESYS's, handled by app/useAppKeys.ts). Breakpoints are set in the editors and listed in the
// Breakpoints panel.
import type { At } from "../online/protocol";
import { onlineStore, useOnline } from "../online/store";
import { keysOf } from "../keys/keymap";
import { describeHalt } from "./breakpoints";
import { CallStack } from "../online/CallStack";
import { useRevealHalt } from "../online/useRevealHalt";
import type { Place } from "./reveal";
import { useDebug } from "./store";

export interface DebugBarProps {
  /** Network ids of a POU (or of its SFC action or transition `part`, "actions/Fill") in order (for "network 2"),
   * empty when it has no diagram. */
  networksOf(pou: string, part?: string | null): string[];
  /** An element of a POU in words when its editor knows it ("step Rinse"), else null. */
  elementText?(pou: string, id: string): string | null;
  /** Shows a location in its editor (opens the POU, selects the network or element, or the line). */
  reveal(target: Place): void;
}

export function DebugBar({ networksOf, elementText, reveal }: DebugBarProps) {
  const state = useOnline((s) => s.monitor.state);
  const at = useOnline((s) => s.monitor.at);
  const debug = useDebug((s) => s);
  const stack = useOnline((s) => s.monitor.stack);
  const halted = state === "halted" && at ? at : null;
  const describe = (where: At) =>
    describeHalt(
      where,
      networksOf(where.pou, where.body),
      where.element && !where.body ? elementText?.(where.pou, where.element) : null,
    );

  useRevealHalt(halted, reveal); // a new halt shows its location in the editor

  if (!halted) return null;
  return (
    <div className="debug-bar debug-halted" role="region" aria-label="Debugging">
      <span role="status">Halted at {describe(halted)}</span>
      <button type="button" onClick={debug.resume} title={`Continue (${keysOf("app", "run")})`}>
        Continue
      </button>
      <button type="button" onClick={() => debug.step("over")} title={`Step over (${keysOf("app", "step-over")})`}>
        Step over
      </button>
      <button type="button" onClick={() => debug.step("statement")} title={`Step into (${keysOf("app", "step-into")})`}>
        Step into
      </button>
      <button type="button" onClick={() => debug.step("out")} title={`Step out (${keysOf("app", "step-out")})`}>
        Step out
      </button>
      <button
        type="button"
        onClick={() => debug.step("transition")}
        title={`Step to the next SFC transition that fires (${keysOf("app", "step-transition")})`}
      >
        Step to transition
      </button>
      <button type="button" onClick={() => debug.step("network")} title="Step to the next network">
        Step network
      </button>
      <button type="button" onClick={() => debug.step("cycle")} title="Run to the end of this scan">
        Step cycle
      </button>
      <button
        type="button"
        onClick={onlineStore.getState().stop}
        title={`Stop the simulation (${keysOf("app", "stop")})`}
      >
        Stop
      </button>
      <CallStack stack={stack} describe={describe} reveal={reveal} />
    </div>
  );
}
