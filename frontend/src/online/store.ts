// Online mode (zustand): one simulation of the open project, its monitor websocket, the merged
// subscription of every view that shows live values (LD editors, the watch list), and the
// commands the toolbar, the diagram and the watch list send. The socket and the REST calls are
// injected so tests drive the store with fakes.
import { useStore } from "zustand";
import { createStore, type StoreApi } from "zustand/vanilla";
import { ApiError } from "../api/client";
import type { Diagnostic, IoPoint, SimulationInfo } from "../generated/api";
import { monitorUrl, simulationApi, type SimulationApi } from "./api";
import {
  applyMessage,
  connectionOpened,
  emptyMonitor,
  keepSubscribed,
  logLocal,
  pathKey,
  powerKey,
  type LogEntry,
  type MonitorState,
} from "./monitor";
import {
  DEFAULT_INTERVAL_MS,
  parseServerMessage,
  type ClientMessage,
  type ElementSubscription,
  type ServerMessage,
  type WriteValue,
} from "./protocol";

/** The part of WebSocket the store uses. */
export type SocketLike = Pick<WebSocket, "readyState" | "send" | "close" | "onopen" | "onmessage" | "onclose">;

export type OpenSocket = (url: string) => SocketLike;

const OPEN = 1;
/** How often the toolbar's scan statistics are refreshed from GET /api/simulations/{id}. */
export const STATS_POLL_MS = 1000;
/** Waits before each attempt to reconnect to a simulation whose connection dropped (then: offline). */
export const RECONNECT_DELAYS_MS = [200, 500, 1000, 2000, 4000];

export interface Subscription {
  paths: string[];
  elements: ElementSubscription[];
  /** How often the view wants values (ms; default DEFAULT_INTERVAL_MS): the subscription takes the shortest. */
  interval_ms?: number;
}

export type Phase = "offline" | "compiling" | "connecting" | "online";

export interface OnlineData {
  phase: Phase;
  project: string | null;
  simulation: string | null;
  error: string | null;
  /** Why the last compile was refused. */
  compileDiagnostics: Diagnostic[];
  /** The simulation's instance paths of every program and function block, by POU name in upper case. */
  instanceChoices: Record<string, string[]>;
  /** The direct addresses the simulation's program uses (%I, %Q, %M), in address order. */
  io: IoPoint[];
  monitor: MonitorState;
  lastScanMs: number | null;
  /** What each view wants to see, by view key. */
  views: Record<string, Subscription>;
  /** Paths in the watch list, as the user typed them. */
  watch: string[];
  /** Upper-case paths of the watch list's expanded rows (FB instances, structures, arrays). */
  watchExpanded: string[];
  /** The instance a function block's diagram shows online, by POU name (e.g. Blinker -> MAIN.BLINK). */
  instances: Record<string, string>;
  /** Counts the connections opened to the simulation (a reconnect ends what the server kept per client). */
  connection: number;
  /**
   * Prepared values (CODESYS): double-clicking a value prepares one; F7 forces them all, Ctrl+F7
   * writes them. Keyed by upper-case path; the value as it will be sent.
   */
  prepared: Readonly<Record<string, WriteValue>>;
  /** Why the last seek (or back to live) was refused, in the server's words; null once one is answered. */
  historyError: string | null;
}

