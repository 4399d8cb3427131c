// The trace panel (zustand): the variables to trace (at most 20), the trigger, the buffer size,
// and the trace being recorded. The server samples every scan and streams `trace_data` chunks
// (backend/ladderlab/simulation/trace.py); this store appends them to its ring buffer, which keeps the
// newest `capacity` samples. The ring is mutated in place: `version` counts the changes, so views
// re-render on it. Sending and hearing the monitor socket are injected so tests drive the store.
import { useStore } from "zustand";
import { createStore, type StoreApi } from "zustand/vanilla";
import type { DisplayType, TraceStart, TraceTriggered } from "../generated/monitor";
import { pathKey } from "../online/monitor";
import { onlineStore } from "../online/store";
import type { ClientMessage, ServerMessage } from "../online/protocol";
import type { Kind } from "./csv";
import { MAX_SAMPLES, SampleRing, sampleNumber } from "./ring";
import { noTrigger, triggerOf, type TriggerForm } from "./trigger";

/** The most variables one trace records (the protocol's MAX_TRACE_PATHS). */
export const MAX_PATHS = 20;
export const DEFAULT_CAPACITY = 1000;

/** starting: trace_start sent, no answer yet; waiting: for the trigger; done: stopped or full. */
export type TracePhase = "idle" | "starting" | "waiting" | "recording" | "done";

export interface TraceStateData {
  /** The variables to trace, as typed (no two with the same upper-case path). */
  paths: string[];
  trigger: TriggerForm;
  /** Samples the ring buffer keeps (1..10,000). */
  capacity: number;
  /** End the trace when `capacity` samples are recorded; otherwise record until Stop, keeping the newest. */
  stopWhenFull: boolean;
  /** Draw each BOOL as its own 0/1 lane. */
  laneView: boolean;
  phase: TracePhase;
  /** Id of the trace in progress (chunks of earlier traces are ignored). */
  id: number;
  /** What the server records, as it names the paths (set by the first chunk). */
  recorded: string[];
  kinds: (Kind | null)[];
  /** How to show each recorded path's values (an enumeration's names), from the trace's first chunk. */
  types: (DisplayType | null)[];
  ring: SampleRing | null;
  /** The scan whose trigger started the recording. */
  triggered: TraceTriggered | null;
  /** Virtual time of the first sample (the trigger's scan): time 0 of the chart and the table. */
  origin: number | null;
  /** Samples the server dropped because this client did not keep up. */
  lost: number;
  error: string | null;
  /** Increases with every change of the ring. */
  version: number;
}

export interface TraceActions {
  /** Adds a path; returns why it was refused (the 21st, a repeat), or null. */
  addPath(path: string): string | null;
  removePath(path: string): void;
  setTrigger(form: Partial<TriggerForm>): void;
  setCapacity(capacity: number): void;
  setStopWhenFull(stop: boolean): void;
  setLaneView(lanes: boolean): void;
  /** Sends `trace_start` with the paths, trigger and buffer size; the old samples are cleared. */
  start(): void;
  stop(): void;
  /** A server message from the monitor socket. */
  receive(msg: ServerMessage): void;
  /** The simulation went away or was replaced: a trace in progress is over (its samples stay). */
  disconnected(): void;
}

export type TraceState = TraceStateData & TraceActions;

export interface TraceDeps {
  /** Sends a monitor message; false when not connected. */
  send(msg: ClientMessage): boolean;
}

export const initialTrace: TraceStateData = {
  paths: [],
  trigger: noTrigger,
  capacity: DEFAULT_CAPACITY,
  stopWhenFull: true,
  laneView: true,
  phase: "idle",
  id: 0,
  recorded: [],
  kinds: [],
  types: [],
  ring: null,
  triggered: null,
  origin: null,
  lost: 0,
  error: null,
  version: 0,
};

const kindOf = (value: unknown): Kind | null =>
  typeof value === "boolean" ? "bool" : value === null || value === undefined ? null : "number";

const active = (phase: TracePhase): boolean => phase === "starting" || phase === "waiting" || phase === "recording";

