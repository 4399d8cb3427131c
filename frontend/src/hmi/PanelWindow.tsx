// A panel in a browser window of its own (`/?panel=<project>/<panel>&simulation=<id>`, opened from the
// panel tab): no editor chrome, its own connection to the simulation (any number of clients may watch
// one), the same canvas and controls. Without a simulation id it attaches to the project's newest one.
import { useEffect, useMemo, useRef, useState } from "react";
import { getProject } from "../api/client";
import type { Panel } from "../generated/api";
import { listSimulations, monitorUrl } from "../online/api";
import { applyMessage, emptyMonitor, type MonitorState } from "../online/monitor";
import { parseServerMessage, type ClientMessage } from "../online/protocol";
import { bindingsOf } from "./model";
import { PANEL_INTERVAL_MS, PanelRun } from "./PanelRun";

function useConnection(simulation: string | null, paths: string[]) {
  const [monitor, setMonitor] = useState<MonitorState>(emptyMonitor);
  const [open, setOpen] = useState(false);
  const socket = useRef<WebSocket | null>(null);
  const key = paths.join("\n");
  useEffect(() => {
    if (!simulation) return;
    const ws = new WebSocket(monitorUrl(simulation));
    socket.current = ws;
    ws.onopen = () => {
      setOpen(true);
      ws.send(
        JSON.stringify({
          type: "subscribe",
          paths: key ? key.split("\n") : [],
          elements: [],
          interval_ms: PANEL_INTERVAL_MS,
        }),
      );
    };
    ws.onmessage = (event) => {
      const msg = typeof event.data === "string" ? parseServerMessage(event.data) : null;
      if (msg) setMonitor((state) => applyMessage(state, msg));
    };
    ws.onclose = () => setOpen(false);
    return () => {
      ws.onclose = null;
      ws.close();
      socket.current = null;
    };
  }, [simulation, key]);
  const send = (msg: ClientMessage) => {
    const ws = socket.current;
    if (!ws || ws.readyState !== WebSocket.OPEN) return false;
    ws.send(JSON.stringify(msg));
    return true;
  };
  return { monitor, open, send };
}

export function PanelWindow({
  project,
  panel: name,
  simulation,
}: {
  project: string;
  panel: string;
  simulation: string | null;
}) {
  const [panel, setPanel] = useState<Panel | null>(null);
  const [sim, setSim] = useState<string | null>(simulation);
  const [problem, setProblem] = useState<string | null>(null);
  useEffect(() => {
    getProject(project).then(
      (doc) => {
        const found = doc.project.panels?.find((p) => p.name === name);
        if (found) setPanel(found);
        else setProblem(`Project ${project} has no panel ${name}.`);
      },
      (err: unknown) => setProblem(err instanceof Error ? err.message : String(err)),
    );
    if (!simulation)
      listSimulations().then(
        (all) =>
          setSim(
            all.filter((s) => s.project === project).sort((a, b) => b.created.localeCompare(a.created))[0]?.id ?? null,
          ),
        () => undefined,
      );
  }, [project, name, simulation]);
  const paths = useMemo(() => (panel ? bindingsOf(panel) : []), [panel]);
  const { monitor, open, send } = useConnection(sim, paths);
  useEffect(() => {
    document.title = `${name} · ${project} · LadderLab`;
  }, [name, project]);
  if (problem) return <p role="alert">{problem}</p>;
  if (!panel) return <p className="placeholder">Opening panel {name}…</p>;
  return (
    <div className="hmi-window">
      <PanelRun panel={panel} link={{ monitor, online: open, simulation: sim, send }} />
      {!sim ? (
        <p className="hmi-notice">No simulation of {project} runs: compile and simulate it in the main window.</p>
      ) : null}
    </div>
  );
}
