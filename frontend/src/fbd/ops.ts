// Pure edits of an FBD body: each returns the new body and what to select, or the reason it is
// refused (shown to the user). Bodies are never mutated, so undo keeps the old ones as they were.
import type { SymbolInfo } from "../generated/api";
import { freshId } from "../ld/ids";
import { arranged } from "./arrange";
import { ordered } from "./order";
import { refusal, type Connection } from "./compat";
import {
  findNode,
  kindOf,
  networksOf,
  nextInput,
  nodesOf,
  samePin,
  wiresOf,
  type Block,
  type FbdBody,
  type FbdNetwork,
  type FbdNode,
  type Lookup,
  type OutputMode,
  type PinRef,
  type Position,
  type Wire,
} from "./model";

export type EditResult =
  { ok: true; body: FbdBody; /** node or network ids to select */ select: string[] } | { ok: false; error: string };

const fail = (error: string): EditResult => ({ ok: false, error });
const done = (body: FbdBody, select: string[]): EditResult => ({ ok: true, body, select });

/** Id prefixes of new nodes: readable ids in the saved JSON. */
export const PREFIX: Record<NonNullable<FbdNode["type"]>, string> = {
  block: "blk",
  input: "in",
  output: "out",
  jump: "jump",
  return: "ret",
  label: "label",
  connector: "con",
  continuation: "cont",
  comment: "note",
};

/** Every id of the body: networks and nodes (node ids are probe ids, unique in the POU). */
export function usedIds(body: FbdBody): Set<string> {
  const ids = new Set(networksOf(body).map((n) => n.id));
  for (const network of networksOf(body)) for (const node of nodesOf(network)) ids.add(node.id);
  return ids;
}

function updateNetwork(body: FbdBody, id: string, update: (n: FbdNetwork) => FbdNetwork): FbdBody {
  return { ...body, networks: networksOf(body).map((n) => (n.id === id ? update(n) : n)) };
}

function updateNode(body: FbdBody, id: string, update: (n: FbdNode) => FbdNode): FbdBody | null {
  const at = findNode(body, id);
  if (!at) return null;
  return updateNetwork(body, at.network.id, (n) => ({
    ...n,
    nodes: nodesOf(n).map((node) => (node.id === id ? update(node) : node)),
  }));
}

// ------------------------------------------------------------------ networks

export function addNetwork(body: FbdBody, index = networksOf(body).length): EditResult {
  const id = freshId("n", usedIds(body));
  const networks = [...networksOf(body)];
  networks.splice(index, 0, { id, nodes: [], wires: [] });
  return done({ ...body, networks }, [id]);
}

export function deleteNetworks(body: FbdBody, ids: readonly string[]): EditResult {
  return done({ ...body, networks: networksOf(body).filter((n) => !ids.includes(n.id)) }, []);
}

export function moveNetwork(body: FbdBody, id: string, delta: -1 | 1): EditResult {
  const networks = [...networksOf(body)];
  const at = networks.findIndex((n) => n.id === id);
  const to = at + delta;
  if (at < 0 || to < 0 || to >= networks.length)
    return fail(delta < 0 ? "This is the first network." : "This is the last network.");
  [networks[at], networks[to]] = [networks[to]!, networks[at]!];
  return done({ ...body, networks }, [id]);
}

export function setNetworkText(body: FbdBody, id: string, field: "label" | "comment", text: string): EditResult {
  const value = text.trim() ? (field === "label" ? text.trim() : text) : null;
  return done(
    updateNetwork(body, id, (n) => ({ ...n, [field]: value })),
    [id],
  );
}

// ------------------------------------------------------------------ nodes

export type NodeSpec =
  | { type: "block"; call: string; instance?: string | null; en?: boolean }
  | { type: "input"; expr?: string }
  | { type: "output"; var?: string; mode?: OutputMode }
  | { type: "jump"; target?: string }
  | { type: "return" }
  | { type: "label"; name?: string }
  | { type: "connector"; name?: string }
  | { type: "continuation"; name?: string }
  | { type: "comment"; text?: string };

