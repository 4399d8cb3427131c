// Auto-arrange: a network laid out left to right in layers by data flow (a node one column right
// of everything feeding it, inputs just left of their first consumer), rows ordered by the rows of
// their sources so wires cross little. Positions are hints, but they break ties in the execution
// order where the wiring leaves it open; ops.arrangeNetwork therefore pins the order first.
// A feedback loop (issue 22 item 6) keeps its data flow left to right: the wire that closes it (the one
// the engine reads from the previous scan) is the only one that runs back, around the blocks.
import { kindOf, nodesOf, wiresOf, type FbdNetwork, type FbdNode, type Position, type Wire } from "./model";
import { feedbackPins } from "./order";

export const COLUMN = 220;
export const ROW_GAP = 30;
const MARGIN = 20;

/**
 * The wires closing a loop: with the execution order the backend reported, those the engine reads from the
 * previous scan (order.ts feedbackPins); without it, the wires back to a node still being walked by a
 * depth-first walk from the network's sources (inputs first, so the loop's entry stays left).
 */
function feedbackWires(network: FbdNetwork, order: readonly string[] | null): Set<Wire> {
  const wires = wiresOf(network);
  if (order) {
    const pins = feedbackPins(network, order);
    return new Set(wires.filter((w) => pins.has(`${w.to.node}/in:${w.to.pin.toUpperCase()}`)));
  }
  const out = new Map<string, Wire[]>();
  for (const w of wires) out.set(w.from.node, [...(out.get(w.from.node) ?? []), w]);
  const back = new Set<Wire>();
  const state = new Map<string, "walking" | "done">();
  const walk = (id: string) => {
    state.set(id, "walking");
    for (const w of out.get(id) ?? []) {
      const next = state.get(w.to.node);
      if (next === "walking") back.add(w);
      else if (next === undefined) walk(w.to.node);
    }
    state.set(id, "done");
  };
  const fed = new Set(wires.map((w) => w.to.node));
  const nodes = nodesOf(network);
  for (const n of [...nodes.filter((n) => !fed.has(n.id)), ...nodes]) if (!state.has(n.id)) walk(n.id);
  return back;
}

/** Longest-path layers over the wires; a wire closing a loop (feedback) does not push its target right. */
function layers(network: FbdNetwork, feedback: ReadonlySet<Wire>): Map<string, number> {
  const preds = new Map<string, string[]>(nodesOf(network).map((n) => [n.id, []]));
  for (const w of wiresOf(network)) if (!feedback.has(w)) preds.get(w.to.node)?.push(w.from.node);
  const layer = new Map<string, number>();
  const visiting = new Set<string>();
  const visit = (id: string): number => {
    const known = layer.get(id);
    if (known !== undefined) return known;
    if (visiting.has(id)) return -1; // a loop of connectors the walk did not see: no push either
    visiting.add(id);
    const from = (preds.get(id) ?? []).filter((p) => preds.has(p)).map(visit);
    visiting.delete(id);
    const value = from.length ? Math.max(...from) + 1 : 0;
    layer.set(id, Math.max(0, value));
    return layer.get(id)!;
  };
  for (const n of nodesOf(network)) visit(n.id);
  // Sources (inputs, continuations) sit just left of their nearest consumer, not all in column 0.
  const consumers = new Map<string, number[]>();
  for (const w of wiresOf(network))
    if (layer.has(w.to.node))
      consumers.set(w.from.node, [...(consumers.get(w.from.node) ?? []), layer.get(w.to.node)!]);
  for (const n of nodesOf(network)) {
    const uses = consumers.get(n.id);
    if ((preds.get(n.id) ?? []).length === 0 && uses?.length) layer.set(n.id, Math.max(0, Math.min(...uses) - 1));
  }
  return layer;
}

/** Positions for every node of `network`; `height` gives a node's drawn height; `order` is the execution order
 * the backend reported (null: not known), which says which wire of a loop is its feedback. */
export function arrange(
  network: FbdNetwork,
  height: (node: FbdNode) => number,
  order: readonly string[] | null = null,
): Map<string, Position> {
  const layer = layers(network, feedbackWires(network, order));
  const columns: FbdNode[][] = [];
  for (const node of nodesOf(network)) (columns[layer.get(node.id) ?? 0] ??= []).push(node);
  const row = new Map<string, number>(); // centre y of placed nodes
  const positions = new Map<string, Position>();
  const sources = new Map<string, string[]>();
  for (const w of wiresOf(network)) sources.set(w.to.node, [...(sources.get(w.to.node) ?? []), w.from.node]);
  columns.forEach((column, x) => {
    const anchor = (node: FbdNode): number => {
      const placed = (sources.get(node.id) ?? []).map((s) => row.get(s)).filter((y): y is number => y !== undefined);
      if (placed.length) return placed.reduce((a, b) => a + b, 0) / placed.length;
      return node.pos?.y ?? 0;
    };
    const keyed = column.map((node, i) => ({
      node,
      key: anchor(node),
      i,
      control: kindOf(node) === "jump" || kindOf(node) === "return",
    }));
    keyed.sort((a, b) => Number(a.control) - Number(b.control) || a.key - b.key || a.i - b.i);
    let y = MARGIN;
    for (const { node } of keyed) {
      const h = height(node);
      positions.set(node.id, { x: MARGIN + x * COLUMN, y });
      row.set(node.id, y + h / 2);
      y += h + ROW_GAP;
    }
  });
  return positions;
}

/** The network with its nodes at the arranged positions. */
export function arranged(
  network: FbdNetwork,
  height: (node: FbdNode) => number,
  order: readonly string[] | null = null,
): FbdNetwork {
  const positions = arrange(network, height, order);
  return { ...network, nodes: nodesOf(network).map((n) => ({ ...n, pos: positions.get(n.id) ?? n.pos ?? null })) };
}
