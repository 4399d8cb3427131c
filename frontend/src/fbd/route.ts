// Orthogonal wire routing of the FBD editor (issue 28): a wire leaves its output pin to the right, enters its
// input pin from the left, runs only horizontally and vertically and goes around the blocks in between
// instead of behind them. Among the few routes of three or five segments whose corners lie on the pins'
// rows, in the gaps next to the nodes or between them, the shortest one that crosses no node wins (a bend
// costs as much as BEND px); when every route crosses something, the one crossing least. Pure: the
// canvas gives the pins and the nodes' boxes.

export interface Point {
  x: number;
  y: number;
}

export interface Box {
  x: number;
  y: number;
  width: number;
  height: number;
}

/** How far a wire runs straight out of a pin before it may turn, and its distance from the nodes it passes. */
export const STUB = 12;
export const CLEARANCE = 8;
const BEND = 24;

type Segment = [Point, Point];

/** Does the horizontal or vertical segment cross the inside of the box (running along its edge does not)? */
function crosses([a, b]: Segment, box: Box): boolean {
  const left = box.x;
  const right = box.x + box.width;
  const top = box.y;
  const bottom = box.y + box.height;
  if (a.y === b.y) {
    const [x1, x2] = a.x < b.x ? [a.x, b.x] : [b.x, a.x];
    return a.y > top && a.y < bottom && x2 > left && x1 < right;
  }
  const [y1, y2] = a.y < b.y ? [a.y, b.y] : [b.y, a.y];
  return a.x > left && a.x < right && y2 > top && y1 < bottom;
}

const segments = (points: readonly Point[]): Segment[] => points.slice(1).map((p, i): Segment => [points[i]!, p]);

function length(points: readonly Point[]): number {
  return segments(points).reduce((sum, [a, b]) => sum + Math.abs(a.x - b.x) + Math.abs(a.y - b.y), 0);
}

/** Consecutive points that repeat or continue in the same direction are merged. */
function simplified(points: readonly Point[]): Point[] {
  const out: Point[] = [];
  for (const p of points) {
    const last = out[out.length - 1];
    if (last && last.x === p.x && last.y === p.y) continue;
    const before = out[out.length - 2];
    if (before && last && ((before.x === last.x && last.x === p.x) || (before.y === last.y && last.y === p.y)))
      out[out.length - 1] = p;
    else out.push(p);
  }
  return out;
}

/**
 * The corners of the wire from `source` (an output pin, leaving to the right) to `target` (an input pin,
 * entered from the left), avoiding `obstacles` (every node's box; the wire's own nodes included: it must
 * not cut through them either).
 */
export function route(source: Point, target: Point, obstacles: readonly Box[]): Point[] {
  const out = { x: source.x + STUB, y: source.y };
  const into = { x: target.x - STUB, y: target.y };
  const xs = new Set<number>([Math.round((out.x + into.x) / 2), out.x, into.x]); // ties: the middle first
  const ys = new Set<number>([source.y, target.y]);
  for (const box of obstacles) {
    xs.add(box.x - CLEARANCE);
    xs.add(box.x + box.width + CLEARANCE);
    ys.add(box.y - CLEARANCE);
    ys.add(box.y + box.height + CLEARANCE);
  }
  const forward = [...xs].filter((x) => x >= out.x && x <= into.x);
  const candidates: Point[][] = forward.map((x) => [source, { x, y: source.y }, { x, y: target.y }, target]);
  const lefts = [...xs].filter((x) => x >= out.x);
  const rights = [...xs].filter((x) => x <= into.x);
  for (const x1 of lefts)
    for (const y of ys)
      for (const x2 of rights)
        candidates.push([source, { x: x1, y: source.y }, { x: x1, y }, { x: x2, y }, { x: x2, y: target.y }, target]);
  let best: { points: Point[]; hits: number; cost: number } | null = null;
  for (const candidate of candidates) {
    const points = simplified(candidate);
    const hits = segments(points).reduce((n, s) => n + obstacles.filter((box) => crosses(s, box)).length, 0);
    const cost = length(points) + BEND * (points.length - 2);
    if (!best || hits < best.hits || (hits === best.hits && cost < best.cost)) best = { points, hits, cost };
  }
  return best!.points;
}

/** An SVG path through the corners. */
export const pathOf = (points: readonly Point[]): string =>
  points.map((p, i) => `${i ? "L" : "M"} ${p.x} ${p.y}`).join(" ");
