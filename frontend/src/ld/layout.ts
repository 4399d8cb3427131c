// LD layout engine: the model in, positioned elements, wires and insertion slots out. Nothing is
// stored in the model, so every edit reflows the whole diagram. Pure arithmetic, no DOM: a series
// is laid out left to right with a wire gap around each element, a parallel stacks its branches
// between two vertical links, a box grows with its pins and the series feeding them. In each rung
// the trailing coils (and jump/return) sit against the right rail, as in CODESYS.
import type { LibraryEntry } from "../generated/api";
import {
  elementsOf,
  type Box,
  type Parallel,
  networksOf,
  type LdBody,
  type LdElement,
  type LdNetwork,
  type Place,
  type Series,
  type SeriesRef,
} from "./model";
import { boxPins, type BoxPin } from "./pins";
import { isOutput } from "./validate";

/** Sizes in SVG pixels. */
export const METRICS = {
  /** Wire gap before, between and after elements of a series. */
  gap: 14,
  /** Height and power-line offset of a contact, coil, compare, jump or return. */
  rowHeight: 58,
  line: 38,
  /** Width of one character of operand text (12 px monospace). */
  char: 7.2,
  minElement: 60,
  maxElement: 170,
  compareWidth: 90,
  branchGap: 6,
  /** Box: space for the instance name, the title row, one pin row. */
  boxTop: 20,
  boxHead: 20,
  pinRow: 22,
  minBoxBody: 72,
  /** A series feeding a box pin starts with a short rail stub this far left of its first wire. */
  stub: 6,
  leftRail: 44,
  minRightRail: 640,
  header: 24,
  comment: 16,
  networkPad: 12,
  emptySeries: 48,
  /** Online (LayoutOptions.values): room under a contact or coil for its variable's value... */
  valueRow: 12,
  /** ...and inside a box next to each pin's name for the pin's value (11 characters of 10 px text). */
  pinValue: 70,
} as const;

/** The element whose right-side power a wire carries; null is the left rail (always ON). */
export type PowerSource = string | null;

export interface LaidWire {
  x1: number;
  y1: number;
  x2: number;
  y2: number;
  power: PowerSource;
  /** A series wire, a vertical link of a parallel, or the rail stub of a series feeding a pin. */
  kind: "wire" | "branch" | "stub";
}

export interface PlacedPin extends BoxPin {
  side: "in" | "out";
  /** The point on the box edge. */
  x: number;
  y: number;
  /** An input carrying power: the element whose power it gets (null: the left rail); unset for operand pins. */
  feed?: PowerSource;
}

export interface PlacedElement {
  id: string;
  element: LdElement;
  network: string;
  series: SeriesRef;
  index: number;
  x: number;
  y: number;
  width: number;
  height: number;
  /** y of the power line through the element. */
  lineY: number;
  /** Boxes: the body rectangle and the pins. */
  body?: { x: number; y: number; width: number; height: number };
  pins?: PlacedPin[];
  /** Boxes: calls a function block, so it names an instance above the box. */
  instanced?: boolean;
}

/** A point on a wire where something can be inserted or dropped. */
export interface Slot {
  place: Place;
  x: number;
  y: number;
}

export interface NetworkLayout {
  network: LdNetwork;
  index: number;
  /** Offset of the network in the diagram; everything else is relative to the network's top. */
  top: number;
  height: number;
  rungTop: number;
  rungBottom: number;
  leftRailX: number;
  rightRailX: number;
  /** Whether the rung's last wire reaches the right rail (it ends with coils, a jump or a return). */
  reachesRightRail: boolean;
  elements: PlacedElement[];
  wires: LaidWire[];
  slots: Slot[];
}

export interface LdLayout {
  networks: NetworkLayout[];
  width: number;
  height: number;
  rightRailX: number;
}

export interface LayoutOptions {
  /** The library entry of a box's call (pins and types); unknown calls show only connected pins. */
  library?: (call: string) => LibraryEntry | undefined;
  minRightRail?: number;
  /** Online: leave room for values (under contacts and coils, next to box pin names). */
  values?: boolean;
}

interface Block {
  width: number;
  height: number;
  lineOffset: number;
  elements: PlacedElement[];
  wires: LaidWire[];
  slots: Slot[];
}

interface Ctx {
  network: string;
  library: (call: string) => LibraryEntry | undefined;
  values: boolean;
}

export const textWidth = (text: string): number => text.length * METRICS.char;

const clamp = (v: number, lo: number, hi: number) => Math.max(lo, Math.min(hi, v));

