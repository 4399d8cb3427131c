// Auto-arrange: a network laid out left to right in layers by data flow (a node one column right
// of everything feeding it, inputs just left of their first consumer), rows ordered by the rows of
// their sources so wires cross little. Positions are hints, but they break ties in the execution
// order where the wiring leaves it open; ops.arrangeNetwork therefore pins the order first.
import { kindOf, nodesOf, wiresOf, type FbdNetwork, type FbdNode, type Position } from "./model";

export const COLUMN = 220;
export const ROW_GAP = 30;
const MARGIN = 20;

/** Longest-path layers over the wires; a wire closing a cycle (feedback) is ignored. */
function layers(network: FbdNetwork): Map<string, number> {
  const preds = new Map<string, string[]>(nodesOf(network).map((n) => [n.id, []]));
  for (const w of wiresOf(network)) preds.get(w.to.node)?.push(w.from.node);
  const layer = new Map<string, number>();
  const visiting = new Set<string>();
  const visit = (id: string): number => {
    const known = layer.get(id);
    if (known !== undefined) return known;
    if (visiting.has(id)) return -1; // a feedback wire: does not push the node right
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

/** Positions for every node of `network`; `height` gives a node's drawn height. */
export function arrange(network: FbdNetwork, height: (node: FbdNode) => number): Map<string, Position> {
  const layer = layers(network);
  const columns: FbdNode[][] = [];
  for (const node of nodesOf(network)) (columns[layer.get(node.id) ?? 0] ??= []).push(node);
  const row = new Map<string, number>(); // centre y of placed nodes
  const positions = new Map<string, Position>();
  const sources = new Map<string, string[]>();
  for (const w of wiresOf(network)) sources.set(w.to.node, [...(sources.get(w.to.node) ?? []), w.from.node]);
  const consumers = new Map<string, string[]>();
  for (const w of wiresOf(network)) consumers.set(w.from.node, [...(consumers.get(w.from.node) ?? []), w.to.node]);
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
export function arranged(network: FbdNetwork, height: (node: FbdNode) => number): FbdNetwork {
  const positions = arrange(network, height);
  return { ...network, nodes: nodesOf(network).map((n) => ({ ...n, pos: positions.get(n.id) ?? n.pos ?? null })) };
}
