// One value as every online view shows it (LD operands and box pins, FBD nodes and pins, ST inline
// values, the watch list, the Variables view): its IEC text, whether it is a BOOL (coloured as
// such), whether it is forced, and the value prepared for it (CODESYS: `<TRUE>` until F7 / Ctrl+F7).
import type { DisplayType } from "../generated/monitor";
import { pathKey, type MonitorState } from "./monitor";
import type { Value, WriteValue } from "./protocol";
import { formatValue } from "./values";

export interface ValueShown {
  text: string;
  /** TRUE/FALSE for a BOOL (drawn blue/black like energised/not), null for other types. */
  bool: boolean | null;
  forced: boolean;
  /** The prepared value's text, or null when none is prepared. */
  prepared: string | null;
}

export type Prepared = Readonly<Record<string, WriteValue>>;

/** How a value reads: its text (by `type` when known), BOOL or not. */
export function shownOf(value: Value, type?: DisplayType | string): Pick<ValueShown, "text" | "bool"> {
  return { text: formatValue(value, type), bool: typeof value === "boolean" ? value : null };
}

/** A prepared value as text: BOOLs and numbers like values of `type`, text as the user typed it. */
export function preparedText(value: WriteValue | undefined, type?: DisplayType | string): string | null {
  if (value === undefined) return null;
  return typeof value === "string" ? value : formatValue(value, type);
}

/** What a subscribed variable shows now; null before its first value arrives. */
export function shownPath(monitor: MonitorState, path: string, prepared: Prepared = {}): ValueShown | null {
  const key = pathKey(path);
  const value = monitor.values[key];
  if (value === undefined) return null;
  const type = monitor.types[key];
  return { ...shownOf(value, type), forced: monitor.forced.has(key), prepared: preparedText(prepared[key], type) };
}

/** The type a literal operand has by its IEC prefix (T#5s is a TIME), else undefined. */
export function literalType(text: string): string | undefined {
  const prefix = /^\s*([A-Za-z_]+)#/.exec(text)?.[1]?.toUpperCase();
  if (!prefix) return undefined;
  const typed: Record<string, string> = {
    T: "TIME",
    TIME: "TIME",
    D: "DATE",
    DATE: "DATE",
    TOD: "TIME_OF_DAY",
    TIME_OF_DAY: "TIME_OF_DAY",
    DT: "DATE_AND_TIME",
    DATE_AND_TIME: "DATE_AND_TIME",
  };
  return typed[prefix] ?? (/^(L?REAL|U?[SDL]?INT|BYTE|L?D?WORD|BOOL)$/.test(prefix) ? prefix : undefined);
}