function shift(block: Block, dx: number, dy: number): Block {
  if (dx === 0 && dy === 0) return block;
  return {
    ...block,
    elements: block.elements.map((e) => ({
      ...e,
      x: e.x + dx,
      y: e.y + dy,
      lineY: e.lineY + dy,
      body: e.body && { ...e.body, x: e.body.x + dx, y: e.body.y + dy },
      pins: e.pins?.map((p) => ({ ...p, x: p.x + dx, y: p.y + dy })),
    })),
    wires: block.wires.map((w) => ({ ...w, x1: w.x1 + dx, x2: w.x2 + dx, y1: w.y1 + dy, y2: w.y2 + dy })),
    slots: block.slots.map((s) => ({ ...s, x: s.x + dx, y: s.y + dy })),
  };
}

/**
 * A series: gap, element, gap, element, ..., gap. `stretch` widens the gap before element `at`
 * by `extra` (how a rung pushes its coils to the right rail).
 */
function layoutSeries(
  series: Series,
  ref: SeriesRef,
  inPower: PowerSource,
  ctx: Ctx,
  stretch?: { at: number; extra: number },
): Block {
  const { gap } = METRICS;
  const blocks = series.map((element, i) => layoutElement(element, ref, i, i === 0 ? inPower : series[i - 1]!.id, ctx));
  const lineOffset = Math.max(METRICS.line, ...blocks.map((b) => b.lineOffset));
  const out: Block = { width: 0, height: METRICS.rowHeight, lineOffset, elements: [], wires: [], slots: [] };
  let x = 0;
  for (let i = 0; i <= blocks.length; i += 1) {
    const wide = gap + (stretch?.at === i ? stretch.extra : 0) + (blocks.length === 0 ? METRICS.emptySeries - gap : 0);
    const power = i === 0 ? inPower : series[i - 1]!.id;
    out.wires.push({ x1: x, y1: lineOffset, x2: x + wide, y2: lineOffset, power, kind: "wire" });
    out.slots.push({ place: { series: ref, index: i }, x: x + wide / 2, y: lineOffset });
    x += wide;
    const block = blocks[i];
    if (!block) break;
    const placed = shift(block, x, lineOffset - block.lineOffset);
    out.elements.push(...placed.elements);
    out.wires.push(...placed.wires);
    out.slots.push(...placed.slots);
    out.height = Math.max(out.height, lineOffset - block.lineOffset + block.height);
    x += block.width;
  }
  out.width = x;
  return out;
}

function leaf(element: LdElement, ref: SeriesRef, index: number, ctx: Ctx, width: number): Block {
  const { line } = METRICS;
  const height = METRICS.rowHeight + (ctx.values ? METRICS.valueRow : 0);
  const placed: PlacedElement = {
    id: element.id,
    element,
    network: ctx.network,
    series: ref,
    index,
    x: 0,
    y: 0,
    width,
    height,
    lineY: line,
  };
  return { width, height, lineOffset: line, elements: [placed], wires: [], slots: [] };
}

function layoutElement(element: LdElement, ref: SeriesRef, index: number, inPower: PowerSource, ctx: Ctx): Block {
  const operandWidth = (text: string) => clamp(textWidth(text) + 14, METRICS.minElement, METRICS.maxElement);
  switch (element.type) {
    case "parallel":
      return layoutParallel(element, ref, index, inPower, ctx);
    case "box":
      return layoutBox(element, ref, index, inPower, ctx);
    case "compare":
      return leaf(
        element,
        ref,
        index,
        ctx,
        clamp(
          Math.max(textWidth(element.left), textWidth(element.right)) + 24,
          METRICS.compareWidth,
          METRICS.maxElement,
        ),
      );
    case "jump":
      return leaf(element, ref, index, ctx, operandWidth(`>> ${element.target}`));
    case "return":
      return leaf(element, ref, index, ctx, operandWidth("RETURN"));
    case "contact":
    case "coil":
      return leaf(element, ref, index, ctx, operandWidth(element.var));
  }
  // The schema leaves `type` optional (it has a default), but pydantic always writes it.
  return leaf(element, ref, index, ctx, METRICS.minElement);
}

