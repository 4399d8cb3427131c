// What the browser knows about a running simulation, folded from the server's monitor messages.
// Pure functions only (the store and the views call them), so the handling of every message kind
// is unit-tested without a socket. Paths are compared in upper case, as IEC names ignore case.
import type { SymbolInfo } from "../generated/api";
import type { CallFrame, DisplayType, HistoryRange, Log } from "../generated/monitor";
import type { PowerState, ServerMessage, SimulationState, Value, Where } from "./protocol";

/** What a log entry is about (ON-15), as the server's `log` messages say. */
export type LogKind = NonNullable<Log["kind"]>;
export const LOG_KINDS: readonly LogKind[] = [
  "state",
  "write",
  "force",
  "release",
  "breakpoint",
  "watchdog",
  "fault",
  "system",
];

export interface LogEntry {
  /** Increasing number, a stable React key. */
  seq: number;
  kind: LogKind;
  level: Log["level"];
  message: string;
  at?: Where | null;
  /** The scan it belongs to (the server's; else the scan counter when it arrived). */
  scan: number;
  /** Virtual time of that scan in ms (the server's; else the time shown when it arrived). */
  timeMs: number;
  /**
   * "server": the simulation's own log, which the server sends again (history first) on every
   * connection; "client": this browser's notes (a refused request, a lost connection), kept.
   */
  origin: "server" | "client";
}

export interface MonitorState {
  scan: number;
  timeMs: number;
  state: SimulationState | null;
  /** Where a halted simulation stopped. */
  at: Where | null;
  /** The POU calls the halted scan stands in, outermost first, with a FUNCTION's or METHOD's own variables. */
  stack: readonly CallFrame[];
  /** Latest value of every subscribed path, keyed by the upper-case path. */
  values: Readonly<Record<string, Value>>;
  /** How to show each subscribed path's value (from the snapshot after a subscribe), same keys. */
  types: Readonly<Record<string, DisplayType>>;
  /** Upper-case paths forced now. */
  forced: ReadonlySet<string>;
  /** Upper-case paths with an injected fault: its mode (stuck_true, open, noisy...). */
  injected: Readonly<Record<string, string>>;
  /** Engine power by "<instance>/<element id>"; null = not executed in the last scan. */
  power: Readonly<Record<string, PowerState>>;
  log: readonly LogEntry[];
  /** The scan history's range and the past scan shown instead of the live one (`viewing`); null: none kept. */
  history: HistoryRange | null;
}

/** Where the editors mark a halt (the network or line): in a step through a past scan (history), its point (null
 * once the scan ended); else where the live scan is halted. */
export function haltedAt(monitor: Pick<MonitorState, "state" | "at" | "history">): Where | null {
  const stepping = monitor.history?.stepping;
  if (stepping) return stepping.at ?? null;
  return monitor.state === "halted" ? monitor.at : null;
}

const NO_CALLS: readonly CallFrame[] = [];

/** The POU calls the editors show: those of the point a step through a past scan (history) reached, else those of
 * the halted live scan; none otherwise (the same empty list each time, so a selector of it stays stable). */
export function haltedStack(monitor: Pick<MonitorState, "state" | "stack" | "history">): readonly CallFrame[] {
  const stepping = monitor.history?.stepping;
  if (stepping) return stepping.stack ?? NO_CALLS;
  return monitor.state === "halted" ? monitor.stack : NO_CALLS;
}

/** The call of POU `pou` (a method as `FB.M`, any case) the halted scan stands in, if any: its own variables'
 * values. A POU is called at most once in a stack (no recursion, POU-02). */
export function haltedCall(monitor: Pick<MonitorState, "state" | "stack" | "history">, pou: string): CallFrame | null {
  return haltedStack(monitor).find((f) => f.at.pou.toUpperCase() === pou.toUpperCase()) ?? null;
}

/** The online log keeps this many entries (older ones are dropped). */
export const LOG_LIMIT = 5000;

export const emptyMonitor: MonitorState = {
  scan: 0,
  timeMs: 0,
  state: null,
  at: null,
  stack: [],
  values: {},
  types: {},
  forced: new Set(),
  injected: {},
  power: {},
  log: [],
  history: null,
};

/**
 * A path as the server names it in its messages: upper case, and a global without the `GVL.`
 * prefix a client may write (the server reports `GVL.Start` as `START`), nor the name of its global
 * variable list (`GVL_IO.bStart` is `BSTART`), so values are found; a name several lists declare keeps its list
 * (`GVL_A.x` is `GVL_A.X`: the name alone is no variable then).
 */
export function pathKey(path: string): string {
  const upper = path.trim().toUpperCase();
  const qualified = /^([A-Z_][A-Z0-9_]*)\s*\.\s*(?=([A-Z_][A-Z0-9_]*))/.exec(upper);
  if (qualified && lists.has(qualified[1]!) && shared.has(qualified[2]!))
    return `${qualified[1]}.${upper.slice(qualified[0].length)}`; // (a list called GVL too)
  const key = upper.replace(/^GVL\s*\.\s*/, "");
  const list = /^([A-Z_][A-Z0-9_]*)\s*\.\s*/.exec(key);
  return list && lists.has(list[1]!) ? key.slice(list[0].length) : key;
}

