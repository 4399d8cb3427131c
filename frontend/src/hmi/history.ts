// The undo history of each open panel (kept while the project is open, like the LD editor's per POU):
// every edit records the new panel and writes it into the project's working copy (marked unsaved).
import { useStore } from "zustand";
import { createStore } from "zustand/vanilla";
import type { Panel, Project } from "../generated/api";
import { historyOf, record, redo, undo, type History } from "../store/history";
import { useWorkspace, workspaceStore } from "../store/project";

const histories = createStore<Record<string, History<Panel>>>()(() => ({}));

/** The change key of a panel in the project's unsaved list. */
export const panelChange = (name: string): string => `panel ${name}`;

/** The project with `panel` in place of the panel of that name (or added at the end). */
export function withPanel(project: Project, panel: Panel): Project {
  const panels = project.panels ?? [];
  const found = panels.some((p) => p.name === panel.name);
  return { ...project, panels: found ? panels.map((p) => (p.name === panel.name ? panel : p)) : [...panels, panel] };
}

function write(key: string, history: History<Panel>) {
  histories.setState({ [key]: history });
  const panel = history.present;
  workspaceStore.getState().setProjectPart(panelChange(panel.name), (project) => withPanel(project, panel));
}

export function usePanelHistory(name: string) {
  const project = useWorkspace((s) => s.name);
  const panel = useWorkspace((s) => s.project?.panels?.find((p) => p.name === name));
  const key = `${project}/${name}`;
  const stored = useStore(histories, (s) => s[key]);
  // The project's panel is the truth: a history that no longer ends in it (a reload) starts again.
  const history = stored && stored.present === panel ? stored : panel ? historyOf(panel) : undefined;
  return {
    panel,
    history: history ?? historyOf<Panel>({ name }),
    commit: (next: Panel) => history && next !== history.present && write(key, record(history, next)),
    undoStep: () => history && history.past.length && write(key, undo(history)),
    redoStep: () => history && history.future.length && write(key, redo(history)),
  };
}
