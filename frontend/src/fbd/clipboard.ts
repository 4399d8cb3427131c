// FBD clipboard: nodes of one network with the wires between them. Pasted nodes get fresh ids
// where theirs are taken and move down-right, so a paste next to the original is visible.
import { parseTagged, serializeTagged } from "../ld/taggedClip";
import { freshId } from "../ld/ids";
import { networksOf, nodesOf, wiresOf, type FbdBody, type FbdNetwork, type FbdNode, type Wire } from "./model";
import { PREFIX, usedIds, type EditResult } from "./ops";

const FORMAT = "ladderlab/fbd-clip";
const KINDS = new Set(["block", "input", "output", "jump", "return", "label", "connector", "continuation", "comment"]);
export const PASTE_OFFSET = 30;

export interface FbdClip {
  nodes: FbdNode[];
  wires: Wire[];
}

/** The clip of `ids` in `network`: those nodes and the wires that have both ends among them. */
export function clipOf(network: FbdNetwork, ids: readonly string[]): FbdClip {
  const chosen = new Set(ids);
  return {
    nodes: nodesOf(network).filter((n) => chosen.has(n.id)),
    wires: wiresOf(network).filter((w) => chosen.has(w.from.node) && chosen.has(w.to.node)),
  };
}

export const serializeClip = (clip: FbdClip): string => serializeTagged(FORMAT, clip);

const isPinRef = (v: unknown): boolean =>
  !!v &&
  typeof v === "object" &&
  typeof (v as { node?: unknown }).node === "string" &&
  typeof (v as { pin?: unknown }).pin === "string";

export function parseClip(text: string): FbdClip | null {
  const d = parseTagged(FORMAT, text);
  if (!d || !Array.isArray(d.nodes) || !Array.isArray(d.wires)) return null;
  const nodesOk = d.nodes.every(
    (n: unknown) =>
      !!n &&
      typeof n === "object" &&
      typeof (n as { id?: unknown }).id === "string" &&
      KINDS.has(String((n as { type?: unknown }).type ?? "block")),
  );
  const wiresOk = d.wires.every(
    (w: unknown) => !!w && typeof w === "object" && isPinRef((w as Wire).from) && isPinRef((w as Wire).to),
  );
  return nodesOk && wiresOk ? { nodes: d.nodes as FbdNode[], wires: d.wires as Wire[] } : null;
}

/** Pastes `clip` into `network`; the pasted nodes are selected. */
export function pasteClip(body: FbdBody, network: string, clip: FbdClip): EditResult {
  if (!networksOf(body).some((n) => n.id === network)) return { ok: false, error: "Select a network to paste into." };
  const used = usedIds(body);
  const ids = new Map<string, string>();
  for (const node of clip.nodes)
    ids.set(node.id, used.has(node.id) ? freshId(PREFIX[node.type ?? "block"], used) : (used.add(node.id), node.id));
  const nodes = clip.nodes.map((n) => ({
    ...n,
    id: ids.get(n.id)!,
    pos: { x: (n.pos?.x ?? 0) + PASTE_OFFSET, y: (n.pos?.y ?? 0) + PASTE_OFFSET },
  }));
  const wires = clip.wires
    .filter((w) => ids.has(w.from.node) && ids.has(w.to.node))
    .map((w) => ({ from: { ...w.from, node: ids.get(w.from.node)! }, to: { ...w.to, node: ids.get(w.to.node)! } }));
  const networks = networksOf(body).map((n) =>
    n.id === network ? { ...n, nodes: [...nodesOf(n), ...nodes], wires: [...wiresOf(n), ...wires] } : n,
  );
  return { ok: true, body: { ...body, networks }, select: nodes.map((n) => n.id) };
}
