// Operator panels (HMI): the pure part. Panels are the project's `panels` (hmi/<name>.json, see
// backend/ladderlab/model/hmi.py and docs/hmi.md); this module makes widgets for the palette, edits
// panels (move, resize, align, distribute, delete, duplicate: every edit returns a new panel, so the
// editor's undo history is a list of values) and turns variable values into what widgets show.
import type { DisplayType } from "../generated/monitor";
import type { IndicatorState as State, Motion, Panel } from "../generated/api";
import { pathKey } from "../online/monitor";
import { formatValue, parseValue } from "../online/values";
import type { Value, WriteValue } from "../online/protocol";

export type Widget = NonNullable<Panel["widgets"]>[number];
export type WidgetType = Widget["type"];
export type WidgetOf<T extends WidgetType> = Extract<Widget, { type: T }>;
export type SymbolShape = WidgetOf<"symbol">["shape"];

/** The widgets that send input events (the others only show values). */
export const INPUT_WIDGETS: readonly WidgetType[] = [
  "push_button",
  "toggle_switch",
  "selector_switch",
  "emergency_stop",
  "numeric_input",
  "slider",
];

export const SYMBOL_SHAPES: readonly SymbolShape[] = [
  "motor",
  "pump",
  "fan",
  "valve",
  "heater",
  "conveyor",
  "cylinder",
  "box",
  "siren",
  "person",
  "car",
  "door",
  "wall",
];

interface PaletteEntry {
  type: WidgetType;
  title: string;
  w: number;
  h: number;
  /** The type's own fields of a new widget (besides id, place and size). */
  fields: Record<string, unknown>;
}

/** What the editor's palette offers, in its order, with each new widget's size and settings. */
export const PALETTE: readonly PaletteEntry[] = [
  { type: "push_button", title: "Push button", w: 100, h: 40, fields: { bind: "" } },
  { type: "toggle_switch", title: "Toggle switch", w: 100, h: 40, fields: { bind: "" } },
  {
    type: "selector_switch",
    title: "Selector switch",
    w: 100,
    h: 80,
    fields: {
      bind: "",
      positions: [
        { label: "0", value: false },
        { label: "1", value: true },
      ],
    },
  },
  { type: "emergency_stop", title: "Emergency stop", w: 80, h: 80, fields: { bind: "" } },
  { type: "lamp", title: "Lamp", w: 30, h: 30, fields: { bind: "" } },
  {
    type: "multistate",
    title: "Multistate indicator",
    w: 140,
    h: 30,
    fields: { bind: "", states: [{ value: 0, text: "off", color: "#5f6368" }] },
  },
  { type: "numeric_display", title: "Numeric display", w: 120, h: 30, fields: { bind: "" } },
  { type: "numeric_input", title: "Numeric input", w: 120, h: 30, fields: { bind: "" } },
  { type: "slider", title: "Slider", w: 160, h: 40, fields: { bind: "" } },
  { type: "bar", title: "Bar / tank", w: 60, h: 160, fields: { bind: "" } },
  { type: "seven_segment", title: "7-segment display", w: 120, h: 50, fields: { bind: "" } },
  { type: "label", title: "Text", w: 160, h: 30, fields: { text: "Text" } },
  { type: "trend", title: "Trend", w: 220, h: 120, fields: { paths: [""] } },
  { type: "symbol", title: "Symbol", w: 60, h: 60, fields: { shape: "motor", bind: "" } },
];

export const paletteEntry = (type: WidgetType): PaletteEntry => PALETTE.find((p) => p.type === type)!;

export const DEFAULT_GRID = 10;

/** A new, empty panel. */
export const newPanel = (name: string): Panel => ({
  name,
  title: name,
  width: 800,
  height: 480,
  grid: 10,
  widgets: [],
});

export const widgetsOf = (panel: Panel): Widget[] => panel.widgets ?? [];

/** `base` followed by the smallest number that makes an id no widget of the panel has. */
export function freeId(panel: Panel, base: string): string {
  const taken = new Set(widgetsOf(panel).map((w) => w.id));
  for (let n = 1; ; n++) if (!taken.has(`${base}${n}`)) return `${base}${n}`;
}

/** `value` to the grid (no grid: as it is), at least 0. */
export const snap = (value: number, grid: number | undefined): number =>
  Math.max(0, grid ? Math.round(value / grid) * grid : Math.round(value));

/** A new widget of `type` at (x, y), snapped, held inside the panel. */
export function makeWidget(panel: Panel, type: WidgetType, x: number, y: number): Widget {
  const entry = paletteEntry(type);
  const grid = panel.grid ?? DEFAULT_GRID;
  const w = Math.min(entry.w, panel.width ?? 800);
  const h = Math.min(entry.h, panel.height ?? 480);
  return {
    type,
    id: freeId(
      panel,
      type.replace(/_(\w)/g, (_, c: string) => c.toUpperCase()),
    ),
    x: Math.min(snap(x, grid), Math.max(0, (panel.width ?? 800) - w)),
    y: Math.min(snap(y, grid), Math.max(0, (panel.height ?? 480) - h)),
    w,
    h,
    ...structuredClone(entry.fields),
  } as Widget;
}

