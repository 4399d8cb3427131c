// FBD <-> CFC from the POU's menu (issue 26, docs/diagrams.md "CFC"). FBD -> CFC stacks the networks on one
// chart, top to bottom, and numbers the elements in the order the FBD ran them (each network's evaluation
// order, one network after the other), so the chart runs exactly as the networks did. CFC -> FBD makes the
// chart one network, only when its numbers are the data-flow order: FBD cannot run an element before the
// block feeding it, so any other chart would change behaviour.
import { kindOf, networksOf, nodesOf, type FbdBody, type FbdNetwork, type FbdNode } from "./model";
import { ordered } from "./order";

export type Converted = { ok: true; body: FbdBody } | { ok: false; error: string };

/** The vertical room between two stacked networks on the chart (px). */
const GAP = 40;

/** The executed elements of `order` (those with a chart number). */
const executed = (network: FbdNetwork, order: readonly string[]) => order.filter((id) => ordered(network, id, true));

/** What a message calls an element. */
function named(node: FbdNode): string {
  const n = node as { call?: string; var?: string; instance?: string | null };
  if (kindOf(node) === "block") return n.instance ? `${n.call} ${n.instance}` : (n.call ?? node.id);
  return kindOf(node) === "output" ? `output ${n.var}` : node.id;
}

/**
 * An FBD body as one CFC chart. `orders`: each network's evaluation order as the backend reports it
 * (POST /api/fbd/order); `heightOf`: a network's drawn height. Refused: a jump (a chart has no networks to
 * jump to) and a connector name used in two networks (a chart is one scope).
 */
export function fbdToCfc(
  body: FbdBody,
  orders: ReadonlyMap<string, readonly string[]>,
  heightOf: (network: FbdNetwork) => number,
): Converted {
  const nodes: FbdNode[] = [];
  const wires: NonNullable<FbdNetwork["wires"]> = [];
  const order: string[] = [];
  const connectors = new Map<string, number>();
  let top = 0;
  for (const [index, network] of networksOf(body).entries()) {
    const number = index + 1;
    const flow = orders.get(network.id);
    if (!flow) return { ok: false, error: `The execution order of network ${number} is not known yet: try again.` };
    for (const node of nodesOf(network)) {
      if (kindOf(node) === "jump")
        return {
          ok: false,
          error: `Network ${number} jumps to ${(node as { target: string }).target}: a CFC chart has no networks to jump to (its jumps go to label elements). Remove the jump first.`,
        };
      if (kindOf(node) === "connector") {
        const name = (node as { name: string }).name.toUpperCase();
        const first = connectors.get(name);
        if (first !== undefined && first !== number)
          return {
            ok: false,
            error: `Networks ${first} and ${number} both have a connector ${(node as { name: string }).name}: on one chart the names must differ. Rename one first.`,
          };
        connectors.set(name, number);
      }
      nodes.push(node.pos ? { ...node, pos: { x: node.pos.x, y: node.pos.y + top } } : node);
    }
    wires.push(...(network.wires ?? []));
    order.push(...executed(network, flow));
    top += heightOf(network) + GAP;
  }
  return { ok: true, body: { networks: [{ id: "chart", nodes, wires, order }] } };
}

/**
 * A CFC chart as one FBD network, when its execution order (`chartOrder`, the numbers) is the order FBD would
 * run it in (`flowOrder`, POST /api/fbd/order without `chart`); otherwise the first element out of place.
 */
export function cfcToFbd(body: FbdBody, chartOrder: readonly string[], flowOrder: readonly string[]): Converted {
  const chart = networksOf(body)[0] ?? { id: "chart" };
  const control = nodesOf(chart).find((n) => kindOf(n) === "jump" || kindOf(n) === "label");
  if (control)
    return {
      ok: false,
      error:
        `The chart has ${kindOf(control) === "jump" ? "a jump" : "a label"}: a chart's jumps go to its label ` +
        `elements, FBD's to whole networks. Remove the jumps and labels first, or keep the chart.`,
    };
  const numbers = executed(chart, chartOrder);
  const flow = executed(chart, flowOrder);
  const at = numbers.findIndex((id, i) => flow[i] !== id);
  if (at >= 0) {
    const node = nodesOf(chart).find((n) => n.id === numbers[at]);
    const expected = nodesOf(chart).find((n) => n.id === flow[at]);
    return {
      ok: false,
      error:
        `The chart runs ${node ? named(node) : numbers[at]} as number ${at + 1}, where data flow would run ` +
        `${expected ? named(expected) : flow[at]}: FBD cannot keep that order. Use "Order by data flow" first ` +
        `(it changes what the chart computes), or keep the chart.`,
    };
  }
  return { ok: true, body: { networks: [{ ...chart, id: "n1", order: flow }] } };
}
