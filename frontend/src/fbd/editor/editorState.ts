// The FBD editor's state machine as plain TypeScript (issue 19, as ld/editor/editorState.ts): the
// selection (nodes and wires of one network, or a whole network), which overlay is open (operand or
// network-text editor, block picker, context menu, shortcut help, value prompt), the message and the
// "declare variable" offer, the networks near the viewport, and the halt place or focus request last
// revealed. FbdEditor renders this state and dispatches the actions; the body and its undo history stay
// with the caller. The pure questions the editor asks of a body (which network new things go into, what
// Delete and Copy take, the type a new variable is offered with, the variable behind a pin) live here too.
import type { LibraryEntry, SymbolInfo } from "../../generated/api";
import type { MenuItem } from "../../ui/MenuList";
import { concrete, undeclared, type VariableDeclaration } from "../../ld/editor/declare";
import type { ValueRequest } from "../../online/ValuePrompt";
import { clipOf, type FbdClip } from "../clipboard";
import { outputType } from "../compat";
import {
  findNode,
  kindOf,
  networksOf,
  nodePins,
  nodesOf,
  wireKey,
  wiresOf,
  type Block,
  type FbdBody,
  type FbdNode,
  type OutputMode,
  type Position,
} from "../model";
import { operandOf } from "../online";
import * as ops from "../ops";
import type { NetworkSelection } from "./NetworkCanvas";

/** Nodes and wires selected in one network. */
export type FbdSelection = NetworkSelection & { network: string };

/** A place to reveal: a halt or a clicked diagnostic, by element or by network. */
export interface FbdPlace {
  network?: string | null;
  element?: string | null;
}

export interface FbdEditorState {
  selection: FbdSelection | null;
  /** A whole network is selected (its header was clicked); never together with `selection`. */
  networkSelected: string | null;
  /** The node whose text (operand, instance, comment) is being edited. */
  editing: string | null;
  networkText: { network: string; field: "label" | "comment" } | null;
  /** The block picker is open; where the block goes (null: the target network, a free spot). */
  picker: { network: string | null; pos: Position | null } | null;
  menu: { x: number; y: number; groups: MenuItem[][] } | null;
  message: string | null;
  offer: VariableDeclaration | null;
  valuePrompt: ValueRequest | null;
  help: boolean;
  /** Networks near the viewport (only those are online and get order badges). */
  near: ReadonlySet<string>;
  /** The halt place and focus request last acted on, and the network to scroll to for them. */
  revealed: { halt: string | null; focus: number | null; network: string | null };
  /** Counts "Zoom to fit" requests; each canvas fits its network to a new one (NetworkCanvas). */
  fitRequest: number;
}

export const INITIAL_STATE: FbdEditorState = {
  selection: null,
  networkSelected: null,
  editing: null,
  networkText: null,
  picker: null,
  menu: null,
  message: null,
  offer: null,
  valuePrompt: null,
  help: false,
  near: new Set(),
  revealed: { halt: null, focus: null, network: null },
  fitRequest: 0,
};

type PinChange = { id: string; selected: boolean };

export type FbdEditorAction =
  | { type: "select"; selection: FbdSelection | null }
  | { type: "selectNetwork"; network: string | null }
  /** xyflow's selection changes in one network's canvas (another canvas letting go keeps its selection). */
  | { type: "selectChanges"; network: string; nodes: readonly PinChange[]; edges: readonly PinChange[] }
  /** An edit's outcome: its error as the message, or its new nodes (or network) selected. */
  | { type: "edited"; result: ops.EditResult }
  /** Escape: no selection, no menu. */
  | { type: "clear" }
  | { type: "edit"; id: string | null }
  | { type: "networkText"; text: FbdEditorState["networkText"] }
  | { type: "picker"; at: FbdEditorState["picker"] }
  | { type: "menu"; menu: FbdEditorState["menu"] }
  | { type: "message"; text: string | null }
  | { type: "offer"; offer: VariableDeclaration | null }
  | { type: "valuePrompt"; request: ValueRequest | null }
  | { type: "help"; open: boolean | "toggle" }
  | { type: "near"; network: string; near: boolean }
  | { type: "fit" }
  /**
   * A new halt place (`haltKey` changed) or focus request (`focus.seq` changed) selects its place in
   * `body`, once; the halt wins when both are new.
   */
  | {
      type: "reveal";
      halt: { key: string | null; place: FbdPlace | null | undefined };
      focus: (FbdPlace & { seq: number }) | null | undefined;
      body: FbdBody;
    };

/** Whether a reveal action carries anything new (the component dispatches it while rendering only then). */
export function revealPending(state: FbdEditorState, haltKey: string | null, focusSeq: number | null): boolean {
  return haltKey !== state.revealed.halt || focusSeq !== state.revealed.focus;
}

