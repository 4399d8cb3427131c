// Arrow-key movement of the selection through the rung. Left/right follow the structure (into a
// parallel's first branch, out after its end, from a box input series to the box); up/down move
// between branches and networks by position, to the element nearest in x.
import type { LdLayout, PlacedElement } from "../layout";
import { elementsOf, locate, networksOf, seriesAt, type LdBody, type Location, type SeriesRef } from "../model";
import type { Selection } from "../view/types";

export type Direction = "left" | "right" | "up" | "down";

const owner = (ref: SeriesRef): string | undefined =>
  ref.kind === "branch" ? ref.parallel : ref.kind === "pin" ? ref.box : undefined;

/** The element right of `id`: first of a parallel's first branch, the next one, or after the parallel it ends. */
function rightOf(body: LdBody, at: Location): string | undefined {
  if (at.element.type === "parallel") return at.element.branches[0]?.[0]?.id;
  let here: Location | undefined = at;
  while (here) {
    const next = seriesAt(body, here.series)?.[here.index + 1];
    if (next) return next.id;
    const up = owner(here.series);
    if (!up) return undefined;
    if (here.series.kind === "pin") return up;
    here = locate(body, up);
  }
  return undefined;
}

/** The element left of `id`: the previous one (the last of its first branch when it is a parallel), or the enclosing parallel or box. */
function leftOf(body: LdBody, at: Location): string | undefined {
  const previous = seriesAt(body, at.series)?.[at.index - 1];
  if (!previous) return owner(at.series);
  if (previous.type === "parallel") {
    const branch = previous.branches[0] ?? [];
    return branch[branch.length - 1]?.id ?? previous.id;
  }
  return previous.id;
}

function placedById(layout: LdLayout): Map<string, { placed: PlacedElement; top: number; index: number }> {
  const map = new Map<string, { placed: PlacedElement; top: number; index: number }>();
  layout.networks.forEach((n, index) =>
    n.elements.forEach((placed) => map.set(placed.id, { placed, top: n.top, index })),
  );
  return map;
}

/** The element of network `index` whose centre is nearest to x (or the network itself when empty). */
function nearestIn(layout: LdLayout, index: number, x: number, fromBelow: boolean): Selection | undefined {
  const n = layout.networks[index];
  if (!n) return undefined;
  const candidates = n.elements.filter((e) => e.element.type !== "parallel");
  if (candidates.length === 0) return { kind: "network", id: n.network.id };
  const row = fromBelow ? Math.max(...candidates.map((e) => e.lineY)) : Math.min(...candidates.map((e) => e.lineY));
  const best = candidates
    .filter((e) => e.lineY === row)
    .reduce((a, b) => (Math.abs(a.x + a.width / 2 - x) <= Math.abs(b.x + b.width / 2 - x) ? a : b));
  return { kind: "elements", ids: [best.id] };
}

function vertical(
  layout: LdLayout,
  from: { placed: PlacedElement; index: number },
  down: boolean,
): Selection | undefined {
  const cx = from.placed.x + from.placed.width / 2;
  const n = layout.networks[from.index]!;
  const rows = n.elements.filter(
    (e) => e.element.type !== "parallel" && (down ? e.lineY > from.placed.lineY : e.lineY < from.placed.lineY),
  );
  if (rows.length) {
    const row = down ? Math.min(...rows.map((e) => e.lineY)) : Math.max(...rows.map((e) => e.lineY));
    const best = rows
      .filter((e) => e.lineY === row)
      .reduce((a, b) => (Math.abs(a.x + a.width / 2 - cx) <= Math.abs(b.x + b.width / 2 - cx) ? a : b));
    return { kind: "elements", ids: [best.id] };
  }
  return nearestIn(layout, from.index + (down ? 1 : -1), cx, !down);
}

/** The selection after an arrow key, or the same selection when there is nowhere to go. */
export function navigate(
  body: LdBody,
  layout: LdLayout,
  selection: Selection | null,
  direction: Direction,
): Selection | null {
  const networks = networksOf(body);
  if (!selection) {
    const first = networks[0];
    if (!first) return null;
    const element = elementsOf(first)[0];
    return element ? { kind: "elements", ids: [element.id] } : { kind: "network", id: first.id };
  }
  if (selection.kind === "network") {
    const index = networks.findIndex((n) => n.id === selection.id);
    if (direction === "right") {
      const element = elementsOf(networks[index]!)[0];
      return element ? { kind: "elements", ids: [element.id] } : selection;
    }
    if (direction === "left") return selection;
    const next = networks[index + (direction === "down" ? 1 : -1)];
    return next ? { kind: "network", id: next.id } : selection;
  }
  if (selection.kind === "place") {
    const series = seriesAt(body, selection.place.series) ?? [];
    const id = direction === "left" ? series[selection.place.index - 1]?.id : series[selection.place.index]?.id;
    return id ? { kind: "elements", ids: [id] } : selection;
  }
  const focus = selection.ids[selection.ids.length - 1];
  const at = focus ? locate(body, focus) : undefined;
  if (!at) return null;
  if (direction === "right" || direction === "left") {
    const id = direction === "right" ? rightOf(body, at) : leftOf(body, at);
    if (id) return { kind: "elements", ids: [id] };
    return direction === "left" && at.series.kind === "network" ? { kind: "network", id: at.network } : selection;
  }
  const placed = placedById(layout).get(at.element.id);
  return (placed && vertical(layout, placed, direction === "down")) ?? selection;
}

/** Shift+left/right: grow or shrink a range within one series, keeping `anchor`. */
export function extend(body: LdBody, anchor: string, focus: string, direction: "left" | "right"): string {
  const at = locate(body, focus);
  const series = at && seriesAt(body, at.series);
  if (!at || !series) return focus;
  const next = series[at.index + (direction === "right" ? 1 : -1)];
  return next && locate(body, anchor) ? next.id : focus;
}
