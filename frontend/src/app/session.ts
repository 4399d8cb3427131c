// What a user set up for a project survives a page reload (issue 17): the watch list and what of it
// was expanded, the trace setup, the open tabs and the active one, and the simulation that was
// running, kept per project in localStorage; and which project was open last. The stores stay
// unaware: `keepSession` watches them and `restoreSession` fills them when the project opens again.
import type { StoreApi } from "zustand/vanilla";
import type { OnlineState } from "../online/store";
import type { TraceState } from "../trace/store";
import type { TriggerForm } from "../trace/trigger";
import type { WorkspaceState } from "../store/project";
import { migratedTab } from "../store/parts";

export interface TraceSetup {
  paths: string[];
  trigger: TriggerForm;
  capacity: number;
  stopWhenFull: boolean;
  laneView: boolean;
}

export interface Session {
  watch: string[];
  watchExpanded: string[];
  trace: TraceSetup | null;
  tabs: string[];
  active: string | null;
  /** The simulation of this project that ran when the page went away (reattached if still there). */
  simulation: string | null;
}

const emptySession: Session = { watch: [], watchExpanded: [], trace: null, tabs: [], active: null, simulation: null };
const sessionKey = (project: string) => `ladderlab:session:${project}`;
/** 2: the project parts' tabs are keyed `part:<id>` (store/parts.ts); an entry without it has the old keys. */
const SESSION_VERSION = 2;
const LAST_PROJECT = "ladderlab:last-project";

const strings = (value: unknown): string[] =>
  Array.isArray(value) ? value.filter((v): v is string => typeof v === "string") : [];

/** `project`'s kept session; an empty one when none was kept or the entry is unreadable. */
export function loadSession(project: string, storage: Storage): Session {
  try {
    const kept = JSON.parse(storage.getItem(sessionKey(project)) ?? "null") as Partial<Record<keyof Session, unknown>>;
    if (!kept || typeof kept !== "object") return emptySession;
    const trace = kept.trace as Partial<TraceSetup> | null | undefined;
    const tab = (key: string) => ((kept as { version?: unknown }).version === SESSION_VERSION ? key : migratedTab(key));
    return {
      watch: strings(kept.watch),
      watchExpanded: strings(kept.watchExpanded),
      trace:
        trace && Array.isArray(trace.paths) && typeof trace.trigger === "object" && trace.trigger
          ? {
              paths: strings(trace.paths),
              trigger: trace.trigger,
              capacity: typeof trace.capacity === "number" ? trace.capacity : 1000,
              stopWhenFull: trace.stopWhenFull !== false,
              laneView: trace.laneView !== false,
            }
          : null,
      tabs: strings(kept.tabs).map(tab),
      active: typeof kept.active === "string" ? tab(kept.active) : null,
      simulation: typeof kept.simulation === "string" ? kept.simulation : null,
    };
  } catch {
    return emptySession;
  }
}

function saveSession(project: string, session: Session, storage: Storage): void {
  try {
    storage.setItem(sessionKey(project), JSON.stringify({ ...session, version: SESSION_VERSION }));
  } catch {
    // storage full or refused: the session works until the page is reloaded
  }
}

export function lastProject(storage: Storage): string | null {
  try {
    return storage.getItem(LAST_PROJECT);
  } catch {
    return null;
  }
}

export function rememberProject(project: string | null, storage: Storage): void {
  try {
    if (project) storage.setItem(LAST_PROJECT, project);
    else storage.removeItem(LAST_PROJECT);
  } catch {
    // as above
  }
}

export interface SessionStores {
  workspace: StoreApi<WorkspaceState>;
  online: StoreApi<OnlineState>;
  trace: StoreApi<TraceState>;
}

/** The session the stores hold now for `project`. */
function sessionOf(project: string, { workspace, online, trace }: SessionStores): Session {
  const w = workspace.getState();
  const o = online.getState();
  const t = trace.getState();
  return {
    watch: o.watch,
    watchExpanded: o.watchExpanded,
    trace: {
      paths: t.paths,
      trigger: t.trigger,
      capacity: t.capacity,
      stopWhenFull: t.stopWhenFull,
      laneView: t.laneView,
    },
    tabs: w.tabs,
    active: w.active,
    simulation: o.project === project ? o.simulation : null,
  };
}

/**
 * Puts `project`'s kept session back into the stores once its project has loaded: the watch list,
 * the trace setup, the tabs, and the simulation if the server still runs it. Returns whether a
 * simulation was reattached.
 */
export async function restoreSession(project: string, stores: SessionStores, storage: Storage): Promise<boolean> {
  const session = loadSession(project, storage);
  stores.online.getState().restoreWatch(session.watch, session.watchExpanded);
  if (session.trace) stores.trace.setState(session.trace);
  const workspace = stores.workspace.getState();
  for (const tab of session.tabs) workspace.openPou(tab);
  if (session.active && stores.workspace.getState().tabs.includes(session.active))
    stores.workspace.getState().openPou(session.active);
  return session.simulation ? stores.online.getState().attach(project, session.simulation) : false;
}

/** Keeps `project`'s session in `storage` as the stores change; returns the unsubscribe. */
export function keepSession(project: string, stores: SessionStores, storage: Storage): () => void {
  const save = () => {
    if (stores.workspace.getState().name === project) saveSession(project, sessionOf(project, stores), storage);
  };
  const unsubscribe = [
    stores.online.subscribe((s, p) => {
      if (s.watch !== p.watch || s.watchExpanded !== p.watchExpanded || s.simulation !== p.simulation) save();
    }),
    stores.trace.subscribe((s, p) => {
      if (
        s.paths !== p.paths ||
        s.trigger !== p.trigger ||
        s.capacity !== p.capacity ||
        s.stopWhenFull !== p.stopWhenFull ||
        s.laneView !== p.laneView
      )
        save();
    }),
    stores.workspace.subscribe((s, p) => {
      if (s.tabs !== p.tabs || s.active !== p.active) save();
    }),
  ];
  return () => unsubscribe.forEach((u) => u());
}