function nodeOf(spec: NodeSpec, id: string, pos: Position): FbdNode {
  switch (spec.type) {
    case "block":
      return {
        type: "block",
        id,
        pos,
        call: spec.call,
        ...(spec.instance ? { instance: spec.instance } : {}),
        ...(spec.en ? { en: true } : {}),
      };
    case "input":
      return { type: "input", id, pos, expr: spec.expr ?? "" };
    case "output":
      return {
        type: "output",
        id,
        pos,
        var: spec.var ?? "",
        ...(spec.mode && spec.mode !== "normal" ? { mode: spec.mode } : {}),
      };
    case "jump":
      return { type: "jump", id, pos, target: spec.target ?? "" };
    case "return":
      return { type: "return", id, pos };
    case "label":
      return { type: "label", id, pos, name: spec.name ?? "" };
    case "connector":
    case "continuation":
      return { type: spec.type, id, pos, name: spec.name ?? "" };
    case "comment":
      return { type: "comment", id, pos, text: spec.text ?? "" };
  }
}

export function addNode(body: FbdBody, network: string, spec: NodeSpec, pos: Position): EditResult {
  if (!networksOf(body).some((n) => n.id === network)) return fail(`There is no network ${network}.`);
  const id = freshId(PREFIX[spec.type], usedIds(body));
  return done(
    updateNetwork(body, network, (n) => ({ ...n, nodes: [...nodesOf(n), nodeOf(spec, id, pos)] })),
    [id],
  );
}

/** Removes nodes, their wires and their places in the order list. */
export function deleteNodes(body: FbdBody, ids: readonly string[]): EditResult {
  const gone = new Set(ids);
  const networks = networksOf(body).map((n) => {
    if (!nodesOf(n).some((node) => gone.has(node.id))) return n;
    const order = n.order?.filter((id) => !gone.has(id));
    return {
      ...n,
      nodes: nodesOf(n).filter((node) => !gone.has(node.id)),
      wires: wiresOf(n).filter((w) => !gone.has(w.from.node) && !gone.has(w.to.node)),
      ...(n.order ? { order: order?.length ? order : null } : {}),
    };
  });
  return done({ ...body, networks }, []);
}

/** New positions (layout hints) for nodes, e.g. after a drag. */
export function moveNodes(body: FbdBody, positions: ReadonlyMap<string, Position>): EditResult {
  const networks = networksOf(body).map((n) =>
    nodesOf(n).some((node) => positions.has(node.id))
      ? {
          ...n,
          nodes: nodesOf(n).map((node) => (positions.has(node.id) ? { ...node, pos: positions.get(node.id)! } : node)),
        }
      : n,
  );
  return done({ ...body, networks }, [...positions.keys()]);
}

/** The text of a node: an input's operand, an output's variable, a jump's target, a connector's or a CFC label's
 * name, a block's instance, a comment's text. */
export function setNodeText(body: FbdBody, id: string, text: string): EditResult {
  const value = text.trim();
  const next = updateNode(body, id, (node) => {
    switch (kindOf(node)) {
      case "input":
        return { ...node, expr: value };
      case "output":
        return { ...node, var: value };
      case "jump":
        return { ...node, target: value };
      case "connector":
      case "continuation":
      case "label":
        return { ...node, name: value };
      case "block":
        return { ...node, instance: value || null };
      case "comment":
        return { ...node, text: text.replace(/\s+$/, "") }; // a comment keeps its line breaks and indentation
      default:
        return node;
    }
  });
  return next ? done(next, [id]) : fail(`There is no node ${id}.`);
}

export function setOutputMode(body: FbdBody, id: string, mode: OutputMode): EditResult {
  const at = findNode(body, id);
  if (!at || kindOf(at.node) !== "output") return fail("Only output nodes have a mode.");
  return done(
    updateNode(body, id, (n) => ({ ...n, mode }))!,
    [id],
  );
}

/** EN/ENO on a block; switching them off drops the wires on EN and ENO. */
export function toggleEn(body: FbdBody, id: string): EditResult {
  const at = findNode(body, id);
  if (!at || kindOf(at.node) !== "block") return fail("Only blocks have EN/ENO.");
  const on = !(at.node as Block).en;
  const next = updateNetwork(body, at.network.id, (n) => ({
    ...n,
    nodes: nodesOf(n).map((node) => (node.id === id ? { ...node, en: on } : node)),
    wires: on
      ? wiresOf(n)
      : wiresOf(n).filter(
          (w) =>
            !(w.to.node === id && w.to.pin.toUpperCase() === "EN") &&
            !(w.from.node === id && w.from.pin.toUpperCase() === "ENO"),
        ),
  }));
  return done(next, [id]);
}

