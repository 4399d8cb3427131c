// The simulation controls, always visible over the editor: Check, Compile & simulate, Run, Stop,
// Single cycle, Reset, Go offline; the online/offline state; the number of active forces with
// Release all forces; the prepared values (force / write / clear); scan counter, virtual time and
// the last scan time. Compile & simulate saves unsaved changes first (the server compiles the saved
// project). Keys (CODESYS's) come from the keymap and are handled by project/useAppKeys.ts.
import { panelsStore, usePanels } from "../panels/store";
import { workspaceStore } from "../project/store";
import { onlineStore, useOnline } from "./store";
import { formatClock } from "./values";
import { keysOf, type CommandOf } from "../keys/keymap";

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

/** A button's tooltip: what it does and its key from the keymap. */
const titled = (label: string, command: CommandOf<"app">) => `${label} (${keysOf("app", command)})`;

export function SimulationBar() {
  const phase = useOnline((s) => s.phase);
  const state = useOnline((s) => s.monitor.state);
  const scan = useOnline((s) => s.monitor.scan);
  const timeMs = useOnline((s) => s.monitor.timeMs);
  const forces = useOnline((s) => s.monitor.forced.size);
  const prepared = useOnline((s) => Object.keys(s.prepared).length);
  const lastScanMs = useOnline((s) => s.lastScanMs);
  const error = useOnline((s) => s.error);
  const checking = usePanels((s) => s.checking);
  const online = phase === "online";
  const running = state === "running";
  const s = onlineStore.getState();

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
      <button type="button" onClick={() => void checkSaved()} disabled={checking} title={titled("Check", "check")}>
        Check
      </button>
      <button
        type="button"
        onClick={() => void compileSaved()}
        disabled={phase === "compiling" || phase === "connecting"}
        title={titled("Compile & simulate", "go-online")}
      >
        Compile &amp; simulate
      </button>
      <button type="button" onClick={s.run} disabled={!online || running} title={titled("Run", "run")}>
        Run
      </button>
      <button
        type="button"
        onClick={s.stop}
        disabled={!online || !(running || state === "halted")}
        title={titled("Stop", "stop")}
      >
        Stop
      </button>
      <button
        type="button"
        onClick={s.singleCycle}
        disabled={!online}
        title={titled("Single cycle: one scan, then stopped", "single-cycle")}
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
        title={titled("Go offline", "go-offline")}
      >
        Go offline
      </button>
      <span className="online-state" role="status" aria-label="Online state">
        <span className="online-dot" aria-hidden="true" />
        {label}
      </span>
      <span className={`force-count${forces ? " forcing" : ""}`} role="status" aria-label="Active forces">
        {forces} forced
      </span>
      <button
        type="button"
        onClick={s.unforceAll}
        disabled={!online || forces === 0}
        title={titled("Release all forces", "release-forces")}
      >
        Release all forces
      </button>
      {prepared ? (
        <span className="prepared" role="group" aria-label="Prepared values">
          {prepared} prepared
          <button
            type="button"
            onClick={() => s.applyPrepared("force")}
            disabled={!online}
            title={titled("Force the prepared values", "force-prepared")}
          >
            Force
          </button>
          <button
            type="button"
            onClick={() => s.applyPrepared("write")}
            disabled={!online}
            title={titled("Write the prepared values", "write-prepared")}
          >
            Write
          </button>
          <button type="button" onClick={s.clearPrepared} title="Forget the prepared values">
            Clear
          </button>
        </span>
      ) : null}
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