function layoutParallel(element: Parallel, ref: SeriesRef, index: number, inPower: PowerSource, ctx: Ctx): Block {
  const branches = element.branches.map((series, branch) =>
    layoutSeries(series, { kind: "branch", parallel: element.id, branch }, inPower, ctx),
  );
  const width = Math.max(...branches.map((b) => b.width));
  const out: Block = {
    width,
    height: 0,
    lineOffset: branches[0]?.lineOffset ?? METRICS.line,
    elements: [],
    wires: [],
    slots: [],
  };
  let top = 0;
  const lines: number[] = [];
  branches.forEach((block, i) => {
    const placed = shift(block, 0, top);
    const lineY = top + block.lineOffset;
    lines.push(lineY);
    out.elements.push(...placed.elements);
    out.wires.push(...placed.wires);
    out.slots.push(...placed.slots);
    if (block.width < width) {
      const last = element.branches[i]![element.branches[i]!.length - 1];
      out.wires.push({ x1: block.width, y1: lineY, x2: width, y2: lineY, power: last?.id ?? inPower, kind: "wire" });
    }
    top += block.height + METRICS.branchGap;
  });
  out.height = top - METRICS.branchGap;
  const first = lines[0] ?? out.lineOffset;
  const last = lines[lines.length - 1] ?? out.lineOffset;
  out.wires.push({ x1: 0, y1: first, x2: 0, y2: last, power: inPower, kind: "branch" });
  out.wires.push({ x1: width, y1: first, x2: width, y2: last, power: element.id, kind: "branch" });
  const self: PlacedElement = {
    id: element.id,
    element,
    network: ctx.network,
    series: ref,
    index,
    x: 0,
    y: 0,
    width,
    height: out.height,
    lineY: first,
  };
  out.elements.unshift(self);
  return out;
}

function layoutBox(element: Box, ref: SeriesRef, index: number, inPower: PowerSource, ctx: Ctx): Block {
  const { boxTop, boxHead, pinRow, stub } = METRICS;
  const entry = ctx.library(element.call);
  const pins = boxPins(element, entry);
  const inputRows = pins.inputs.map((pin) => {
    if (Array.isArray(pin.value)) {
      const block = layoutSeries(pin.value, { kind: "pin", box: element.id, pin: pin.name }, null, ctx);
      return { pin, block, height: Math.max(pinRow, block.height), line: Math.max(pinRow / 2, block.lineOffset) };
    }
    return { pin, block: undefined, height: pinRow, line: pinRow / 2 };
  });
  const leftWidth = Math.max(
    24,
    ...inputRows.map((r) =>
      r.block ? r.block.width + stub : typeof r.pin.value === "string" ? textWidth(r.pin.value) + 12 : 0,
    ),
  );
  const rightWidth = Math.max(
    24,
    ...pins.outputs.map((p) => (typeof p.value === "string" ? textWidth(p.value) + 12 : 0)),
  );
  const rows = Math.max(pins.inputs.length, pins.outputs.length);
  let bodyWidth = Math.max(METRICS.minBoxBody, textWidth(element.call) + 20, textWidth(element.instance ?? "") + 8);
  const values = ctx.values ? 2 * METRICS.pinValue : 0;
  for (let i = 0; i < rows; i += 1) {
    bodyWidth = Math.max(
      bodyWidth,
      textWidth(pins.inputs[i]?.name ?? "") + textWidth(pins.outputs[i]?.name ?? "") + 24 + values,
    );
  }
  const bodyX = leftWidth;
  const rowsTop = boxTop + boxHead;
  const out: Block = {
    width: leftWidth + bodyWidth + rightWidth,
    height: 0,
    lineOffset: rowsTop + inputRows[0]!.line,
    elements: [],
    wires: [],
    slots: [],
  };
  const placedPins: PlacedPin[] = [];
  let top = rowsTop;
  for (const row of inputRows) {
    const y = top + row.line;
    const series = Array.isArray(row.pin.value) ? row.pin.value : null;
    const feed = series ? (series[series.length - 1]?.id ?? null) : row.pin.power ? inPower : undefined;
    placedPins.push({ ...row.pin, side: "in", x: bodyX, y, ...(feed !== undefined ? { feed } : {}) });
    if (row.block) {
      const x = bodyX - row.block.width;
      const placed = shift(row.block, x, y - row.block.lineOffset);
      out.elements.push(...placed.elements);
      out.wires.push(...placed.wires);
      out.slots.push(...placed.slots);
      out.wires.push({ x1: x, y1: y - 9, x2: x, y2: y + 9, power: null, kind: "stub" });
    }
    top += row.height;
  }
  const row0 = inputRows[0]!;
  pins.outputs.forEach((pin, i) => {
    const y = i === 0 ? out.lineOffset : rowsTop + row0.height + (i - 1) * pinRow + pinRow / 2;
    placedPins.push({ ...pin, side: "out", x: bodyX + bodyWidth, y });
  });
  const bodyBottom = Math.max(top, rowsTop + row0.height + (pins.outputs.length - 1) * pinRow) + 4;
  out.height = bodyBottom + 4;
  out.wires.push({ x1: 0, y1: out.lineOffset, x2: bodyX, y2: out.lineOffset, power: inPower, kind: "wire" });
  out.wires.push({
    x1: bodyX + bodyWidth,
    y1: out.lineOffset,
    x2: out.width,
    y2: out.lineOffset,
    power: element.id,
    kind: "wire",
  });
  out.elements.unshift({
    id: element.id,
    element,
    network: ctx.network,
    series: ref,
    index,
    x: 0,
    y: 0,
    width: out.width,
    height: out.height,
    lineY: out.lineOffset,
    body: { x: bodyX, y: boxTop, width: bodyWidth, height: bodyBottom - boxTop },
    pins: placedPins,
    instanced: entry ? entry.kind === "function_block" : element.instance != null,
  });
  return out;
}

