// The content of a shell tab (a panel's online view and editor, the exercise statement), in its own chunk:
// the panel widgets and the Markdown renderer load the first time such a tab opens.
import { useEffect, useMemo, useState } from "react";
import { useStore } from "zustand";
import { onlineStore, useOnline } from "../online/store";
import { useWorkspace } from "../store/project";
import { ExerciseView } from "./ExerciseView";
import { bindingsOf } from "./model";
import { PanelEditor } from "./PanelEditor";
import { PANEL_INTERVAL_MS, PanelRun, type PanelLink } from "./PanelRun";
import { EXERCISE_TAB, PANEL_TAB, widgetReveal } from "./shell";

/** The content of a shell tab. */
export function ShellTab({ tab }: { tab: string }) {
  if (tab === EXERCISE_TAB) return <ExerciseView />;
  return <PanelTab key={tab} name={tab.slice(PANEL_TAB.length)} />;
}

/** The app's online store as a panel's link, with the panel's variables subscribed while it shows. */
function useAppLink(paths: string[], view: string): PanelLink {
  const monitor = useOnline((s) => s.monitor);
  const phase = useOnline((s) => s.phase);
  const simulation = useOnline((s) => s.simulation);
  const key = paths.join("\n");
  useEffect(() => {
    const store = onlineStore.getState();
    store.subscribe(view, { paths: key ? key.split("\n") : [], elements: [], interval_ms: PANEL_INTERVAL_MS });
    return () => onlineStore.getState().subscribe(view, null);
  }, [key, view]);
  return { monitor, online: phase === "online", simulation, send: (msg) => onlineStore.getState().send(msg) };
}

function PanelTab({ name }: { name: string }) {
  const panel = useWorkspace((s) => s.project?.panels?.find((p) => p.name === name));
  const project = useWorkspace((s) => s.name);
  const [mode, setMode] = useState<"run" | "edit">("run");
  const reveal = useStore(widgetReveal);
  const [revealed, setRevealed] = useState<{ widget: string | null; seq: number } | null>(null);
  if (reveal?.panel === name && reveal.seq !== revealed?.seq) {
    setRevealed(reveal);
    setMode("edit");
  }
  useEffect(() => {
    if (reveal?.panel === name) widgetReveal.setState(null, true); // taken: the tab opens as usual next time
  }, [reveal, name]);
  const paths = useMemo(() => (panel && mode === "run" ? bindingsOf(panel) : []), [panel, mode]);
  const link = useAppLink(paths, `hmi:${name}`);
  if (!panel || !project) return <p className="placeholder">There is no panel {name} in this project.</p>;
  const openWindow = () => {
    const query = new URLSearchParams({ panel: `${project}/${name}`, simulation: link.simulation ?? "" });
    window.open(
      `/?${query}`,
      `ladderlab-panel-${project}-${name}`,
      `popup,width=${(panel.width ?? 800) + 40},height=${(panel.height ?? 480) + 120}`,
    );
  };
  return (
    <div className="pou-view">
      <div className="pou-modes" role="tablist" aria-label={`${name} views`}>
        <button type="button" role="tab" aria-selected={mode === "run"} onClick={() => setMode("run")}>
          Panel
        </button>
        <button type="button" role="tab" aria-selected={mode === "edit"} onClick={() => setMode("edit")}>
          Edit
        </button>
      </div>
      {mode === "run" ? (
        <PanelRun panel={panel} link={link} onOpenWindow={openWindow} />
      ) : (
        <PanelEditor key={revealed?.seq ?? 0} name={name} selected={revealed?.widget ? [revealed.widget] : undefined} />
      )}
    </div>
  );
}
