// What the browser knows about a running simulation, folded from the server's monitor messages.
// Pure functions only (the store and the views call them), so the handling of every message kind
// is unit-tested without a socket. Paths are compared in upper case, as IEC names ignore case.
import type { DisplayType } from "../generated/monitor";
import type { PowerState, ServerMessage, SimulationState, Value, Where, WriteValue } from "./protocol";

export interface LogEntry {
  /** Increasing number, a stable React key. */
  seq: number;
  level: string;
  message: string;
  at?: Where | null;
  /** Scan counter when the entry arrived. */
  scan: number;
}

export interface MonitorState {
  scan: number;
  timeMs: number;
  state: SimulationState | null;
  /** Where a halted simulation stopped. */
  at: Where | null;
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
}

/** The online log keeps this many entries (older ones are dropped). */
export const LOG_LIMIT = 500;

export const emptyMonitor: MonitorState = {
  scan: 0,
  timeMs: 0,
  state: null,
  at: null,
  values: {},
  types: {},
  forced: new Set(),
  injected: {},
  power: {},
  log: [],
};

/**
 * A path as the server names it in its messages: upper case, and a global without the `GVL.`
 * prefix a client may write (the server reports `GVL.Start` as `START`), so values are found.
 */
export const pathKey = (path: string): string =>
  path
    .trim()
    .toUpperCase()
    .replace(/^GVL\s*\.\s*/, "");

function appendLog(state: MonitorState, entry: Omit<LogEntry, "seq" | "scan">, scan?: number | null): MonitorState {
  const last = state.log[state.log.length - 1];
  const next = [...state.log, { ...entry, seq: (last?.seq ?? 0) + 1, scan: scan ?? state.scan }];
  return { ...state, log: next.length > LOG_LIMIT ? next.slice(next.length - LOG_LIMIT) : next };
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
      };
    }
    case "status":
      return { ...state, state: message.state, at: message.state === "halted" ? (message.at ?? null) : null };
    case "log":
      return appendLog(state, { level: message.level, message: message.message, at: message.at ?? null }, message.scan);
    case "error":
      return appendLog(state, { level: "error", message: `${message.code}: ${message.message}` });
    case "trace_data":
      return state; // the trace panel keeps its own samples (src/trace/store.ts)
  }
}

/** A local entry in the online log (connection lost, a refused compile), shown like the server's. */
export function logLocal(state: MonitorState, level: "info" | "warning" | "error", message: string): MonitorState {
  return appendLog(state, { level, message });
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

/**
 * Text of a value for labels, the watch list and inline values, as IEC writes it: TRUE/FALSE, TIME
 * and dates as literals (the server sends ms), an enumeration's value by name. `type` is the
 * server's DisplayType or a declared type name; without one a number shows as it is.
 */
export function formatValue(value: Value | undefined, type?: DisplayType | string): string {
  if (value === undefined) return "…";
  if (value === null) return "—";
  if (typeof value === "boolean") return value ? "TRUE" : "FALSE";
  if (typeof value === "object") return JSON.stringify(value);
  if (typeof value !== "number" || type === undefined) return String(value);
  const name = (typeof type === "string" ? type : type.name).toUpperCase();
  const named = typeof type === "string" ? undefined : type.names?.[String(value)];
  if (named !== undefined) return named;
  return TIME_LITERALS[name]?.(value) ?? String(value);
}

const pad = (n: number, width = 2) => String(n).padStart(width, "0");

/** `T#1h2m3s500ms`: the non-zero units, largest first (`T#0ms` for zero; a minus sign after `T#`). */
export function timeLiteral(ms: number): string {
  const units: [string, number][] = [
    ["d", 86_400_000],
    ["h", 3_600_000],
    ["m", 60_000],
    ["s", 1000],
    ["ms", 1],
  ];
  let rest = Math.abs(ms);
  let text = "";
  for (const [unit, size] of units) {
    const count = unit === "ms" ? Math.round(rest * 1000) / 1000 : Math.floor(rest / size);
    if (count) text += `${count}${unit}`;
    rest -= unit === "ms" ? rest : count * size;
  }
  return `T#${ms < 0 ? "-" : ""}${text || "0ms"}`;
}

/** Time of day after midnight, with milliseconds when there are any. */
function clock(ms: number): string {
  const day = new Date(ms);
  const millis = day.getUTCMilliseconds();
  return `${pad(day.getUTCHours())}:${pad(day.getUTCMinutes())}:${pad(day.getUTCSeconds())}${millis ? `.${pad(millis, 3)}` : ""}`;
}

const dateOf = (ms: number) => {
  const day = new Date(ms);
  return `${day.getUTCFullYear()}-${pad(day.getUTCMonth() + 1)}-${pad(day.getUTCDate())}`;
};

/** TIME and the date types, from the server's ms (dates since 1970-01-01 UTC), as IEC literals. */
const TIME_LITERALS: Record<string, (ms: number) => string> = {
  TIME: timeLiteral,
  DATE: (ms) => `D#${dateOf(ms)}`,
  TIME_OF_DAY: (ms) => `TOD#${clock(ms)}`,
  TOD: (ms) => `TOD#${clock(ms)}`,
  DATE_AND_TIME: (ms) => `DT#${dateOf(ms)}-${clock(ms)}`,
  DT: (ms) => `DT#${dateOf(ms)}-${clock(ms)}`,
};

/**
 * The JSON value to send for text the user typed: TRUE/FALSE become booleans and plain numbers
 * numbers; anything else goes as text, which the server reads as an IEC literal (T#1s, 16#FF).
 */
export function parseValue(text: string): WriteValue {
  const t = text.trim();
  if (/^true$/i.test(t)) return true;
  if (/^false$/i.test(t)) return false;
  if (/^[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?$/.test(t)) return Number(t);
  return t;
}
