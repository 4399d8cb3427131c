// The drawing of an SFC chart, computed from its structure (no coordinates are stored): sequences run top to
// bottom on a centre line, a step's action block stands to its right, the branches of a divergence stand side
// by side under a single (alternative) or double (simultaneous) line and join again under another. Pure, so it
// is tested without a browser; the SVG view only draws what this returns.
import { kindOf, type Sequence, type SfcElement, type SfcStep, type SfcTransition } from "./model";

export const STEP_W = 120;
export const STEP_H = 40;
export const TRANSITION_H = 28;
export const JUMP_H = 34;
export const ROW_H = 22;
export const ACTION_GAP = 24;
export const QUALIFIER_W = 46;
export const ACTION_NAME_W = 130;
export const TIME_W = 64;
export const ACTION_W = QUALIFIER_W + ACTION_NAME_W + TIME_W;
export const LINK = 18;
export const BRANCH_GAP = 36;
export const BAR = 6;
const CHAR_W = 7;

export interface Item {
  element: SfcElement;
  /** The centre line and top of the element itself. */
  x: number;
  y: number;
  height: number;
}

export interface Line {
  x1: number;
  y1: number;
  x2: number;
  y2: number;
  /** A simultaneous divergence or convergence: a double line. */
  double?: boolean;
}

export interface ChartLayout {
  items: Item[];
  lines: Line[];
  width: number;
  height: number;
}

interface Block {
  left: number;
  right: number;
  height: number;
  /** Draws the block with its centre line at x and its top at y. */
  draw(x: number, y: number, out: ChartLayout): void;
}

const textWidth = (text: string) => Math.min(280, 12 + text.length * CHAR_W);

function element(e: SfcElement): Block {
  switch (kindOf(e)) {
    case "step": {
      const rows = (e as SfcStep).actions?.length ?? 0;
      const height = Math.max(STEP_H, rows * ROW_H);
      return {
        left: STEP_W / 2,
        right: STEP_W / 2 + (rows ? ACTION_GAP + ACTION_W : 0),
        height,
        draw: (x, y, out) => out.items.push({ element: e, x, y, height }),
      };
    }
    case "transition":
      return {
        left: STEP_W / 2,
        right: 14 + textWidth((e as SfcTransition).condition ?? ""),
        height: TRANSITION_H,
        draw: (x, y, out) => out.items.push({ element: e, x, y, height: TRANSITION_H }),
      };
    case "jump":
      return {
        left: STEP_W / 2,
        right: 14 + textWidth((e as { target: string }).target),
        height: JUMP_H,
        draw: (x, y, out) => out.items.push({ element: e, x, y, height: JUMP_H }),
      };
    default:
      return divergence(e);
  }
}

/** A sequence: its elements on one centre line, joined by short vertical links. */
function sequence(elements: Sequence): Block {
  const blocks = elements.map(element);
  const left = Math.max(STEP_W / 2, ...blocks.map((b) => b.left));
  const right = Math.max(STEP_W / 2, ...blocks.map((b) => b.right));
  const height = blocks.reduce((sum, b) => sum + b.height, 0) + LINK * Math.max(0, blocks.length - 1);
  return {
    left,
    right,
    height,
    draw(x, y, out) {
      let top = y;
      blocks.forEach((b, i) => {
        if (i > 0) {
          out.lines.push({ x1: x, y1: top, x2: x, y2: top + LINK });
          top += LINK;
        }
        b.draw(x, top, out);
        top += b.height;
      });
    },
  };
}

/** The branches side by side between a divergence line and, where they join, a convergence line. */
function divergence(e: SfcElement): Block {
  const parallel = kindOf(e) === "parallel";
  const branches = (e as { branches: Sequence[] }).branches.map(sequence);
  const joins = (e as { branches: Sequence[] }).branches.map((b) => {
    const last = b[b.length - 1];
    return last !== undefined && kindOf(last) !== "jump";
  });
  const offsets: number[] = [];
  let at = 0;
  branches.forEach((b, i) => {
    if (i > 0) at += branches[i - 1]!.right + BRANCH_GAP + b.left;
    offsets.push(at);
  });
  const left = branches[0]!.left;
  const right = offsets[offsets.length - 1]! + branches[branches.length - 1]!.right;
  const inner = Math.max(...branches.map((b) => b.height));
  const height = BAR + LINK + inner + LINK + BAR;
  return {
    left,
    right,
    height,
    draw(x, y, out) {
      const xs = offsets.map((o) => x + o);
      const last = xs[xs.length - 1]!;
      out.items.push({ element: e, x, y, height });
      out.lines.push({ x1: x, y1: y, x2: last, y2: y, double: parallel });
      const top = y + BAR;
      const bottom = y + height - BAR;
      branches.forEach((b, i) => {
        const bx = xs[i]!;
        out.lines.push({ x1: bx, y1: top, x2: bx, y2: top + LINK });
        b.draw(bx, top + LINK, out);
        if (joins[i]) out.lines.push({ x1: bx, y1: top + LINK + b.height, x2: bx, y2: bottom });
      });
      const joined = xs.filter((_, i) => joins[i]);
      if (joined.length)
        out.lines.push({
          x1: Math.min(x, ...joined),
          y1: bottom,
          x2: Math.max(...joined),
          y2: bottom,
          double: parallel,
        });
    },
  };
}

/** The chart's drawing, with a margin around it. */
export function layoutChart(elements: Sequence, margin = 24): ChartLayout {
  const out: ChartLayout = { items: [], lines: [], width: 0, height: 0 };
  if (elements.length === 0) return { ...out, width: 2 * margin + STEP_W, height: 2 * margin + STEP_H };
  const block = sequence(elements);
  block.draw(margin + block.left, margin, out);
  return { ...out, width: 2 * margin + block.left + block.right, height: 2 * margin + block.height };
}

/** The item of the element with this id. */
export const itemOf = (layout: ChartLayout, id: string): Item | undefined =>
  layout.items.find((i) => i.element.id === id);

export type Direction = "up" | "down" | "left" | "right";

/** The element the arrow keys move to from `id`: the nearest item in that direction (vertical moves prefer
 * the same column). */
export function neighbour(layout: ChartLayout, id: string | null, direction: Direction): string | null {
  const items = layout.items.filter((i) => kindOf(i.element) !== "alternative" && kindOf(i.element) !== "parallel");
  if (!id) return items[0]?.element.id ?? null;
  const from = itemOf(layout, id);
  if (!from) return items[0]?.element.id ?? null;
  const fy = from.y + from.height / 2;
  let best: Item | null = null;
  let score = Infinity;
  for (const item of items) {
    if (item === from) continue;
    const dx = item.x - from.x;
    const dy = item.y + item.height / 2 - fy;
    const ahead = direction === "down" ? dy > 0 : direction === "up" ? dy < 0 : direction === "right" ? dx > 0 : dx < 0;
    if (!ahead) continue;
    const along = direction === "up" || direction === "down" ? Math.abs(dy) : Math.abs(dx);
    const across = direction === "up" || direction === "down" ? Math.abs(dx) : Math.abs(dy);
    const value = along + across * 3;
    if (value < score) {
      score = value;
      best = item;
    }
  }
  return best?.element.id ?? id;
}
