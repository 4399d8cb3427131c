// Online FBD: which probes and variable paths the shown networks need, and what each wire, node
// and block pin shows. Values come from the engine's probes (docs/diagrams.md "Power-flow probes"):
// `<block>.<PIN>` for every output pin of a block, `<node>` for input, output, jump and return
// nodes; a probe that is null did not execute in the last scan (the block is dimmed). Block pins
// are bound as LD boxes are (online/pinValues.ts): an FB instance's from the instance, a
// function's inputs from the wire feeding them, its outputs from their probes.
import type { SymbolInfo } from "../generated/api";
import { operandPath } from "../online/monitor";
import { powerKey, type MonitorState } from "../online/monitor";
import {
  bindBoxPins,
  diagramBinding,
  diagramValues,
  type DiagramBinding,
  type PinBinding,
  type PinSource,
} from "../online/pinValues";
import type { PowerState } from "../online/protocol";
import type { Prepared, ValueShown } from "../online/shown";
import {
  blockEntry,
  findNode,
  kindOf,
  networksOf,
  nodePins,
  nodesOf,
  wiresOf,
  type FbdBody,
  type FbdNetwork,
  type Lookup,
  type PinRef,
} from "./model";

/** The variable operand of a node (an input's expression, an output's variable), if it has one. */
export function operandOf(node: ReturnType<typeof nodesOf>[number]): string | null {
  const kind = kindOf(node);
  const text =
    kind === "input" ? (node as { expr: string }).expr : kind === "output" ? (node as { var: string }).var : "";
  return text.trim() || null;
}

/** The probe id carrying what an output pin produces; continuations carry their connector's input. */
export function probeOf(network: FbdNetwork, ref: PinRef, seen = new Set<string>()): string | null {
  const node = nodesOf(network).find((n) => n.id === ref.node);
  if (!node || seen.has(node.id)) return null;
  seen.add(node.id);
  switch (kindOf(node)) {
    case "block":
      return `${node.id}.${ref.pin.toUpperCase()}`;
    case "input":
      return node.id;
    case "continuation": {
      const name = (node as { name: string }).name.toUpperCase();
      const connector = nodesOf(network).find(
        (n) => kindOf(n) === "connector" && (n as { name: string }).name.toUpperCase() === name,
      );
      const feed = connector && wiresOf(network).find((w) => w.to.node === connector.id);
      return feed ? probeOf(network, feed.from, seen) : null;
    }
    default:
      return null;
  }
}

/** The node a probe id belongs to (`blk2.OUT` -> `blk2`; a halt names the probe it stopped at). */
export function nodeOfProbe(body: FbdBody, probe: string): string {
  if (findNode(body, probe)) return probe;
  const dot = probe.lastIndexOf(".");
  return dot > 0 && findNode(body, probe.slice(0, dot)) ? probe.slice(0, dot) : probe;
}

/** What an FBD view subscribes and how the values map back onto its nodes and blocks. */
export type FbdBinding = DiagramBinding;

/** A block's pins online: its FB instance's, or what the wires feed a function's inputs and its output probes. */
function bindBlock(
  node: ReturnType<typeof nodesOf>[number],
  network: FbdNetwork,
  lookup: Lookup,
  symbols: readonly SymbolInfo[],
  path: (operand: string) => string | null,
  feedback: ReadonlySet<string>,
): PinBinding[] {
  const block = node as { id: string; call: string; instance?: string | null };
  const { inputs, outputs } = nodePins(node, network, lookup, symbols);
  const pins = [
    ...inputs.map((p) => ({ side: "in" as const, name: p.name, type: p.type })),
    ...outputs.map((p) => ({ side: "out" as const, name: p.name, type: p.type })),
  ];
  const instance = block.instance?.trim() ? path(block.instance) : null;
  return bindBoxPins(blockEntry(block.call, lookup, symbols), instance, pins, (pin): PinSource => {
    if (pin.side === "out") return { probe: `${block.id}.${pin.name.toUpperCase()}` };
    const wire = wiresOf(network).find(
      (w) => w.to.node === block.id && w.to.pin.toUpperCase() === pin.name.toUpperCase(),
    );
    const probe = wire ? probeOf(network, wire.from) : null;
    if (!probe) return null;
    const source = nodesOf(network).find((n) => n.id === wire!.from.node);
    const operand = source && kindOf(source) === "input" ? operandOf(source) : null;
    const read = feedback.has(`${block.id}/in:${pin.name.toUpperCase()}`) ? readProbe(block.id, pin.name) : undefined;
    return { probe, read, typeOf: (operand && path(operand)) ?? undefined };
  });
}