export function createTraceStore(deps: TraceDeps): StoreApi<TraceState> {
  return createStore<TraceState>()((set, get) => ({
    ...initialTrace,

    addPath(path) {
      const text = path.trim();
      if (!text) return "type a variable path, e.g. MAIN.Motor";
      const { paths } = get();
      if (paths.some((p) => pathKey(p) === pathKey(text))) return `${text} is traced already`;
      if (paths.length >= MAX_PATHS)
        return `a trace records at most ${MAX_PATHS} variables: remove one before adding ${text}`;
      set({ paths: [...paths, text], error: null });
      return null;
    },

    removePath: (path) => set({ paths: get().paths.filter((p) => pathKey(p) !== pathKey(path)) }),
    setTrigger: (form) => set({ trigger: { ...get().trigger, ...form } }),
    setCapacity: (capacity) => set({ capacity: Math.min(MAX_SAMPLES, Math.max(1, Math.round(capacity) || 1)) }),
    setStopWhenFull: (stopWhenFull) => set({ stopWhenFull }),
    setLaneView: (laneView) => set({ laneView }),

    start() {
      const { paths, capacity, stopWhenFull } = get();
      if (!paths.length) return set({ error: "add a variable to trace first" });
      const trigger = triggerOf(get().trigger);
      if (!trigger.ok) return set({ error: trigger.error });
      const id = get().id + 1;
      const sent = deps.send({
        type: "trace_start",
        id,
        paths: paths as TraceStart["paths"],
        samples: stopWhenFull ? capacity : null,
        trigger: trigger.trigger,
      });
      if (!sent) return set({ error: "go online (Compile & simulate) to record a trace" });
      set({
        phase: "starting",
        id,
        recorded: [],
        kinds: [],
        types: [],
        ring: null,
        triggered: null,
        origin: null,
        lost: 0,
        error: null,
        version: get().version + 1,
      });
    },

    stop() {
      if (!active(get().phase)) return;
      if (!deps.send({ type: "trace_stop" })) set({ phase: "done" });
    },

    receive(msg) {
      const state = get();
      if (msg.type === "error") {
        // The request in flight is the trace_start: a refusal of it is shown in the panel.
        if (state.phase === "starting") set({ phase: "idle", error: msg.message });
        return;
      }
      if (msg.type !== "trace_data" || msg.id !== state.id || !active(state.phase)) return;
      const recorded = state.ring ? state.recorded : Object.keys(msg.values);
      const ring = state.ring ?? new SampleRing(state.capacity, recorded.length);
      const columns = recorded.map((p) => msg.values[p] ?? []);
      const kinds = recorded.map((_, c) => state.kinds[c] ?? kindOf(columns[c]!.find((v) => v !== null)));
      const types = recorded.map((p, c) => state.types[c] ?? msg.types?.[p] ?? null);
      for (let i = 0; i < msg.scans.length; i++)
        ring.push(
          msg.scans[i]!,
          msg.time_ms[i]!,
          columns.map((column) => sampleNumber(column[i])),
        );
      set({
        phase: msg.state,
        recorded,
        kinds,
        types,
        ring,
        triggered: msg.triggered ?? state.triggered,
        origin: state.origin ?? msg.time_ms[0] ?? null,
        lost: state.lost + (msg.lost ?? 0),
        version: state.version + 1,
      });
    },

    disconnected() {
      if (active(get().phase))
        set({
          phase: get().phase === "starting" ? "idle" : "done",
          error: "the simulation went offline: the trace ended",
        });
    },
  }));
}

/** Connects a trace store to the online store: messages in, sending out, the end of a simulation. */
export interface OnlineLike {
  getState(): {
    send(msg: ClientMessage): boolean;
    listen(listener: (msg: ServerMessage) => void): () => void;
    simulation: string | null;
  };
  subscribe(listener: (state: Connection, previous: Connection) => void): () => void;
}

/** Which simulation, and which connection to it: the server keeps a trace per connection. */
interface Connection {
  simulation: string | null;
  connection: number;
}

export function traceStoreFor(online: OnlineLike): StoreApi<TraceState> {
  const store = createTraceStore({ send: (msg) => online.getState().send(msg) });
  online.getState().listen((msg) => store.getState().receive(msg));
  online.subscribe((state, previous) => {
    if (state.simulation !== previous.simulation || state.connection !== previous.connection)
      store.getState().disconnected();
  });
  return store;
}

export const traceStore = traceStoreFor(onlineStore);

export function useTrace<T>(selector: (state: TraceState) => T): T {
  return useStore(traceStore, selector);
}