let lists = new Set<string>();
let shared = new Set<string>();

/** The names of the open project's global variable lists and the names several of them declare, for `pathKey`
 * (the shell sets them as they change). */
export function setGlobalListNames(names: readonly string[], sharedNames: readonly string[] = []): void {
  lists = new Set(names.map((name) => name.toUpperCase()));
  shared = new Set(sharedNames.map((name) => name.toUpperCase()));
}

function appendLog(
  state: MonitorState,
  entry: Omit<LogEntry, "seq" | "scan" | "timeMs">,
  scan?: number | null,
  timeMs?: number | null,
): MonitorState {
  const last = state.log[state.log.length - 1];
  const next = [
    ...state.log,
    { ...entry, seq: (last?.seq ?? 0) + 1, scan: scan ?? state.scan, timeMs: timeMs ?? state.timeMs },
  ];
  return { ...state, log: next.length > LOG_LIMIT ? next.slice(next.length - LOG_LIMIT) : next };
}

/**
 * A new connection to the simulation: the server sends its whole log again (oldest first) before
 * live entries, so the entries of the last connection make way for it; this browser's own stay.
 */
export function connectionOpened(state: MonitorState): MonitorState {
  return { ...state, log: state.log.filter((e) => e.origin === "client") };
}

/** The state after one server message (values and power merge, `forced` replaces, status and log append). */
export function applyMessage(state: MonitorState, message: ServerMessage): MonitorState {
  switch (message.type) {
    case "values": {
      const values = { ...state.values };
      for (const [path, value] of Object.entries(message.changed ?? {})) values[pathKey(path)] = value;
      const types = { ...state.types };
      for (const [path, type] of Object.entries(message.types ?? {})) types[pathKey(path)] = type;
      return {
        ...state,
        scan: message.scan,
        timeMs: message.time_ms,
        values,
        types,
        forced: new Set(message.forced.map(pathKey)),
        injected: Object.fromEntries(Object.entries(message.injected ?? {}).map(([p, mode]) => [pathKey(p), mode])),
        power: { ...state.power, ...message.power },
        history: message.history ?? null,
      };
    }
    case "status": {
      const halted = message.state === "halted";
      return {
        ...state,
        state: message.state,
        at: halted ? (message.at ?? null) : null,
        stack: halted ? (message.stack ?? []) : [],
      };
    }
    case "log":
      return appendLog(
        state,
        {
          kind: message.kind ?? "system",
          level: message.level,
          message: message.message,
          at: message.at ?? null,
          origin: "server",
        },
        message.scan,
        message.time_ms,
      );
    case "error":
      return appendLog(state, {
        kind: "system",
        level: "error",
        message: `${message.code}: ${message.message}`,
        origin: "client",
      });
    case "trace_data":
      return state; // the trace panel keeps its own samples (src/trace/store.ts)
  }
}

/** A local entry in the online log (connection lost, a refused compile), shown like the server's. */
export function logLocal(state: MonitorState, level: LogEntry["level"], message: string): MonitorState {
  return appendLog(state, { kind: "system", level, message, origin: "client" });
}

/**
 * Whether a subscription change can keep the old values: a new subscription's first message is a
 * full snapshot, but values of paths no longer subscribed must not linger as if they were live.
 */
export function keepSubscribed(
  state: MonitorState,
  paths: readonly string[],
  powerKeys: readonly string[],
): MonitorState {
  const wanted = new Set(paths.map(pathKey));
  const ids = new Set(powerKeys);
  return {
    ...state,
    values: Object.fromEntries(Object.entries(state.values).filter(([p]) => wanted.has(p))),
    power: Object.fromEntries(Object.entries(state.power).filter(([id]) => ids.has(id))),
  };
}

/** The key of an element's power in `values.power`. */
export const powerKey = (instance: string, id: string): string => `${instance}/${id}`;

/** A variable operand: names with member/index access (`T1.Q`, `A[3]`); literals and addresses are not. */
const VARIABLE = /^[A-Za-z_][A-Za-z0-9_]*(\.[A-Za-z_][A-Za-z0-9_]*|\[\s*\d+\s*\])*(\.%[XBWDL]\d+|\.\d+)?$/i;
const LITERALS = new Set(["TRUE", "FALSE"]);

/**
 * The canonical simulation path of an operand in POU instance `instance`, as the server names it
 * in its messages: the instance's own variable (`MAIN.START`) or a global (`ALARM`), a bit or part of one
 * too (`w.3` and `w.%X3` are `MAIN.W.%X3`, issue 25); null for literals and addresses.
 */
export function operandPath(operand: string, instance: string, symbols: readonly SymbolInfo[]): string | null {
  const text = operand.trim();
  if (!VARIABLE.test(text) || LITERALS.has(text.toUpperCase())) return null;
  const head = text.split(/[.[]/, 1)[0]!.toUpperCase();
  const symbol = symbols.find((s) => s.name.toUpperCase() === head);
  const global =
    symbol?.var_class === "VAR_GLOBAL" || symbol?.var_class === "VAR_EXTERNAL" || (!symbol && lists.has(head));
  const path = text.replace(/\.(\d+)$/, ".%X$1"); // the server names a bit by its long form
  return pathKey(global ? path : `${instance}.${path}`);
}
