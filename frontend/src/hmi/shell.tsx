// What the app shell shows of panels and exercises: the project tree's Panels section, and the tabs
// that are no POU (a panel: editor and online view; the exercise statement). Tab keys start with
// PANEL_TAB or are EXERCISE_TAB, which no POU name can be.
import { useEffect, useMemo, useState, type FormEvent } from "react";
import { useStore } from "zustand";
import { createStore } from "zustand/vanilla";
import type { Panel } from "../generated/api";
import { onlineStore, useOnline } from "../online/store";
import { useWorkspace, workspaceStore } from "../project/store";
import { ExerciseView } from "./ExerciseView";
import { panelChange, withPanel } from "./history";
import { bindingsOf, newPanel } from "./model";
import { PanelEditor } from "./PanelEditor";
import { PANEL_INTERVAL_MS, PanelRun, type PanelLink } from "./PanelRun";

export const PANEL_TAB = "hmi:";
export const EXERCISE_TAB = "exercise";

export const isShellTab = (key: string | null): boolean => !!key && (key.startsWith(PANEL_TAB) || key === EXERCISE_TAB);
export const tabLabel = (key: string): string =>
  key === EXERCISE_TAB ? "Exercise" : key.startsWith(PANEL_TAB) ? `${key.slice(PANEL_TAB.length)} (panel)` : key;

const NAME = /^[A-Za-z_][A-Za-z0-9_]{0,63}$/;
const NO_PANELS: Panel[] = [];

/** The project tree's Panels section, and the exercise statement. */
export function PanelsTree() {
  const panels = useWorkspace((s) => s.project?.panels ?? NO_PANELS);
  const exercise = useWorkspace((s) => s.project?.exercise ?? "");
  const active = useWorkspace((s) => s.active);
  const changed = useWorkspace((s) => s.changed);
  const [adding, setAdding] = useState(false);
  const [name, setName] = useState("");
  const [error, setError] = useState<string | null>(null);
  const open = (key: string) => workspaceStore.getState().openTab(key);
  const add = (e: FormEvent) => {
    e.preventDefault();
    const text = name.trim();
    if (!NAME.test(text)) return setError(`${text || "An empty name"} is not a name (letters, digits and _).`);
    if (panels.some((p) => p.name.toUpperCase() === text.toUpperCase())) return setError(`There is a panel ${text}.`);
    workspaceStore.getState().setProjectPart(panelChange(text), (project) => withPanel(project, newPanel(text)));
    setAdding(false);
    setName("");
    setError(null);
    open(PANEL_TAB + text);
  };
  return (
    <>
      <section>
        <h3>Panels</h3>
        {panels.length ? (
          <ul>
            {panels.map((p) => (
              <li key={p.name}>
                <button
                  type="button"
                  className="tree-item"
                  aria-current={active === PANEL_TAB + p.name ? "true" : undefined}
                  onClick={() => open(PANEL_TAB + p.name)}
                >
                  <span className="tree-name">{p.name}</span>
                  <span className="lang">HMI</span>
                  {changed.includes(panelChange(p.name)) ? (
                    <span className="unsaved" aria-label="unsaved changes">
                      ●
                    </span>
                  ) : null}
                </button>
              </li>
            ))}
          </ul>
        ) : (
          <p className="tree-empty">none</p>
        )}
        {adding ? (
          <form className="new-pou" aria-label="New panel" onSubmit={add}>
            <input
              aria-label="Panel name"
              autoFocus
              value={name}
              onChange={(e) => setName(e.target.value)}
              spellCheck={false}
            />
            <button type="submit">Create</button>
            <button type="button" onClick={() => setAdding(false)}>
              Cancel
            </button>
            {error ? <p role="alert">{error}</p> : null}
          </form>
        ) : (
          <button type="button" onClick={() => setAdding(true)}>
            New panel
          </button>
        )}
      </section>
      <section>
        <h3>Exercise</h3>
        <button
          type="button"
          className="tree-item"
          aria-current={active === EXERCISE_TAB ? "true" : undefined}
          onClick={() => open(EXERCISE_TAB)}
        >
          <span className="tree-name">{exercise ? "Statement" : "none (write one)"}</span>
        </button>
      </section>
    </>
  );
}

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

/** A widget to show in its panel's editor, selected (a diagnostic's click); `seq` tells two clicks apart. */
const widgetReveal = createStore<{ panel: string; widget: string | null; seq: number } | null>(() => null);
let reveals = 0;

/** Opens panel `panel` in its editor with `widget` selected (the Diagnostics panel's click on a binding). */
export function revealWidget(panel: string, widget: string | null): void {
  workspaceStore.getState().openTab(PANEL_TAB + panel);
  widgetReveal.setState({ panel, widget, seq: ++reveals }, true);
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