function selectChanges(state: FbdEditorState, action: Extract<FbdEditorAction, { type: "selectChanges" }>) {
  const { network, nodes, edges } = action;
  const current = state.selection;
  const base = current?.network === network ? current : { network, nodes: [], edges: [] };
  const nextNodes = new Set(base.nodes);
  const nextEdges = new Set(base.edges);
  for (const c of nodes) {
    if (c.selected) nextNodes.add(c.id);
    else nextNodes.delete(c.id);
  }
  for (const c of edges) {
    if (c.selected) nextEdges.add(c.id);
    else nextEdges.delete(c.id);
  }
  const selection =
    !nextNodes.size && !nextEdges.size
      ? current?.network === network
        ? null
        : current // another network's canvas letting go
      : { network, nodes: [...nextNodes], edges: [...nextEdges] };
  const picked = nodes.some((c) => c.selected) || edges.some((c) => c.selected);
  return { ...state, selection, networkSelected: picked ? null : state.networkSelected };
}

function edited(state: FbdEditorState, result: ops.EditResult): FbdEditorState {
  if (!result.ok) return { ...state, message: result.error };
  const next = { ...state, message: null };
  const [first] = result.select;
  const network =
    first && networksOf(result.body).find((n) => n.id === first || nodesOf(n).some((node) => node.id === first));
  if (network && network.id === first) return { ...next, selection: null, networkSelected: network.id };
  if (network)
    return { ...next, selection: { network: network.id, nodes: result.select, edges: [] }, networkSelected: null };
  return next;
}

function reveal(state: FbdEditorState, action: Extract<FbdEditorAction, { type: "reveal" }>): FbdEditorState {
  const { halt, focus, body } = action;
  const focusSeq = focus?.seq ?? null;
  const place =
    halt.key !== state.revealed.halt && halt.place ? halt.place : focusSeq !== state.revealed.focus ? focus : null;
  const network = place ? ((place.element ? findNode(body, place.element)?.network.id : place.network) ?? null) : null;
  let next: FbdEditorState = { ...state, revealed: { halt: halt.key, focus: focusSeq, network } };
  if (place && network) {
    next = place.element
      ? { ...next, selection: { network, nodes: [place.element], edges: [] } }
      : { ...next, networkSelected: network };
  }
  return next;
}

export function fbdEditorReducer(state: FbdEditorState, action: FbdEditorAction): FbdEditorState {
  switch (action.type) {
    case "select":
      return { ...state, selection: action.selection };
    case "selectNetwork":
      return { ...state, selection: null, networkSelected: action.network };
    case "selectChanges":
      return selectChanges(state, action);
    case "edited":
      return edited(state, action.result);
    case "clear":
      return { ...state, selection: null, networkSelected: null, menu: null };
    case "edit":
      return { ...state, editing: action.id };
    case "networkText":
      return { ...state, networkText: action.text };
    case "picker":
      return { ...state, picker: action.at };
    case "menu":
      return { ...state, menu: action.menu };
    case "message":
      return { ...state, message: action.text };
    case "offer":
      return { ...state, offer: action.offer };
    case "valuePrompt":
      return { ...state, valuePrompt: action.request };
    case "help":
      return { ...state, help: action.open === "toggle" ? !state.help : action.open };
    case "near": {
      if (state.near.has(action.network) === action.near) return state;
      const near = new Set(state.near);
      if (action.near) near.add(action.network);
      else near.delete(action.network);
      return { ...state, near };
    }
    case "reveal":
      return reveal(state, action);
    case "fit":
      return { ...state, fitRequest: state.fitRequest + 1 };
  }
}

/** The network new things (palette, picker, paste, arrange) go into: the selected one, else the last. */
export function targetNetwork(state: FbdEditorState, body: FbdBody): string | null {
  const networks = networksOf(body);
  return state.selection?.network ?? state.networkSelected ?? networks[networks.length - 1]?.id ?? null;
}

/** The network the toolbar's network commands act on: the selected one or the selection's (-1: none). */
export function selectedNetworkIndex(state: FbdEditorState, body: FbdBody): number {
  return networksOf(body).findIndex((n) => n.id === (state.networkSelected ?? state.selection?.network));
}

/** What Delete does: the selected nodes with the selected wires cut first, else the selected network; null: nothing. */
export function deletion(state: FbdEditorState, body: FbdBody): ops.EditResult | null {
  const { selection, networkSelected } = state;
  if (selection && (selection.nodes.length || selection.edges.length)) {
    const network = networksOf(body).find((n) => n.id === selection.network);
    const cut = network ? wiresOf(network).filter((w) => selection.edges.includes(wireKey(w))) : [];
    const withoutWires = cut.length
      ? ops.disconnect(body, selection.network, cut)
      : ({ ok: true, body, select: [] } as ops.EditResult);
    return withoutWires.ok ? ops.deleteNodes(withoutWires.body, selection.nodes) : withoutWires;
  }
  return networkSelected ? ops.deleteNetworks(body, [networkSelected]) : null;
}