/** The first place (left to right, top to bottom, on the grid) where a w x h widget overlaps no other one. */
export function freeSpot(panel: Panel, w: number, h: number): { x: number; y: number } {
  const step = Math.max(panel.grid || DEFAULT_GRID, 10);
  const width = panel.width ?? 800;
  const height = panel.height ?? 480;
  const gap = step;
  const clear = (x: number, y: number) =>
    widgetsOf(panel).every(
      (o) => x + w + gap <= o.x || o.x + o.w + gap <= x || y + h + gap <= o.y || o.y + o.h + gap <= y,
    );
  for (let y = step; y + h <= height; y += step)
    for (let x = step; x + w <= width; x += step) if (clear(x, y)) return { x, y };
  return { x: 0, y: 0 };
}

export const addWidget = (panel: Panel, widget: Widget): Panel => ({
  ...panel,
  widgets: [...widgetsOf(panel), widget],
});

export function updateWidget(panel: Panel, id: string, patch: Partial<Widget>): Panel {
  return { ...panel, widgets: widgetsOf(panel).map((w) => (w.id === id ? ({ ...w, ...patch } as Widget) : w)) };
}

export const deleteWidgets = (panel: Panel, ids: ReadonlySet<string>): Panel => ({
  ...panel,
  widgets: widgetsOf(panel).filter((w) => !ids.has(w.id)),
});

/** Copies of the widgets, 2 grid steps down and right, with new ids; returns the panel and the copies' ids. */
export function duplicateWidgets(panel: Panel, ids: ReadonlySet<string>): [Panel, string[]] {
  const step = 2 * (panel.grid || DEFAULT_GRID);
  let next = panel;
  const made: string[] = [];
  for (const w of widgetsOf(panel).filter((w) => ids.has(w.id))) {
    const copy = { ...structuredClone(w), id: freeId(next, w.id.replace(/\d+$/, "")), x: w.x + step, y: w.y + step };
    next = addWidget(next, copy);
    made.push(copy.id);
  }
  return [next, made];
}

/** Moves the widgets by (dx, dy) in panel pixels, snapped, none past the panel's edges. */
export function moveWidgets(panel: Panel, ids: ReadonlySet<string>, dx: number, dy: number): Panel {
  const grid = panel.grid ?? DEFAULT_GRID;
  return {
    ...panel,
    widgets: widgetsOf(panel).map((w) =>
      ids.has(w.id)
        ? {
            ...w,
            x: Math.min(snap(w.x + dx, grid), Math.max(0, (panel.width ?? 800) - w.w)),
            y: Math.min(snap(w.y + dy, grid), Math.max(0, (panel.height ?? 480) - w.h)),
          }
        : w,
    ),
  };
}

/** The widget's new size (snapped, at least 4 px, not past the panel's edges). */
export function resizeWidget(panel: Panel, id: string, w: number, h: number): Panel {
  const grid = panel.grid ?? DEFAULT_GRID;
  return {
    ...panel,
    widgets: widgetsOf(panel).map((x) =>
      x.id === id
        ? {
            ...x,
            w: Math.max(4, Math.min(snap(w, grid) || grid, (panel.width ?? 800) - x.x)),
            h: Math.max(4, Math.min(snap(h, grid) || grid, (panel.height ?? 480) - x.y)),
          }
        : x,
    ),
  };
}

export type Alignment = "left" | "center" | "right" | "top" | "middle" | "bottom";

/** Lines the widgets up on the first selected one's edge or centre (the selection's order). */
export function alignWidgets(panel: Panel, ids: readonly string[], how: Alignment): Panel {
  const chosen = ids.map((id) => widgetsOf(panel).find((w) => w.id === id)).filter((w) => w !== undefined);
  const anchor = chosen[0];
  if (!anchor || chosen.length < 2) return panel;
  const place = (w: Widget): Partial<Widget> => {
    switch (how) {
      case "left":
        return { x: anchor.x };
      case "right":
        return { x: anchor.x + anchor.w - w.w };
      case "center":
        return { x: Math.round(anchor.x + anchor.w / 2 - w.w / 2) };
      case "top":
        return { y: anchor.y };
      case "bottom":
        return { y: anchor.y + anchor.h - w.h };
      case "middle":
        return { y: Math.round(anchor.y + anchor.h / 2 - w.h / 2) };
    }
  };
  const set = new Set(ids);
  return {
    ...panel,
    widgets: widgetsOf(panel).map((w) => (set.has(w.id) && w !== anchor ? ({ ...w, ...place(w) } as Widget) : w)),
  };
}

