// Online FBD: which probes and variable paths the shown networks need, and what each wire and
// node shows. Values come from the engine's probes (docs/diagrams.md "Power-flow probes"):
// `<block>.<PIN>` for every output pin of a block, `<node>` for input, output, jump and return
// nodes; a probe that is null did not execute in the last scan (the block is dimmed).
import type { SymbolInfo } from "../generated/api";
import { operandPath } from "../online/ldBinding";
import { powerKey, type MonitorState } from "../online/monitor";
import type { ElementSubscription, PowerState } from "../online/protocol";
import {
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

export interface FbdBinding {
  instance: string;
  paths: string[];
  elements: ElementSubscription[];
  /** Upper-case operand text -> its path. */
  pathOf: ReadonlyMap<string, string>;
}

/** The probe ids of one node: its output pins (blocks) or the node itself. */
function probesOfNode(
  node: ReturnType<typeof nodesOf>[number],
  network: FbdNetwork,
  lookup: Lookup,
  symbols: readonly SymbolInfo[],
): string[] {
  switch (kindOf(node)) {
    case "block":
      return lookup((node as { call: string }).call)
        ? nodePins(node, network, lookup, symbols).outputs.map((p) => `${node.id}.${p.name.toUpperCase()}`)
        : [];
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
): FbdBinding {
  const pathOf = new Map<string, string>();
  const ids: string[] = [];
  for (const network of networksOf(body)) {
    if (networks && !networks.has(network.id)) continue;
    for (const node of nodesOf(network)) {
      ids.push(...probesOfNode(node, network, lookup, symbols));
      const operand = operandOf(node);
      const path = operand ? operandPath(operand, instance, symbols) : null;
      if (operand && path) pathOf.set(operand.toUpperCase(), path);
    }
  }
  return {
    instance,
    paths: [...new Set(pathOf.values())],
    elements: ids.length ? [{ pou_instance: instance, ids }] : [],
    pathOf,
  };
}

/** What the FBD diagram shows online: probe values by id (null: not executed), forced operands. */
export interface FbdOnlineView {
  probes: Readonly<Record<string, PowerState>>;
  forced: ReadonlySet<string>;
}

export function fbdOnlineView(monitor: MonitorState, binding: FbdBinding): FbdOnlineView {
  const probes: Record<string, PowerState> = {};
  for (const { pou_instance, ids } of binding.elements) {
    for (const id of ids ?? []) {
      const state = monitor.power[powerKey(pou_instance, id)];
      if (state !== undefined) probes[id] = state;
    }
  }
  const forced = new Set<string>();
  for (const [operand, path] of binding.pathOf) if (monitor.forced.has(path)) forced.add(operand);
  return { probes, forced };
}

/** Whether a block ran in the last scan: any of its probes holds a value (none known: assume it did). */
export function executed(view: FbdOnlineView, nodeId: string): boolean {
  const states = Object.entries(view.probes).filter(([id]) => id === nodeId || id.startsWith(`${nodeId}.`));
  return states.length === 0 || states.some(([, v]) => v !== null);
}
