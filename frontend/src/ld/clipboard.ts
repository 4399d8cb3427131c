// Clipboard contents for LD elements and networks: plain JSON text with a format tag, so copy and
// paste work through the system clipboard between tabs, windows and POUs.
import type { LdElement, LdNetwork } from "./model";
import { parseTagged, serializeTagged } from "./taggedClip";

const FORMAT = "ladderlab/ld-clip";

export type Clip = { kind: "elements"; elements: LdElement[] } | { kind: "networks"; networks: LdNetwork[] };

export const serializeClip = (clip: Clip): string => serializeTagged(FORMAT, clip);

const ELEMENT_TYPES = new Set(["contact", "compare", "coil", "parallel", "box", "jump", "return"]);

function isElement(value: unknown): value is LdElement {
  if (!value || typeof value !== "object") return false;
  const e = value as Record<string, unknown>;
  if (typeof e.id !== "string" || !ELEMENT_TYPES.has(String(e.type))) return false;
  if (e.type === "parallel") return Array.isArray(e.branches) && e.branches.every(isSeries);
  if (e.type === "box") {
    const inputs = (e.inputs ?? {}) as Record<string, unknown>;
    return typeof e.call === "string" && Object.values(inputs).every((v) => typeof v === "string" || isSeries(v));
  }
  return true;
}

const isSeries = (value: unknown): value is LdElement[] => Array.isArray(value) && value.every(isElement);

function isNetwork(value: unknown): value is LdNetwork {
  if (!value || typeof value !== "object") return false;
  const n = value as Record<string, unknown>;
  return typeof n.id === "string" && (n.elements === undefined || isSeries(n.elements));
}

/** The clip in `text`, or null when it is not one of ours (any other text, or a damaged clip). */
export function parseClip(text: string): Clip | null {
  const d = parseTagged(FORMAT, text);
  if (!d) return null;
  if (d.kind === "elements" && isSeries(d.elements)) return { kind: "elements", elements: d.elements };
  if (d.kind === "networks" && Array.isArray(d.networks) && d.networks.every(isNetwork)) {
    return { kind: "networks", networks: d.networks };
  }
  return null;
}
