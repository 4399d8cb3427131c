// Changing the execution order where the wiring leaves it open (the network's `order` list,
// docs/diagrams.md "Evaluation order"): "run earlier/later" swaps a block or output node with its
// neighbour in the order the lowering reports, unless one feeds the other - data flow always wins.
import { kindOf, networksOf, nodesOf, wiresOf, type FbdBody, type FbdNetwork, type PinRef } from "./model";
import type { EditResult } from "./ops";

/** Nodes whose place the `order` list decides (inputs follow their consumer, jumps and returns run last). */
const ordered = (network: FbdNetwork, id: string): boolean => {
  const node = nodesOf(network).find((n) => n.id === id);
  return node !== undefined && (kindOf(node) === "block" || kindOf(node) === "output");
};

/** The node really producing what `ref` carries: a continuation stands for the wire into its connector. */
function producer(network: FbdNetwork, ref: PinRef, seen = new Set<string>()): string | undefined {
  const node = nodesOf(network).find((n) => n.id === ref.node);
  if (!node || kindOf(node) !== "continuation") return node?.id;
  if (seen.has(node.id)) return undefined;
  seen.add(node.id);
  const name = (node as { name: string }).name.toUpperCase();
  const connector = nodesOf(network).find(
    (n) => kindOf(n) === "connector" && (n as { name: string }).name.toUpperCase() === name,
  );
  const feed = connector && wiresOf(network).find((w) => w.to.node === connector.id);
  return feed ? producer(network, feed.from, seen) : undefined;
}

/** Whether node `a` feeds node `b` through a wire (following connectors). */
export function feeds(network: FbdNetwork, a: string, b: string): boolean {
  return wiresOf(network).some((w) => w.to.node === b && producer(network, w.from) === a);
}

/**
 * Moves `id` one place earlier (-1) or later (+1) among the blocks and output nodes of `order`
 * (the evaluation order the backend reported) and stores the result as the network's order list.
 */
export function moveInOrder(
  body: FbdBody,
  networkId: string,
  order: readonly string[],
  id: string,
  delta: -1 | 1,
): EditResult {
  const network = networksOf(body).find((n) => n.id === networkId);
  if (!network) return { ok: false, error: `There is no network ${networkId}.` };
  if (!ordered(network, id))
    return {
      ok: false,
      error:
        "Only blocks and output nodes have an order to change: inputs run just before their first consumer, jumps and returns last.",
    };
  const sequence = order.filter((n) => ordered(network, n));
  const at = sequence.indexOf(id);
  if (at < 0) return { ok: false, error: "The execution order is not known yet; try again in a moment." };
  const other = sequence[at + delta];
  if (other === undefined)
    return { ok: false, error: delta < 0 ? `${id} already runs first.` : `${id} already runs last.` };
  const [first, second] = delta < 0 ? [other, id] : [id, other];
  if (feeds(network, first, second))
    return { ok: false, error: `${first} feeds ${second}: data flow makes ${first} run first.` };
  const next = [...sequence];
  [next[at], next[at + delta]] = [next[at + delta]!, next[at]!];
  const networks = networksOf(body).map((n) => (n.id === networkId ? { ...n, order: next } : n));
  return { ok: true, body: { ...body, networks }, select: [id] };
}
