// How values read: the IEC text of a monitored value (TRUE/FALSE, T#1s, D#2024-05-01, enumerations
// by name, REALs in their shortest decimal form), the virtual clock, and the value a user typed.
// Pure functions, shared by every view that shows values (LD, FBD, ST, watch list, log, trace).
import type { DisplayType } from "../generated/monitor";
import type { Value, WriteValue } from "./protocol";

/**
 * Text of a value for labels, the watch list and inline values, as IEC writes it: TRUE/FALSE, TIME
 * and dates as literals (the server sends ms), an enumeration's value by name. `type` is the
 * server's DisplayType or a declared type name; without one a number shows as it is.
 */
export function formatValue(value: Value | undefined, type?: DisplayType | string): string {
  if (value === undefined) return "…";
  if (value === null) return "—";
  if (typeof value === "boolean") return value ? "TRUE" : "FALSE";
  const name = type === undefined ? undefined : (typeof type === "string" ? type : type.name).toUpperCase();
  if (typeof value === "object") return compositeText(value, name);
  if (typeof value !== "number" || name === undefined) return String(value);
  const named = typeof type === "string" ? undefined : type?.names?.[String(value)];
  if (named !== undefined) return named;
  if (name === "REAL" || name === "LREAL") return realText(value, name === "REAL");
  return TIME_LITERALS[name]?.(value) ?? String(value);
}

/**
 * A REAL or LREAL as the engine's TO_STRING writes it (iec/value_text.py `format_real`), as an IEC
 * real literal (`50.0`, `0.1`, `1.0E20`, `1.5E-7`): an LREAL in the fewest digits that read back as
 * the same double; a REAL rounded to 6 significant digits (7, 8 or 9 when 6 do not read back as the
 * same single: the server sends the single widened to a double, 50.4 arrives as 50.400001525878906
 * and shows as 50.4), trailing zeros dropped. The exponent form starts where Python's does (below
 * 1e-4; from 10^16, for a REAL from 10^p with p the digits rounded to).
 */
export function realText(value: number, single: boolean): string {
  if (Number.isNaN(value)) return "NAN";
  if (!Number.isFinite(value)) return value > 0 ? "INF" : "-INF";
  const x = single ? Math.fround(value) : value;
  let [mantissa, exponent] = x.toExponential().split("e") as [string, string];
  let limit = 16;
  if (single) {
    limit = [6, 7, 8, 9].find((p) => Math.fround(Number(x.toExponential(p - 1))) === x) ?? 9;
    [mantissa, exponent] = x.toExponential(limit - 1).split("e") as [string, string];
  }
  const exp = Number(exponent);
  const sign = mantissa.startsWith("-") ? "-" : "";
  const digits = mantissa.replace("-", "").replace(".", "").replace(/0+$/, "") || "0";
  if (exp < -4 || exp >= limit) return `${sign}${digits[0]}.${digits.slice(1) || "0"}E${exp}`;
  if (exp < 0) return `${sign}0.${"0".repeat(-exp - 1)}${digits}`;
  return `${sign}${digits.slice(0, exp + 1).padEnd(exp + 1, "0")}.${digits.slice(exp + 1) || "0"}`;
}

/** An array, structure or FB instance in one line (its members show in the watch list's tree). */
function compositeText(value: object, type: string | undefined): string {
  if (Array.isArray(value)) return `${type && type !== "ARRAY" ? type : "ARRAY"} (${value.length} elements)`;
  return type ?? "STRUCT";
}

const pad = (n: number, width = 2) => String(n).padStart(width, "0");

/** `T#1h2m3s500ms`: the non-zero units, largest first (`T#0s` for zero, as the engine's TO_STRING; a minus sign after `T#`). */
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
  return `T#${ms < 0 ? "-" : ""}${text || "0s"}`;
}

/** Time of day after midnight, with the fraction of a second when there is one (`12:30:15.5`, as the engine). */
function clock(ms: number): string {
  const day = new Date(ms);
  const millis = day.getUTCMilliseconds();
  return `${pad(day.getUTCHours())}:${pad(day.getUTCMinutes())}:${pad(day.getUTCSeconds())}${millis ? `.${pad(millis, 3).replace(/0+$/, "")}` : ""}`;
}

const dateOf = (ms: number) => {
  const day = new Date(ms);
  return `${day.getUTCFullYear()}-${pad(day.getUTCMonth() + 1)}-${pad(day.getUTCDate())}`;
};

/** `LTIME#1h2m3s4ms5us6ns`: an LTIME (the server sends ns) with its non-zero units, largest first. */
function ltimeLiteral(ns: number): string {
  const units: [string, number][] = [
    ["d", 86_400e9],
    ["h", 3_600e9],
    ["m", 60e9],
    ["s", 1e9],
    ["ms", 1e6],
    ["us", 1e3],
    ["ns", 1],
  ];
  let rest = Math.abs(ns);
  let text = "";
  for (const [unit, size] of units) {
    const count = Math.floor(rest / size);
    if (count) text += `${count}${unit}`;
    rest -= count * size;
  }
  return `LTIME#${ns < 0 ? "-" : ""}${text || "0s"}`;
}

/** Nanoseconds since midnight as `12:30:00` or `12:30:00.00000025` (the fraction only when there is one). */
function clockNs(ns: number): string {
  const inDay = ns % 86_400e9;
  const nanos = inDay % 1e9;
  const fraction = nanos ? `.${pad(nanos, 9).replace(/0+$/, "")}` : "";
  return `${clock(Math.floor(inDay / 1e9) * 1000)}${fraction}`;
}

/**
 * TIME and the date types, from the server's ms (dates since 1970-01-01 UTC), and their IEC 3rd edition long
 * forms, from ns, as IEC literals. A long value beyond 2^53 ns (an LTIME over 104 days, any LDATE_AND_TIME) reaches
 * the browser as the nearest double: shown to about a microsecond.
 */
const TIME_LITERALS: Record<string, (value: number) => string> = {
  TIME: timeLiteral,
  DATE: (ms) => `D#${dateOf(ms)}`,
  TIME_OF_DAY: (ms) => `TOD#${clock(ms)}`,
  TOD: (ms) => `TOD#${clock(ms)}`,
  DATE_AND_TIME: (ms) => `DT#${dateOf(ms)}-${clock(ms)}`,
  DT: (ms) => `DT#${dateOf(ms)}-${clock(ms)}`,
  LTIME: ltimeLiteral,
  LDATE: (ns) => `LDATE#${dateOf(ns / 1e6)}`,
  LTIME_OF_DAY: (ns) => `LTOD#${clockNs(ns)}`,
  LTOD: (ns) => `LTOD#${clockNs(ns)}`,
  LDATE_AND_TIME: (ns) => `LDT#${dateOf(ns / 1e6)}-${clockNs(ns)}`,
  LDT: (ns) => `LDT#${dateOf(ns / 1e6)}-${clockNs(ns)}`,
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

/** Virtual time as h:mm:ss.mmm (the simulation's clock starts at 0). */
export function formatClock(ms: number): string {
  const total = Math.max(0, Math.round(ms));
  const h = Math.floor(total / 3_600_000);
  const m = Math.floor(total / 60_000) % 60;
  const s = Math.floor(total / 1000) % 60;
  const rest = total % 1000;
  return `${h}:${String(m).padStart(2, "0")}:${String(s).padStart(2, "0")}.${String(rest).padStart(3, "0")}`;
}
