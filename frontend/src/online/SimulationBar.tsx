// The simulation controls, always visible over the editor: Check, Compile & simulate, Run, Stop,
// Single cycle, Reset, Go offline; the online/offline state; the number of active forces with
// Release all forces; the prepared values (force / write / clear); scan counter, virtual time and
// the last scan time; the scan history's timeline (HistoryBar.tsx) and Open recording (OpenRecording.tsx). Check checks the working copy and never saves;
// Compile & simulate compiles the saved project, so with unsaved changes it asks: save and compile, compile the
// saved version, or cancel. Keys (CODESYS's) come from the keymap and are handled by app/useAppKeys.ts.
import { panelsStore, usePanels } from "../store/panels";
import { workspaceStore } from "../store/project";
import { onlineStore, useOnline } from "./store";
import { formatClock } from "./values";
import { useStore } from "zustand";
import { createStore } from "zustand/vanilla";
import { HistoryBar } from "./HistoryBar";
import { OpenRecording } from "./OpenRecording";
import { keysOf, type CommandOf } from "../keys/keymap";
import { CheckCheck, Cpu, LockOpen, Play, RotateCcw, Square, StepForward, Unplug } from "lucide-react";
import { useRef } from "react";
import { OverflowBar, toolItem, type BarItem } from "../ui/OverflowBar";

/** Saves pending changes; the project's name once it is saved, else null (the save's message is shown). */
async function savedProject(): Promise<string | null> {
  const ws = workspaceStore.getState();
  if (!ws.name) return null;
  if (ws.changed.length) {
    await ws.save();
    if (workspaceStore.getState().changed.length) return null; // the save failed or conflicted; its message is shown
  }
  return ws.name;
}

/** Check: every diagnostic of the working copy as it is; nothing is saved. */
export async function checkWorkingCopy(): Promise<void> {
  const { project } = workspaceStore.getState();
  if (project) await panelsStore.getState().check(project);
}

/** Whether the "unsaved changes" question of Compile & simulate is open. */
const compileQuestion = createStore<{ open: boolean }>()(() => ({ open: false }));

/** Compile & simulate: the server compiles the saved project, so with unsaved changes the user chooses first. */
export async function compileSaved(): Promise<void> {
  const ws = workspaceStore.getState();
  if (ws.changed.length) compileQuestion.setState({ open: true });
  else if (ws.name) await compile(ws.name);
}

async function compile(name: string | null): Promise<void> {
  compileQuestion.setState({ open: false });
  if (!name) return;
  await onlineStore.getState().compile(name);
  const { compileDiagnostics } = onlineStore.getState();
  if (compileDiagnostics.length) panelsStore.getState().showDiagnostics(compileDiagnostics);
}

