// What the app shell shows of panels and exercises: the project tree's Panels section and the keys of
// the tabs that are no POU (a panel: editor and online view; the exercise statement; their content is
// ShellTab.tsx, loaded on first use). Tab keys start with PANEL_TAB or are EXERCISE_TAB (store/parts.ts), which
// no POU name can be (both hold a ':').
import { createStore } from "zustand/vanilla";
import type { Panel } from "../generated/api";
import { useWorkspace, workspaceStore } from "../store/project";
import { panelChange, withPanel } from "./history";
import { newPanel } from "./model";
import { EXERCISE_TAB, partLabel } from "../store/parts";
import { NewNameForm } from "../ui/NewNameForm";

export { EXERCISE_TAB };

export const PANEL_TAB = "hmi:";

export const isShellTab = (key: string | null): boolean => !!key && (key.startsWith(PANEL_TAB) || key === EXERCISE_TAB);
/** What a tab or an unsaved-changes entry shows: a panel's name, a project part's label, a POU's name. */
export const tabLabel = (key: string): string =>
  key.startsWith(PANEL_TAB) ? `${key.slice(PANEL_TAB.length)} (panel)` : partLabel(key);

const NAME = /^[A-Za-z_][A-Za-z0-9_]{0,63}$/;
const NO_PANELS: Panel[] = [];

/** The project tree's Panels section, and the exercise statement. */
export function PanelsTree() {
  const panels = useWorkspace((s) => s.project?.panels ?? NO_PANELS);
  const exercise = useWorkspace((s) => s.project?.exercise ?? "");
  const active = useWorkspace((s) => s.active);
  const changed = useWorkspace((s) => s.changed);
  const open = (key: string) => workspaceStore.getState().openTab(key);
  const add = (text: string): string | null => {
    if (!NAME.test(text)) return `${text || "An empty name"} is not a name (letters, digits and _).`;
    if (panels.some((p) => p.name.toUpperCase() === text.toUpperCase())) return `There is a panel ${text}.`;
    workspaceStore.getState().setProjectPart(panelChange(text), (project) => withPanel(project, newPanel(text)));
    open(PANEL_TAB + text);
    return null;
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
        <NewNameForm formLabel="New panel" inputLabel="Panel name" buttonLabel="New panel" create={add} />
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

/** A widget to show in its panel's editor, selected (a diagnostic's click); `seq` tells two clicks apart. */
export const widgetReveal = createStore<{ panel: string; widget: string | null; seq: number } | null>(() => null);
let reveals = 0;

/** Opens panel `panel` in its editor with `widget` selected (the Diagnostics panel's click on a binding). */
export function revealWidget(panel: string, widget: string | null): void {
  workspaceStore.getState().openTab(PANEL_TAB + panel);
  widgetReveal.setState({ panel, widget, seq: ++reveals }, true);
}