/** Spaces three or more widgets evenly between the outermost ones, across (x) or down (y). */
export function distributeWidgets(panel: Panel, ids: readonly string[], axis: "x" | "y"): Panel {
  const size = axis === "x" ? "w" : "h";
  const chosen = widgetsOf(panel)
    .filter((w) => ids.includes(w.id))
    .sort((a, b) => a[axis] - b[axis]);
  if (chosen.length < 3) return panel;
  const first = chosen[0]!;
  const last = chosen[chosen.length - 1]!;
  const inner = chosen.slice(1, -1).reduce((sum, w) => sum + w[size], 0);
  const gap = (last[axis] - (first[axis] + first[size]) - inner) / (chosen.length - 1);
  const placed = new Map<string, number>();
  let at = first[axis] + first[size] + gap;
  for (const w of chosen.slice(1, -1)) {
    placed.set(w.id, Math.round(at));
    at += w[size] + gap;
  }
  return {
    ...panel,
    widgets: widgetsOf(panel).map((w) => (placed.has(w.id) ? ({ ...w, [axis]: placed.get(w.id) } as Widget) : w)),
  };
}

/** Every variable a panel reads, in widget order, without repeats (what it subscribes to online). */
export function bindingsOf(panel: Panel): string[] {
  const found = new Map<string, string>();
  const add = (path: string | null | undefined) => {
    if (path && path.trim() && !found.has(pathKey(path))) found.set(pathKey(path), path.trim());
  };
  for (const w of widgetsOf(panel)) {
    if ("bind" in w) add(w.bind);
    if ("fault" in w) add(w.fault);
    add(w.visible);
    add(w.move_x?.path);
    add(w.move_y?.path);
    if (w.type === "trend") for (const p of w.paths) add(p);
  }
  return [...found.values()];
}

// ------------------------------------------------------------------ values

/** What a value means as a BOOL (numbers: not 0), for lamps, switches and `visible`. */
export const truthy = (value: Value | undefined): boolean =>
  value === true || (typeof value === "number" && value !== 0) || value === "TRUE";

/** A number from a value (BOOLs as 0/1), or null when it is none. */
export function numeric(value: Value | undefined): number | null {
  if (typeof value === "number") return Number.isFinite(value) ? value : null;
  if (typeof value === "boolean") return value ? 1 : 0;
  return null;
}

/** Where `value` puts a widget moved by `motion`: 0 at `min`, `distance` pixels at `max`, held at the ends. */
export function motionOffset(motion: Motion | null | undefined, value: Value | undefined): number {
  if (!motion) return 0;
  const n = numeric(value);
  if (n === null) return 0;
  const min = motion.min ?? 0;
  const max = motion.max ?? 100;
  return Math.min(1, Math.max(0, (n - min) / (max - min))) * motion.distance;
}

/** The fraction (0..1) of `value` between `min` and `max`, held at the ends. */
export const fraction = (value: Value | undefined, min = 0, max = 100): number => {
  const n = numeric(value);
  return n === null || !(max > min) ? 0 : Math.min(1, Math.max(0, (n - min) / (max - min)));
};

/** A numeric display's text: numbers with `decimals` (as they come without), TIME and dates as IEC literals. */
export function displayText(value: Value | undefined, type: DisplayType | undefined, decimals?: number | null): string {
  if (typeof value === "number" && decimals != null && !type?.names && !isTimeType(type))
    return value.toFixed(decimals);
  return formatValue(value, type);
}

const isTimeType = (type: DisplayType | undefined): boolean =>
  !!type && ["TIME", "DATE", "TIME_OF_DAY", "TOD", "DATE_AND_TIME", "DT"].includes(type.name.toUpperCase());

/** The state a multistate indicator shows: the first whose value equals the variable's (TRUE = 1 and so on). */
export function stateOf(states: readonly State[], value: Value | undefined): State | undefined {
  return states.find(
    (s) => s.value === value || (numeric(s.value as Value) !== null && numeric(s.value as Value) === numeric(value)),
  );
}

/** The characters of a seven-segment display: the integer right-aligned, "-" for a minus, all "-" on overflow. */
export function sevenSegmentText(value: Value | undefined, digits: number): string {
  const n = numeric(value);
  if (n === null) return " ".repeat(digits);
  const text = String(Math.trunc(n));
  return text.length > digits ? "-".repeat(digits) : text.padStart(digits, " ");
}

/** What a push button writes: TRUE while held (FALSE while held when normally closed). */
export const pushValue = (pressed: boolean, nc: boolean | undefined): boolean => (nc ? !pressed : pressed);

/** The value a numeric input sends for text the user typed (as the watch list reads it); null for nothing. */
export const typedValue = (text: string): WriteValue | null => (text.trim() ? parseValue(text) : null);

/** A slider's value for a pointer at `at` (0..1 along it), on its steps. */
export function sliderValue(at: number, min: number, max: number, step: number): number {
  const raw = min + Math.min(1, Math.max(0, at)) * (max - min);
  const stepped = min + Math.round((raw - min) / step) * step;
  return Number(Math.min(max, Math.max(min, stepped)).toFixed(10));
}
