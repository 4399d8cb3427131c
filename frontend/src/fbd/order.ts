// Changing the execution order where the wiring leaves it open (the network's `order` list,
// docs/diagrams.md "Evaluation order"): "run earlier/later" swaps a block or output node with its
// neighbour in the order the lowering reports, unless one feeds the other - data flow always wins.
// On a CFC chart (docs/diagrams.md "CFC") the order list is the order: every executed element
// (blocks, outputs, jumps, labels, returns) moves freely, and a wire against the order carries the previous scan.
import { kindOf, networksOf, nodesOf, wiresOf, type FbdBody, type FbdNetwork, type PinRef } from "./model";
import type { EditResult } from "./ops";

/**
 * Elements with an execution order number on a CFC chart (inputs are read where they are used): model/fbd.py's
 * EXECUTED_ELEMENTS, checked against iec.json by order.test.ts (read from there, the whole vocabulary would load
 * with the project tree).
 */
export const EXECUTED: ReadonlySet<string> = new Set(["block", "output", "jump", "label", "return"]);

/** Nodes whose place the `order` list decides (inputs follow their consumer; in FBD jumps and returns run last). */
export const ordered = (network: FbdNetwork, id: string, chart = false): boolean => {
  const node = nodesOf(network).find((n) => n.id === id);
  if (node === undefined) return false;
  return chart ? EXECUTED.has(kindOf(node)) : kindOf(node) === "block" || kindOf(node) === "output";
};

/** A chart's execution order numbers (CFC-02): node id -> 1, 2, ... over its executed elements in `order`. */
export function orderNumbers(network: FbdNetwork, order: readonly string[]): Map<string, number> {
  const numbers = new Map<string, number>();
  for (const id of order) if (ordered(network, id, true)) numbers.set(id, numbers.size + 1);
  return numbers;
}

/**
 * The input pins fed over a feedback wire, by the execution order the backend reported (`order`): a wire from
 * an element that runs at the same place or later (a loop in FBD, a wire against the numbers in CFC). They read
 * the previous scan's value; the engine records what they read (probe `<block>.<PIN>`). Keys `<node>/in:<PIN>`.
 */
export function feedbackPins(network: FbdNetwork, order: readonly string[]): Set<string> {
  const numbers = orderNumbers(network, order);
  const found = new Set<string>();
  for (const wire of wiresOf(network)) {
    const from = numbers.get(wire.from.node);
    const to = numbers.get(wire.to.node);
    if (from !== undefined && to !== undefined && from >= to)
      found.add(`${wire.to.node}/in:${wire.to.pin.toUpperCase()}`);
  }
  return found;
}

/**
 * "Order by data flow" on a chart: its executed elements in `flow`, the FBD order the backend reported. A chart with
 * jumps or labels keeps them at their numbers (`current`, the chart's order): the data flow orders the elements
 * between two of them only, so no element changes side of a jump or label (which would change what is skipped).
 */
export function orderByDataFlow(
  body: FbdBody,
  networkId: string,
  flow: readonly string[],
  current: readonly string[] = [],
): EditResult {
  const network = networksOf(body).find((n) => n.id === networkId);
  if (!network) return { ok: false, error: `There is no network ${networkId}.` };
  let order = flow.filter((id) => ordered(network, id, true));
  const fixed = new Set(
    nodesOf(network)
      .filter((n) => kindOf(n) === "jump" || kindOf(n) === "label")
      .map((n) => n.id),
  );
  const numbered = current.filter((id) => ordered(network, id, true));
  if (fixed.size && numbered.length === order.length) {
    const place = new Map(order.map((id, i) => [id, i]));
    const segments: string[][] = [[]];
    for (const id of numbered) {
      if (fixed.has(id)) segments.push([id], []);
      else segments[segments.length - 1]!.push(id);
    }
    order = segments.flatMap((s) =>
      s.length === 1 && fixed.has(s[0]!) ? s : s.sort((a, b) => place.get(a)! - place.get(b)!),
    );
  }
  const networks = networksOf(body).map((n) => (n.id === networkId ? { ...n, order } : n));
  return { ok: true, body: { ...body, networks }, select: [] };
}

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
 * On a `chart` (CFC) returns and jumps move too, and a move against the wiring is allowed.
 */
export function moveInOrder(
  body: FbdBody,
  networkId: string,
  order: readonly string[],
  id: string,
  delta: -1 | 1,
  chart = false,
): EditResult {
  const network = networksOf(body).find((n) => n.id === networkId);
  if (!network) return { ok: false, error: `There is no network ${networkId}.` };
  if (!ordered(network, id, chart))
    return {
      ok: false,
      error: chart
        ? "Inputs have no execution order number: they are read where their consumer runs."
        : "Only blocks and output nodes have an order to change: inputs run just before their first consumer, jumps and returns last.",
    };
  const sequence = order.filter((n) => ordered(network, n, chart));
  const at = sequence.indexOf(id);
  if (at < 0) return { ok: false, error: "The execution order is not known yet; try again in a moment." };
  const other = sequence[at + delta];
  if (other === undefined)
    return { ok: false, error: delta < 0 ? `${id} already runs first.` : `${id} already runs last.` };
  const [first, second] = delta < 0 ? [other, id] : [id, other];
  if (!chart && feeds(network, first, second))
    return { ok: false, error: `${first} feeds ${second}: data flow makes ${first} run first.` };
  const next = [...sequence];
  [next[at], next[at + delta]] = [next[at + delta]!, next[at]!];
  const networks = networksOf(body).map((n) => (n.id === networkId ? { ...n, order: next } : n));
  return { ok: true, body: { ...body, networks }, select: [id] };
}