/** What Copy takes: the selected nodes with the wires between them; null when no node is selected. */
export function clipOfSelection(state: FbdEditorState, body: FbdBody): FbdClip | null {
  const { selection } = state;
  const network = selection && networksOf(body).find((n) => n.id === selection.network);
  if (!network || !selection?.nodes.length) return null;
  return clipOf(network, selection.nodes);
}

/** The node F9 and the toolbar's "Run earlier/later" act on: the one selected node. */
export function singleNode(state: FbdEditorState): string | undefined {
  const nodes = state.selection?.nodes ?? [];
  return nodes.length === 1 ? nodes[0] : undefined;
}

/** What F9 toggles: the one selected node, else the selected network (or the selection's network). */
export function breakpointTarget(state: FbdEditorState): { element: string } | { network: string } | null {
  const element = singleNode(state);
  if (element) return { element };
  const network = state.networkSelected ?? state.selection?.network;
  return network ? { network } : null;
}

type Lookup = (call: string) => LibraryEntry | undefined;

/**
 * The type a new variable typed into node `id` is offered with: a block's instance is of the block's
 * type; an output's is what feeds it (BOOL for a set/reset/negated coil-like output); an input's is the
 * pin it feeds.
 */
export function guessType(body: FbdBody, id: string, lookup: Lookup, symbols: readonly SymbolInfo[]): string {
  const at = findNode(body, id);
  if (!at) return "BOOL";
  const { network, node } = at;
  if (kindOf(node) === "block") return (node as Block).call;
  if (kindOf(node) === "output") {
    if (((node as { mode?: OutputMode }).mode ?? "normal") !== "normal") return "BOOL";
    const feed = wiresOf(network).find((w) => w.to.node === id);
    const type = feed ? outputType(network, feed.from, lookup, symbols) : undefined;
    return type ? concrete(type === "ANY_LITERAL_INT" ? "ANY_INT" : type) : "BOOL";
  }
  const use = wiresOf(network).find((w) => w.from.node === id);
  const consumer = use && nodesOf(network).find((n) => n.id === use.to.node);
  const pin =
    consumer &&
    nodePins(consumer, network, lookup, symbols).inputs.find((p) => p.name.toUpperCase() === use.to.pin.toUpperCase());
  return pin?.type ? concrete(pin.type) : "BOOL";
}

/** The variable behind a block pin: the FB instance's pin, or the input node wired to it. */
export function pinOperand(
  body: FbdBody,
  block: Block,
  side: "in" | "out",
  pin: string,
  lookup: Lookup,
): string | null {
  const entry = lookup(block.call);
  const declared = entry
    ? [...entry.inputs, ...entry.in_outs, ...entry.outputs].some((p) => p.name.toUpperCase() === pin.toUpperCase())
    : false;
  if (entry?.kind === "function_block" && block.instance?.trim() && declared) return `${block.instance.trim()}.${pin}`;
  const network = findNode(body, block.id)?.network;
  const wire =
    side === "in"
      ? network && wiresOf(network).find((w) => w.to.node === block.id && w.to.pin.toUpperCase() === pin.toUpperCase())
      : undefined;
  const source = wire && network ? nodesOf(network).find((n) => n.id === wire.from.node) : undefined;
  return source && kindOf(source) === "input" ? operandOf(source) : null;
}

/** The FB instance names the network's blocks already use (upper case), so a new block gets a fresh one. */
export function instancesOf(body: FbdBody): string[] {
  return networksOf(body).flatMap((n) =>
    nodesOf(n).flatMap((node) =>
      kindOf(node) === "block" && (node as Block).instance ? [(node as Block).instance!.toUpperCase()] : [],
    ),
  );
}

/** Whether a node's text edit changed the node (an unchanged text records no undo step). */
export function nodeChanged(before: FbdBody, after: FbdBody, id: string): boolean {
  return JSON.stringify(findNode(after, id)?.node) !== JSON.stringify(findNode(before, id)?.node);
}

/** The variable a node's text names: an input's expression, an output's variable, a block's instance. */
export function nodeVariable(node: FbdNode): string | null {
  return kindOf(node) === "block" ? (node as Block).instance?.trim() || null : operandOf(node);
}

/**
 * What the declare dialog offers for `text` typed into node `id` (after an edit, and from the node's
 * menu): an undeclared plain name with its guessed type, or null (a declared name, a literal, a node
 * whose text is no variable).
 */
export function declareOffer(
  body: FbdBody,
  id: string,
  text: string,
  known: ReadonlySet<string>,
  lookup: Lookup,
  symbols: readonly SymbolInfo[],
): VariableDeclaration | null {
  const node = findNode(body, id)?.node;
  const kind = node ? kindOf(node) : null;
  const name = kind === "input" || kind === "output" || kind === "block" ? undeclared(text, known) : null;
  return name ? { name, type: guessType(body, id, lookup, symbols) } : null;
}