/** Index of the first of a rung's trailing outputs, or -1 when it has none. */
function trailingOutputs(series: Series): number {
  return series.findIndex(isOutput);
}

/** The positions of everything in one network, with rails at `leftRailX` and `rightRailX`. */
function layoutNetwork(network: LdNetwork, rightRailX: number, ctx: Ctx): { layout: NetworkLayout; natural: number } {
  const elements = elementsOf(network);
  const ref: SeriesRef = { kind: "network", network: network.id };
  const leftRailX = METRICS.leftRail;
  let block = layoutSeries(elements, ref, null, ctx);
  const natural = leftRailX + block.width;
  const outputsAt = trailingOutputs(elements);
  const reachesRightRail = outputsAt >= 0;
  if (reachesRightRail && natural < rightRailX) {
    block = layoutSeries(elements, ref, null, ctx, { at: outputsAt, extra: rightRailX - natural });
  }
  const rungTop = METRICS.header + (network.comment ? METRICS.comment : 0) + 6;
  const placed = shift(block, leftRailX, rungTop);
  return {
    natural,
    layout: {
      network,
      index: 0,
      top: 0,
      height: rungTop + block.height + METRICS.networkPad,
      rungTop,
      rungBottom: rungTop + block.height,
      leftRailX,
      rightRailX,
      reachesRightRail,
      elements: placed.elements,
      wires: placed.wires,
      slots: placed.slots,
    },
  };
}

type Laid = ReturnType<typeof layoutNetwork>;

/**
 * Network layouts by network object, rail position and library. Edits rebuild only the networks
 * they touch (model.ts keeps the others' identity), so reflowing a 1,000-network POU after an edit
 * recomputes one network.
 */
const cache = new WeakMap<
  LdNetwork,
  { rightRailX: number; library: Ctx["library"]; values: boolean; laid: Laid; placed?: NetworkLayout }
>();

type Shared = Pick<Ctx, "library" | "values">;

function cachedNetwork(network: LdNetwork, rightRailX: number, { library, values }: Shared): Laid {
  const hit = cache.get(network);
  if (hit && hit.rightRailX === rightRailX && hit.library === library && hit.values === values) return hit.laid;
  const laid = layoutNetwork(network, rightRailX, { network: network.id, library, values });
  cache.set(network, { rightRailX, library, values, laid });
  return laid;
}

/** The network's layout at its place in the diagram, the same object while nothing changed. */
function placedNetwork(
  network: LdNetwork,
  rightRailX: number,
  shared: Shared,
  index: number,
  top: number,
): NetworkLayout {
  const { layout } = cachedNetwork(network, rightRailX, shared);
  const entry = cache.get(network)!;
  if (entry.placed?.index !== index || entry.placed.top !== top) entry.placed = { ...layout, index, top };
  return entry.placed;
}

const noLibrary = (): undefined => undefined;

/** Lays out a whole LD body; all networks share one right rail, far enough right for the widest. */
export function layoutBody(body: LdBody, options: LayoutOptions = {}): LdLayout {
  const shared: Shared = { library: options.library ?? noLibrary, values: options.values ?? false };
  const networks = networksOf(body);
  const natural = networks.map((n) => {
    const hit = cache.get(n);
    return (hit?.library === shared.library && hit.values === shared.values ? hit.laid : cachedNetwork(n, 0, shared))
      .natural;
  });
  const rightRailX = Math.max(options.minRightRail ?? METRICS.minRightRail, ...natural);
  let top = 0;
  const laid = networks.map((network, index) => {
    const layout = placedNetwork(network, rightRailX, shared, index, top);
    top += layout.height;
    return layout;
  });
  return { networks: laid, width: rightRailX + METRICS.leftRail, height: top, rightRailX };
}