export interface OnlineActions {
  /**
   * Compiles the saved project and connects; an open simulation is closed first. `create` makes the
   * simulation another way (the Tests panel: a failed test's last state).
   */
  compile(project: string, create?: () => Promise<SimulationInfo>): Promise<void>;
  /**
   * Connects to simulation `id` of `project` if it still runs on the server (after a page reload);
   * false when it is gone or belongs to another project.
   */
  attach(project: string, id: string): Promise<boolean>;
  goOffline(): Promise<void>;
  run(): void;
  stop(): void;
  /** Exactly one scan, then stopped (a running simulation is stopped first; halted: the rest of the scan). */
  singleCycle(): void;
  reset(cold?: boolean): Promise<void>;
  write(path: string, value: WriteValue): void;
  force(path: string, value: WriteValue): void;
  unforce(path: string): void;
  unforceAll(): void;
  /** Shows past scan `scan` from the scan history (values as `values.scan` numbers them); the live scans go on.
   * Seeks and goLive go one at a time in the order asked; while one runs, only the newest asked waits (a drag of
   * the slider does not queue every scan it passes). A refusal lands in `historyError`. */
  seek(scan: number): Promise<void>;
  /** Shows the live scans again after `seek`. */
  goLive(): Promise<void>;
  /** Continues from the scan shown: a new branch of the history becomes live (the old one is kept). */
  fork(): void;
  /** Prepares `value` for `path` (null: drops its prepared value). */
  prepare(path: string, value: WriteValue | null): void;
  /** Forces (F7) or writes (Ctrl+F7) every prepared value, then forgets them. */
  applyPrepared(action: "force" | "write"): void;
  clearPrepared(): void;
  /** Sets (or with null removes) the subscription of one view. */
  subscribe(view: string, subscription: Subscription | null): void;
  addWatch(path: string): void;
  removeWatch(path: string): void;
  /** Opens or closes a row of the watch list's tree. */
  toggleWatchExpanded(path: string): void;
  /** The watch list of a project opened again (kept in localStorage); the rows it had expanded. */
  restoreWatch(watch: readonly string[], expanded: readonly string[]): void;
  setInstance(pou: string, instance: string): void;
  /** Sends any client message (breakpoints, continue, step); false and a log line when not connected. */
  send(msg: ClientMessage): boolean;
  /** A note of this browser's in the online log (e.g. a breakpoint removed because its place is gone). */
  note(level: LogEntry["level"], message: string): void;
  /** Hears every server message after it is folded into `monitor` (e.g. trace chunks); returns the unsubscribe. */
  listen(listener: (msg: ServerMessage) => void): () => void;
}

export type OnlineState = OnlineData & OnlineActions;

/** What going offline resets; the views, the watch list and the chosen instances stay. */
export const offline: Omit<OnlineData, "views" | "watch" | "watchExpanded" | "instances" | "connection"> = {
  phase: "offline",
  project: null,
  simulation: null,
  error: null,
  compileDiagnostics: [],
  instanceChoices: {},
  io: [],
  monitor: emptyMonitor,
  lastScanMs: null,
  prepared: {},
  historyError: null,
};

/** The union of every view's subscription: paths without repeats, element ids merged per instance. */
export function mergeSubscriptions(views: Iterable<Subscription>): Subscription {
  const paths = new Set<string>();
  const byInstance = new Map<string, Set<string> | null>();
  const all = [...views];
  for (const view of all) {
    for (const p of view.paths) paths.add(pathKey(p));
    for (const { pou_instance, ids = null } of view.elements) {
      const key = pou_instance.toUpperCase();
      const known = byInstance.get(key);
      if (ids === null || known === null) byInstance.set(key, null);
      else byInstance.set(key, new Set([...(known ?? []), ...ids]));
    }
  }
  const intervals = all.map((v) => v.interval_ms).filter((ms): ms is number => ms !== undefined);
  return {
    ...(intervals.length ? { interval_ms: Math.min(...intervals) } : {}),
    paths: [...paths].sort(),
    elements: [...byInstance].map(([pou_instance, ids]) => ({ pou_instance, ids: ids ? [...ids].sort() : null })),
  };
}

const message = (err: unknown) => (err instanceof Error ? err.message : String(err));
const GONE = "The simulation is gone (stopped on the server); compile & simulate to start a new one.";

const compileDiagnosticsOf = (err: unknown): Diagnostic[] => {
  const detail = err instanceof ApiError ? (err.detail as { diagnostics?: unknown } | undefined) : undefined;
  return Array.isArray(detail?.diagnostics) ? (detail.diagnostics as Diagnostic[]) : [];
};

const defaultSocket: OpenSocket = (url) => new WebSocket(url);