/** Save and compile / compile the saved version / cancel. */
function CompileQuestion() {
  const open = useStore(compileQuestion, (s) => s.open);
  const changed = workspaceStore.getState().changed;
  if (!open) return null;
  return (
    <div className="ld-dialog-backdrop">
      <div className="ld-dialog" role="alertdialog" aria-label="Unsaved changes">
        <h2>Compile with unsaved changes?</h2>
        <p>The simulator compiles the saved project. Unsaved: {changed.join(", ")}.</p>
        <div className="dialog-buttons">
          <button type="button" autoFocus onClick={() => void savedProject().then(compile)}>
            Save and compile
          </button>
          <button type="button" onClick={() => void compile(workspaceStore.getState().name)}>
            Compile the saved version
          </button>
          <button type="button" onClick={() => compileQuestion.setState({ open: false })}>
            Cancel
          </button>
        </div>
      </div>
    </div>
  );
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
  const recording = useOnline((s) => s.monitor.history?.recording ?? false); // history only: no scan runs
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
  const recording_ = useRef<HTMLSpanElement>(null);
  const busy = phase === "compiling" || phase === "connecting";
  // One row (ui/OverflowBar.tsx): as it narrows, Open recording, Reset and Release all forces go into More first;
  // the state, the force count and the scan figures always stay.
  const items: BarItem[] = [
    toolItem(
      {
        id: "check",
        icon: CheckCheck,
        label: "Check",
        keys: keysOf("app", "check"),
        hint: "the project as it is (nothing is saved)",
        disabled: checking,
        run: () => void checkWorkingCopy(),
      },
      { priority: 3 },
    ),
    toolItem(
      {
        id: "compile",
        icon: Cpu,
        label: "Compile & simulate",
        keys: keysOf("app", "go-online"),
        hint: "saves first when you choose, since the server compiles the saved project",
        disabled: busy,
        run: () => void compileSaved(),
      },
      { priority: 4 },
    ),
    {
      key: "open-recording",
      node: (
        <span ref={recording_} className="open-recording">
          <OpenRecording />
        </span>
      ),
      // the bar's own button (kept out of sight when it does not fit) opens the file chooser
      entries: [
        {
          id: "open-recording",
          label: "Open recording…",
          disabled: busy,
          run: () => recording_.current?.querySelector("button")?.click(),
        },
      ],
      priority: 0,
    },
    toolItem(
      {
        id: "run",
        icon: Play,
        label: "Run",
        keys: keysOf("app", "run"),
        run: s.run,
        disabled: !online || running || recording,
      },
      { group: true, priority: 4 },
    ),
    toolItem(
      {
        id: "stop",
        icon: Square,
        label: "Stop",
        keys: keysOf("app", "stop"),
        run: s.stop,
        disabled: !online || !(running || state === "halted"),
      },
      { priority: 4 },
    ),
    toolItem(
      {
        id: "single-cycle",
        icon: StepForward,
        label: "Single cycle",
        keys: keysOf("app", "single-cycle"),
        run: s.singleCycle,
        disabled: !online || recording,
      },
      { priority: 4 },
    ),
    toolItem(
      { id: "reset", icon: RotateCcw, label: "Reset", run: () => void s.reset(), disabled: !online || recording },
      { priority: 1 },
    ),
    toolItem(
      {
        id: "go-offline",
        icon: Unplug,
        label: "Go offline",
        keys: keysOf("app", "go-offline"),
        run: () => void s.goOffline(),
        disabled: phase === "offline",
      },
      { priority: 2 },
    ),
    {
      key: "state",
      node: (
        <span className="online-state" role="status" aria-label="Online state">
          <span className="online-dot" aria-hidden="true" />
          {label}
        </span>
      ),
    },
    {
      key: "forces",
      node: (
        <span className={`force-count${forces ? " forcing" : ""}`} role="status" aria-label="Active forces">
          {forces} forced
        </span>
      ),
    },
    toolItem(
      {
        id: "release-forces",
        icon: LockOpen,
        label: "Release all forces",
        keys: keysOf("app", "release-forces"),
        run: s.unforceAll,
        disabled: !online || forces === 0,
      },
      { priority: 1 },
    ),
    ...(prepared ? preparedItems(prepared, online) : []),
    { key: "scan", node: <ScanFigures scan={scan} timeMs={timeMs} lastScanMs={lastScanMs} /> },
  ];
  return (
    <div className={`simulation-bar phase-${phase}${running ? " running" : ""}`} role="toolbar" aria-label="Simulation">
      <CompileQuestion />
      <OverflowBar
        role="group"
        label="Simulation commands"
        className="simulation-row"
        moreLabel="More simulation commands"
        items={items}
      />
      <HistoryBar />
      {error ? (
        <span className="online-error" role="alert">
          {error}
        </span>
      ) : null}
    </div>
  );
}

/** The prepared values: their count always in the row; Force, Write and Clear go into More when they do not fit. */
function preparedItems(prepared: number, online: boolean): BarItem[] {
  const s = onlineStore.getState();
  return [
    {
      key: "prepared",
      node: (
        <span className="prepared" role="status" aria-label="Prepared values">
          {prepared} prepared
        </span>
      ),
      group: true,
    },
    textItem("force-prepared", "Force", "Force the prepared values", !online, () => s.applyPrepared("force")),
    textItem("write-prepared", "Write", "Write the prepared values", !online, () => s.applyPrepared("write")),
    {
      key: "clear-prepared",
      node: (
        <button type="button" onClick={s.clearPrepared} title="Forget the prepared values">
          Clear
        </button>
      ),
      entries: [{ id: "clear-prepared", label: "Forget the prepared values", run: s.clearPrepared }],
      priority: 2,
    },
  ];
}

/** A text button for a keyed command on the prepared values; in More it says what it does with its key. */
function textItem(
  command: "force-prepared" | "write-prepared",
  text: string,
  label: string,
  disabled: boolean,
  run: () => void,
): BarItem {
  return {
    key: command,
    node: (
      <button type="button" onClick={run} disabled={disabled} title={titled(label, command)}>
        {text}
      </button>
    ),
    entries: [{ id: command, label, keys: keysOf("app", command), disabled, run }],
    priority: 2,
  };
}

/** The scan counter, the virtual time and the last scan's duration in one compact line; the tooltip says it in words. */
function ScanFigures({ scan, timeMs, lastScanMs }: { scan: number; timeMs: number; lastScanMs: number | null }) {
  const clock = formatClock(timeMs);
  const last = lastScanMs === null ? "—" : `${lastScanMs.toFixed(3)} ms`;
  const words = `Scan ${scan}; virtual time t = ${clock}; last scan ${lastScanMs === null ? "not measured yet" : `took ${last}`}`;
  return (
    <span className="scan-info" aria-label="Scan statistics" title={words}>
      scan <strong data-testid="scan-count">{scan}</strong> · <strong>{clock}</strong> · <strong>{last}</strong>
    </span>
  );
}
