// The simulation controls, always visible over the editor: Check, Compile & simulate, Run, Stop,
// Single cycle, Reset, Go offline; the online/offline state; scan counter, virtual time and the
// last scan time. Compile & simulate saves unsaved changes first (the server compiles the saved
// project). F-keys as in CODESYS-like IDEs, listed in the shortcut help.
import { useEffect } from "react";
import { panelsStore, usePanels } from "../panels/store";
import { workspaceStore } from "../project/store";
import { onlineStore, useOnline } from "./store";
import { formatClock } from "./values";

/** Keys of the simulation commands, for the shortcut help. */
export const SIMULATION_KEYS: [string, string][] = [
  ["F7", "Check the project"],
  ["Alt+F8", "Compile & simulate (go online)"],
  ["Ctrl+F8", "Go offline"],
  ["F5", "Run"],
  ["Shift+F5", "Stop"],
  ["F8", "Single cycle"],
];

/** Saves pending changes, then checks or compiles the saved project. */
async function savedProject(): Promise<string | null> {
  const ws = workspaceStore.getState();
  if (!ws.name) return null;
  if (ws.changed.length) {
    await ws.save();
    if (workspaceStore.getState().changed.length) return null; // the save failed or conflicted; its message is shown
  }
  return ws.name;
}

export async function checkSaved(): Promise<void> {
  const name = await savedProject();
  if (name) await panelsStore.getState().check(name);
}

export async function compileSaved(): Promise<void> {
  const name = await savedProject();
  if (!name) return;
  await onlineStore.getState().compile(name);
  const { compileDiagnostics } = onlineStore.getState();
  if (compileDiagnostics.length) panelsStore.getState().showDiagnostics(compileDiagnostics);
}

export function SimulationBar() {
  const phase = useOnline((s) => s.phase);
  const state = useOnline((s) => s.monitor.state);
  const scan = useOnline((s) => s.monitor.scan);
  const timeMs = useOnline((s) => s.monitor.timeMs);
  const lastScanMs = useOnline((s) => s.lastScanMs);
  const error = useOnline((s) => s.error);
  const checking = usePanels((s) => s.checking);
  const online = phase === "online";
  const running = state === "running";
  const s = onlineStore.getState();

  useEffect(() => {
    const onKey = (e: KeyboardEvent) => {
      const o = onlineStore.getState();
      const ready = o.phase === "online";
      let run: (() => unknown) | null = null;
      if (e.key === "F7" && !e.altKey && !e.ctrlKey && !e.shiftKey) run = checkSaved;
      else if (e.key === "F8" && e.altKey) run = compileSaved;
      else if (e.key === "F8" && e.ctrlKey) run = o.goOffline;
      else if (e.key === "F8" && ready) run = o.singleCycle;
      else if (e.key === "F5" && e.shiftKey && ready) run = o.stop;
      else if (e.key === "F5" && !e.shiftKey && ready && o.monitor.state !== "halted") run = o.run; // halted: F5 continues (debug/DebugBar)
      if (!run) return;
      e.preventDefault();
      void run();
    };
    window.addEventListener("keydown", onKey);
    return () => window.removeEventListener("keydown", onKey);
  }, []);

  const label =
    phase === "online"
      ? `Online · ${state ?? "…"}`
      : phase === "offline"
        ? "Offline"
        : phase === "compiling"
          ? "Compiling…"
          : "Connecting…";
  return (
    <div className={`simulation-bar phase-${phase}${running ? " running" : ""}`} role="toolbar" aria-label="Simulation">
      <button type="button" onClick={() => void checkSaved()} disabled={checking} title="Check (F7)">
        Check
      </button>
      <button
        type="button"
        onClick={() => void compileSaved()}
        disabled={phase === "compiling" || phase === "connecting"}
        title="Compile & simulate (Alt+F8)"
      >
        Compile &amp; simulate
      </button>
      <button type="button" onClick={s.run} disabled={!online || running} title="Run (F5)">
        Run
      </button>
      <button
        type="button"
        onClick={s.stop}
        disabled={!online || !(running || state === "halted")}
        title="Stop (Shift+F5)"
      >
        Stop
      </button>
      <button
        type="button"
        onClick={s.singleCycle}
        disabled={!online}
        title="Single cycle (F8): one scan, then stopped"
      >
        Single cycle
      </button>
      <button type="button" onClick={() => void s.reset()} disabled={!online} title="Warm reset">
        Reset
      </button>
      <button
        type="button"
        onClick={() => void s.goOffline()}
        disabled={phase === "offline"}
        title="Go offline (Ctrl+F8)"
      >
        Go offline
      </button>
      <span className="online-state" role="status" aria-label="Online state">
        <span className="online-dot" aria-hidden="true" />
        {label}
      </span>
      <span className="scan-info" aria-label="Scan statistics">
        <span>
          scan <strong data-testid="scan-count">{scan}</strong>
        </span>
        <span>
          t = <strong>{formatClock(timeMs)}</strong>
        </span>
        <span>
          last scan <strong>{lastScanMs === null ? "—" : `${lastScanMs.toFixed(3)} ms`}</strong>
        </span>
      </span>
      {error ? (
        <span className="online-error" role="alert">
          {error}
        </span>
      ) : null}
    </div>
  );
}