export function createOnlineStore(
  api: SimulationApi = simulationApi,
  openSocket: OpenSocket = defaultSocket,
  url: (id: string) => string = monitorUrl,
): StoreApi<OnlineState> {
  let socket: SocketLike | null = null;
  let lastSent = "";
  let poll: ReturnType<typeof setInterval> | null = null;
  const listeners = new Set<(msg: ServerMessage) => void>();

  return createStore<OnlineState>()((set, get) => {
    const send = (msg: ClientMessage): boolean => {
      if (!socket || socket.readyState !== OPEN) {
        set({ monitor: logLocal(get().monitor, "warning", `not connected: ${msg.type} was not sent`) });
        return false;
      }
      socket.send(JSON.stringify(msg));
      return true;
    };

    const views = (): Subscription[] => [...Object.values(get().views), { paths: get().watch, elements: [] }];

    /** Sends the merged subscription when it changed (and always after connecting). */
    const resubscribe = (force = false) => {
      if (!socket || socket.readyState !== OPEN) return;
      const merged = mergeSubscriptions(views());
      const text = JSON.stringify(merged);
      if (!force && text === lastSent) return;
      lastSent = text;
      const powerKeys = merged.elements.flatMap((e) => (e.ids ?? []).map((id) => powerKey(e.pou_instance, id)));
      set({ monitor: keepSubscribed(get().monitor, merged.paths, powerKeys) });
      const interval_ms = merged.interval_ms ?? DEFAULT_INTERVAL_MS;
      send({ type: "subscribe", paths: merged.paths, elements: merged.elements, interval_ms });
    };

    const stopPolling = () => {
      if (poll !== null) clearInterval(poll);
      poll = null;
    };

    const disconnect = () => {
      stopPolling();
      const s = socket;
      socket = null;
      lastSent = "";
      if (s) {
        s.onclose = null;
        s.onmessage = null;
        s.close();
      }
    };

    /** The scan to show next (`"live"`: the live scans) and the request under way, if any (see `seek`). */
    let wanted: number | "live" | null = null;
    let showing: Promise<void> | null = null;
    const show = (target: number | "live"): Promise<void> => {
      wanted = target;
      if (showing) return showing;
      showing = (async () => {
        while (wanted !== null) {
          const id = get().simulation;
          const next: number | "live" = wanted;
          wanted = null;
          if (!id) break;
          try {
            await (next === "live" ? api.goLive(id) : api.seekScan(id, next));
            if (get().simulation === id) set({ historyError: null });
          } catch (err) {
            if (get().simulation === id) set({ historyError: message(err) });
          }
        }
        showing = null;
      })();
      return showing;
    };

    let retry: ReturnType<typeof setTimeout> | null = null;
    const stopRetrying = () => {
      if (retry !== null) clearTimeout(retry);
      retry = null;
    };

    /** After a dropped connection: the simulation may still run (a server hiccup), so try again. */
    const reconnect = (id: string, attempt: number) => {
      if (attempt >= RECONNECT_DELAYS_MS.length) {
        set({ ...offline, error: "The connection to the simulation was lost." });
        return;
      }
      retry = setTimeout(() => {
        retry = null;
        api.listSimulations().then(
          (running) => {
            if (get().simulation !== id || get().phase !== "connecting") return;
            if (running.some((s) => s.id === id)) connect(id, attempt + 1);
            else set({ ...offline, monitor: logLocal(get().monitor, "error", "the simulation is gone"), error: GONE });
          },
          () => {
            if (get().simulation === id && get().phase === "connecting") reconnect(id, attempt + 1);
          },
        );
      }, RECONNECT_DELAYS_MS[attempt]);
    };

    const connect = (id: string, attempt = 0) => {
      const s = openSocket(url(id));
      socket = s;
      s.onopen = () => {
        if (socket !== s) return;
        set({
          phase: "online",
          error: null,
          connection: get().connection + 1,
          monitor: connectionOpened(get().monitor),
        });
        resubscribe(true);
      };
      s.onmessage = (event) => {
        if (socket !== s || typeof event.data !== "string") return;
        const msg = parseServerMessage(event.data);
        if (!msg) return;
        set({ monitor: applyMessage(get().monitor, msg) });
        for (const listener of listeners) listener(msg);
      };
      s.onclose = () => {
        if (socket !== s) return;
        disconnect();
        const opened = get().phase === "online";
        set({
          phase: "connecting",
          error: "The connection to the simulation was lost; reconnecting…",
          monitor: opened ? logLocal(get().monitor, "error", "connection to the simulation lost") : get().monitor,
        });
        reconnect(id, opened ? 0 : attempt);
      };
      poll = setInterval(() => {
        api.getSimulation(id).then(
          (info) => {
            if (get().simulation === id && info.scan_count > 0) set({ lastScanMs: info.scan_ms.last });
          },
          () => undefined, // statistics are a nicety; the websocket reports real trouble
        );
      }, STATS_POLL_MS);
    };

    return {
      ...offline,
      views: {},
      watch: [],
      watchExpanded: [],
      instances: {},
      connection: 0,

      async compile(project, create = () => api.createSimulation(project)) {
        if (get().simulation) await get().goOffline();
        set({ phase: "compiling", project, error: null, compileDiagnostics: [] });
        try {
          const info = await create();
          if (get().phase !== "compiling") {
            void api.deleteSimulation(info.id).catch(() => undefined); // went offline meanwhile
            return;
          }
          set({
            phase: "connecting",
            simulation: info.id,
            monitor: emptyMonitor,
            instanceChoices: info.instances ?? {},
            io: info.io ?? [],
          });
          connect(info.id);
        } catch (err) {
          set({ ...offline, error: message(err), compileDiagnostics: compileDiagnosticsOf(err) });
        }
      },

      async attach(project, id) {
        if (get().simulation) return get().simulation === id;
        try {
          const info = (await api.listSimulations()).find((s) => s.id === id);
          if (!info || info.project !== project || get().simulation || get().phase !== "offline") return false;
          set({
            phase: "connecting",
            project,
            simulation: id,
            error: null,
            monitor: emptyMonitor,
            instanceChoices: info.instances ?? {},
            io: info.io ?? [],
          });
          connect(id);
          return true;
        } catch {
          return false;
        }
      },

      async goOffline() {
        const id = get().simulation;
        stopRetrying();
        disconnect();
        set({ ...offline });
        if (id) await api.deleteSimulation(id).catch(() => undefined);
      },

      // Commands go through the state's `send`, so a test may stand in for the socket there.
      run: () => void get().send({ type: "run" }),
      stop: () => void get().send({ type: "stop" }),
      singleCycle() {
        if (get().monitor.state === "running" && !get().send({ type: "stop" })) return;
        get().send({ type: "single_cycle" });
      },

      async reset(cold = false) {
        const id = get().simulation;
        if (!id) return;
        try {
          await api.resetSimulation(id, cold);
        } catch (err) {
          set({ monitor: logLocal(get().monitor, "error", `reset failed: ${message(err)}`) });
        }
      },

      write: (path, value) => void get().send({ type: "write", path, value }),
      force: (path, value) => void get().send({ type: "force", path, value }),
      unforce: (path) => void get().send({ type: "unforce", path }),
      unforceAll: () => void get().send({ type: "unforce_all" }),
      seek: (scan) => show(scan),
      goLive: () => show("live"),
      fork: () => void get().send({ type: "fork" }),

      prepare(path, value) {
        const next = { ...get().prepared };
        if (value === null) delete next[pathKey(path)];
        else next[pathKey(path)] = value;
        set({ prepared: next });
      },

      applyPrepared(action) {
        const prepared = Object.entries(get().prepared);
        if (!prepared.length) {
          set({ monitor: logLocal(get().monitor, "info", `no prepared values to ${action}`) });
          return;
        }
        for (const [path, value] of prepared) if (!get().send({ type: action, path, value })) return;
        set({ prepared: {} });
      },

      clearPrepared: () => set({ prepared: {} }),

      subscribe(view, subscription) {
        const next = { ...get().views };
        if (subscription) next[view] = subscription;
        else delete next[view];
        set({ views: next });
        resubscribe();
      },

      addWatch(path) {
        const text = path.trim();
        if (!text || get().watch.some((p) => pathKey(p) === pathKey(text))) return;
        set({ watch: [...get().watch, text] });
        resubscribe();
      },

      setInstance(pou, instance) {
        set({ instances: { ...get().instances, [pou]: pathKey(instance) } });
      },

      send,

      note(level, text) {
        set({ monitor: logLocal(get().monitor, level, text) });
      },

      listen(listener) {
        listeners.add(listener);
        return () => void listeners.delete(listener);
      },

      removeWatch(path) {
        const key = pathKey(path);
        set({
          watch: get().watch.filter((p) => pathKey(p) !== key),
          watchExpanded: get().watchExpanded.filter(
            (p) => p !== key && !p.startsWith(`${key}.`) && !p.startsWith(`${key}[`),
          ),
        });
        resubscribe();
      },

      toggleWatchExpanded(path) {
        const key = pathKey(path);
        const open = get().watchExpanded;
        set({ watchExpanded: open.includes(key) ? open.filter((p) => p !== key) : [...open, key] });
      },

      restoreWatch(watch, expanded) {
        set({ watch: [...watch], watchExpanded: expanded.map(pathKey) });
        resubscribe();
      },
    };
  });
}

export const onlineStore = createOnlineStore();

export function useOnline<T>(selector: (state: OnlineState) => T): T {
  return useStore(onlineStore, selector);
}
