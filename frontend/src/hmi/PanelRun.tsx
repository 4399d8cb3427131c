// A panel online: the canvas with live values, and a thin toolbar (run, stop, time scale, run until,
// injected faults, the inputs so far as a file). Widget actions are panel input events, applied at the
// start of the next scan (queued while stopped or halted: the panel then shows the halt's values).
// `PanelLink` is where values come from and commands go: the app's online store, or the panel
// window's own connection (PanelWindow.tsx).
import { useEffect, useMemo, useState, type FormEvent } from "react";
import type { Panel } from "../generated/api";
import { getSimulation } from "../online/api";
import type { MonitorState } from "../online/monitor";
import type { ClientMessage, WriteValue } from "../online/protocol";
import { FaultDialog } from "./FaultDialog";
import { bindingsOf, type Widget } from "./model";
import { liveOf, PanelCanvas } from "./PanelCanvas";
import { parseUntil } from "./until";

export interface PanelLink {
  monitor: MonitorState;
  /** Connected to a running simulation. */
  online: boolean;
  simulation: string | null;
  send(msg: ClientMessage): boolean;
}

/** How often a panel takes values: the fastest the server sends, its publish rate (20 ms). */
export const PANEL_INTERVAL_MS = 20;

/** The time scales offered (the server takes 0.1 to 100). */
export const SPEEDS = [0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100];

export function PanelRun({ panel, link, onOpenWindow }: { panel: Panel; link: PanelLink; onOpenWindow?: () => void }) {
  const { monitor, online, send } = link;
  const live = useMemo(() => liveOf(monitor), [monitor]);
  const [faultPath, setFaultPath] = useState<string | null | undefined>(undefined);
  const act = online
    ? (path: string, value: WriteValue, widget?: Widget) =>
        void send({ type: "panel", path, value, panel: panel.name, widget: widget?.id ?? null })
    : null;
  return (
    <div className="hmi-run" data-state={monitor.state ?? "offline"}>
      <RunToolbar panel={panel} link={link} onFaults={() => setFaultPath(null)} onOpenWindow={onOpenWindow} />
      {!online ? (
        <p className="hmi-notice">Offline: compile and simulate (Alt+F8) to operate the panel.</p>
      ) : monitor.state === "halted" ? (
        <p className="hmi-notice">Halted: the panel shows the values at the halt; presses apply at the next scan.</p>
      ) : null}
      <div className="hmi-stage">
        <PanelCanvas
          panel={panel}
          live={live}
          act={act}
          onWidgetMenu={
            online
              ? (widget, event) => {
                  const path = "bind" in widget ? widget.bind : null;
                  if (!path) return;
                  event.preventDefault();
                  setFaultPath(path);
                }
              : undefined
          }
        />
      </div>
      {faultPath !== undefined ? (
        <FaultDialog
          paths={faultPath ? [faultPath] : bindingsOf(panel)}
          live={live}
          send={send}
          onClose={() => setFaultPath(undefined)}
        />
      ) : null}
    </div>
  );
}

function RunToolbar({
  panel,
  link,
  onFaults,
  onOpenWindow,
}: {
  panel: Panel;
  link: PanelLink;
  onFaults(): void;
  onOpenWindow?: () => void;
}) {
  const { monitor, online, simulation, send } = link;
  const [speed, setSpeed] = useState(1);
  const [until, setUntil] = useState("");
  const [problem, setProblem] = useState<string | null>(null);
  useEffect(() => {
    if (!simulation) return;
    let current = true;
    getSimulation(simulation).then(
      (info) => current && setSpeed(info.speed ?? 1),
      () => undefined,
    );
    return () => void (current = false);
  }, [simulation]);
  const runUntil = (e: FormEvent) => {
    e.preventDefault();
    const parsed = parseUntil(until, monitor.timeMs);
    if ("error" in parsed) return setProblem(parsed.error);
    setProblem(null);
    send({ type: "run_until", ...parsed });
  };
  const running = monitor.state === "running";
  return (
    <div className="hmi-toolbar" role="toolbar" aria-label={`Panel ${panel.name} controls`}>
      <button type="button" disabled={!online || running} onClick={() => send({ type: "run" })}>
        Run
      </button>
      <button type="button" disabled={!online || !running} onClick={() => send({ type: "stop" })}>
        Stop
      </button>
      <label>
        Time scale{" "}
        <select
          aria-label="Time scale"
          value={speed}
          disabled={!online}
          onChange={(e) => {
            const scale = Number(e.target.value);
            setSpeed(scale);
            send({ type: "speed", scale });
          }}
        >
          {SPEEDS.map((s) => (
            <option key={s} value={s}>
              {s}x
            </option>
          ))}
        </select>
      </label>
      <form onSubmit={runUntil}>
        <input
          aria-label="Run until"
          placeholder="run until: Level >= 80, NOT Alarm, 5s"
          value={until}
          onChange={(e) => setUntil(e.target.value)}
          disabled={!online}
          size={26}
        />
        <button type="submit" disabled={!online || !until.trim()}>
          Run until
        </button>
      </form>
      <button type="button" disabled={!online} onClick={onFaults}>
        Faults…
      </button>
      {simulation ? (
        <a
          href={`/api/simulations/${encodeURIComponent(simulation)}/inputs`}
          download
          title="The input events so far, one per line with its scan: ladderlab run --events replays them"
        >
          Download inputs
        </a>
      ) : null}
      {onOpenWindow ? (
        <button type="button" onClick={onOpenWindow}>
          Open in new window
        </button>
      ) : null}
      <span className="hmi-notice" role="status">
        {monitor.state ?? "offline"} · scan {monitor.scan} · {(monitor.timeMs / 1000).toFixed(2)} s
      </span>
      {problem ? (
        <span className="hmi-notice error" role="alert">
          {problem}
        </span>
      ) : null}
    </div>
  );
}