/** The probe of what a block's input read over a feedback wire (the previous scan's value, lower_fbd.py). */
const readProbe = (block: string, pin: string) => `${block}.${pin.toUpperCase()}`;

/** The probe ids of one node: its output pins and feedback inputs (blocks), or the node itself. */
function probesOfNode(
  node: ReturnType<typeof nodesOf>[number],
  network: FbdNetwork,
  lookup: Lookup,
  symbols: readonly SymbolInfo[],
  feedback: ReadonlySet<string>,
): string[] {
  switch (kindOf(node)) {
    case "block": {
      if (!blockEntry((node as { call: string }).call, lookup, symbols)) return [];
      const looped = wiresOf(network).filter((w) => feedback.has(`${node.id}/in:${w.to.pin.toUpperCase()}`));
      return [
        ...nodePins(node, network, lookup, symbols).outputs.map((p) => `${node.id}.${p.name.toUpperCase()}`),
        ...looped.filter((w) => w.to.node === node.id).map((w) => readProbe(node.id, w.to.pin)),
      ];
    }
    case "input":
    case "output":
    case "jump":
    case "return":
      return [node.id];
    default:
      return [];
  }
}

/** What to subscribe for `networks` (all when undefined) of an FBD body shown for `instance`. */
export function bindFbd(
  body: FbdBody,
  instance: string,
  lookup: Lookup,
  symbols: readonly SymbolInfo[],
  networks?: ReadonlySet<string>,
  /** Input pins fed over feedback wires (`<node>/in:<PIN>`, order.ts feedbackPins): they show what they read. */
  feedback: ReadonlySet<string> = new Set(),
): FbdBinding {
  const pathOf = new Map<string, string>();
  const pins = new Map<string, PinBinding[]>();
  const ids: string[] = [];
  const path = (operand: string) => operandPath(operand, instance, symbols);
  for (const network of networksOf(body)) {
    if (networks && !networks.has(network.id)) continue;
    for (const node of nodesOf(network)) {
      ids.push(...probesOfNode(node, network, lookup, symbols, feedback));
      const operand = operandOf(node);
      const p = operand ? path(operand) : null;
      if (operand && p) pathOf.set(operand.toUpperCase(), p);
      if (kindOf(node) === "block") pins.set(node.id, bindBlock(node, network, lookup, symbols, path, feedback));
    }
  }
  return diagramBinding(instance, ids, pathOf, pins);
}

/**
 * What the FBD diagram shows online: probe values by id (null: not executed; wires and variable
 * nodes), the values of the operands' variables (forced, prepared) and of every block pin.
 */
export interface FbdOnlineView {
  probes: Readonly<Record<string, PowerState>>;
  /** By upper-case operand text. */
  operands: Readonly<Record<string, ValueShown>>;
  /** Block id -> pin key (`in:IN1`, `out:ET`) -> value. */
  pins: Readonly<Record<string, Readonly<Record<string, ValueShown>>>>;
}

export function fbdOnlineView(monitor: MonitorState, binding: FbdBinding, prepared: Prepared = {}): FbdOnlineView {
  // what a block read over a feedback wire is a pin value only: it is read before the block's EN is looked at,
  // so it must not make a block that EN skipped look executed
  const reads = new Set(
    [...binding.pins.values()].flatMap((pins) =>
      pins.flatMap((p) => (p.source && "read" in p.source && p.source.read ? [p.source.read] : [])),
    ),
  );
  const probes: Record<string, PowerState> = {};
  for (const { pou_instance, ids } of binding.elements) {
    for (const id of ids ?? []) {
      const state = monitor.power[powerKey(pou_instance, id)];
      if (state !== undefined && !reads.has(id)) probes[id] = state;
    }
  }
  return { probes, ...diagramValues(monitor, binding, prepared) };
}

/** Whether a block ran in the last scan: any of its probes holds a value (none known: assume it did). */
export function executed(view: FbdOnlineView, nodeId: string): boolean {
  const states = Object.entries(view.probes).filter(([id]) => id === nodeId || id.startsWith(`${nodeId}.`));
  return states.length === 0 || states.some(([, v]) => v !== null);
}