/** One more input on an extensible block (ADD, AND, MUX, ...): the pin exists once the model names it. */
export function addInput(body: FbdBody, id: string, lookup: Lookup): EditResult {
  const at = findNode(body, id);
  if (!at || kindOf(at.node) !== "block") return fail("Only blocks have inputs to add.");
  const block = at.node as Block;
  const pin = nextInput(block, lookup(block.call), wiresOf(at.network));
  if (!pin) return fail(`${block.call} takes a fixed number of inputs.`);
  return done(
    updateNode(body, id, (n) => ({ ...n, pins: { ...(n as Block).pins, [pin]: { negated: false } } }))!,
    [id],
  );
}

export type PinFlag = "negated" | "rising" | "falling";

/**
 * Toggles a pin's negation bubble or edge marker (rising/falling exclude each other). Edges exist
 * on inputs only (an edge on an output is FBD-PIN-FLAG); flags live on blocks.
 */
export function togglePinFlag(body: FbdBody, id: string, pin: string, flag: PinFlag, side: "in" | "out"): EditResult {
  const at = findNode(body, id);
  if (!at || kindOf(at.node) !== "block") return fail("Negation and edge markers go on block pins.");
  if (flag !== "negated" && side === "out") return fail("Edge detection applies to inputs only.");
  const block = at.node as Block;
  const current = block.pins?.[pin] ?? {};
  const next =
    flag === "negated"
      ? { ...current, negated: !current.negated }
      : { ...current, edge: current.edge === flag ? null : flag };
  const flags = { ...block.pins, [pin]: { negated: next.negated ?? false, ...(next.edge ? { edge: next.edge } : {}) } };
  return done(
    updateNode(body, id, (n) => ({ ...n, pins: flags }))!,
    [id],
  );
}

// ------------------------------------------------------------------ wires

/** Adds a wire when the editor accepts it (type-compatible, into a free input). */
export function connect(
  body: FbdBody,
  network: string,
  c: Connection,
  lookup: Lookup,
  symbols: readonly SymbolInfo[],
): EditResult {
  const net = networksOf(body).find((n) => n.id === network);
  if (!net) return fail(`There is no network ${network}.`);
  const why = refusal(net, c, lookup, symbols);
  if (why) return fail(why);
  const wire: Wire = { from: { ...c.from }, to: { ...c.to } };
  return done(
    updateNetwork(body, network, (n) => ({ ...n, wires: [...wiresOf(n), wire] })),
    [c.to.node],
  );
}

export function disconnect(body: FbdBody, network: string, wires: readonly Wire[]): EditResult {
  const gone = (w: Wire) => wires.some((x) => samePin(x.from, w.from) && samePin(x.to, w.to));
  return done(
    updateNetwork(body, network, (n) => ({ ...n, wires: wiresOf(n).filter((w) => !gone(w)) })),
    [],
  );
}

/** The wires ending at (`side` "in") or starting from (`side` "out") one pin. */
export function wiresAt(network: FbdNetwork, ref: PinRef, side: "in" | "out"): Wire[] {
  return wiresOf(network).filter((w) => samePin(side === "in" ? w.to : w.from, ref));
}

/**
 * Auto-arrange one network. `order` is the evaluation order the backend reported: it is stored as
 * the network's order list (blocks and outputs), so moving nodes cannot change what runs first.
 */
export function arrangeNetwork(
  body: FbdBody,
  network: string,
  height: (node: FbdNode) => number,
  order: readonly string[] | null,
  chart = false,
): EditResult {
  const net = networksOf(body).find((n) => n.id === network);
  if (!net) return fail(`There is no network ${network}.`);
  const laid = arranged(net, height, order);
  // the order pinned: a chart's execution order numbers (returns too) stay as they were
  const kept = order?.filter((id) => ordered(net, id, chart));
  const next = kept?.length ? { ...laid, order: kept } : laid;
  return done(
    updateNetwork(body, network, () => next),
    [network],
  );
}
