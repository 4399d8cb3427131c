// Which wires the editor accepts: an output may feed an input when some type the output can carry
// is the input's type or widens to it losslessly (the checker's `assignable`). Generic families
// (ANY_NUM, ANY_BIT, ...) stand for their members. Types, families and widenings are the backend's
// (iec/vocabulary.ts). Types the editor cannot resolve (user types, arrays, unknown variables) are
// accepted: the backend's check has the last word, the editor only refuses what can never type-check.
import type { SymbolInfo } from "../generated/api";
import { ALIASES, ELEMENTARY, FAMILIES as IEC_FAMILIES, widens } from "../iec/vocabulary";
import { kindOf, nodePins, nodesOf, wiresOf, type FbdNetwork, type Lookup, type PinRef } from "./model";

/**
 * The IEC families, and ANY_LITERAL_INT: an untyped integer literal, which fits what the checker lets
 * it fit (st/types.py `in_family`: the numbers and the bit strings, BOOL as 0/1).
 */
export const FAMILIES: Readonly<Record<string, readonly string[]>> = {
  ...IEC_FAMILIES,
  ANY_LITERAL_INT: [...new Set([...IEC_FAMILIES.ANY_NUM!, ...IEC_FAMILIES.ANY_BIT!])],
};

/** How a type reads in a refusal (the literal pseudo-family in words). */
export const describeType = (type: string): string => (type === "ANY_LITERAL_INT" ? "an integer literal" : type);

/** The elementary types `type` stands for; null when the editor cannot tell (user types, arrays, STRING[n]). */
export function typeSet(type: string | undefined): readonly string[] | null {
  if (!type) return null;
  const t = ALIASES[type.trim().toUpperCase()] ?? type.trim().toUpperCase();
  if (FAMILIES[t]) return FAMILIES[t];
  return ELEMENTARY.includes(t) ? [t] : null;
}

/** Whether an output of type `source` may feed an input of type `target`. */
export function compatible(source: string | undefined, target: string | undefined): boolean {
  const from = typeSet(source);
  const to = typeSet(target);
  if (!from || !to) return true;
  return from.some((s) => to.some((t) => s === t || widens(s, t)));
}

/**
 * The type an output pin really carries: a generic function result takes the concrete type of the
 * wired inputs of its family (ADD fed two INTs gives INT), followed back through the wiring.
 */
export function outputType(
  network: FbdNetwork,
  ref: PinRef,
  lookup: Lookup,
  symbols: readonly SymbolInfo[],
  seen: Set<string> = new Set(),
): string | undefined {
  const node = nodesOf(network).find((n) => n.id === ref.node);
  if (!node || seen.has(node.id)) return undefined;
  seen.add(node.id);
  const kind = kindOf(node);
  if (kind === "continuation") {
    const name = (node as { name: string }).name.toUpperCase();
    const connector = nodesOf(network).find(
      (n) => kindOf(n) === "connector" && (n as { name: string }).name.toUpperCase() === name,
    );
    const feed = connector && wiresOf(network).find((w) => w.to.node === connector.id);
    return feed ? outputType(network, feed.from, lookup, symbols, seen) : undefined;
  }
  const pins = nodePins(node, network, lookup, symbols);
  const declared = pins.outputs.find((p) => p.name.toUpperCase() === ref.pin.toUpperCase())?.type;
  if (kind !== "block" || !declared || !FAMILIES[declared.toUpperCase()]) return declared;
  const family = declared.toUpperCase();
  for (const input of pins.inputs) {
    if (input.type?.toUpperCase() !== family) continue;
    const feed = wiresOf(network).find(
      (w) => w.to.node === node.id && w.to.pin.toUpperCase() === input.name.toUpperCase(),
    );
    const fed = feed && outputType(network, feed.from, lookup, symbols, seen);
    const set = typeSet(fed);
    if (fed && set && set.length === 1) return set[0];
  }
  return declared;
}

export type Connection = { from: PinRef; to: PinRef };

/** Why the editor refuses the wire `c` (null: it is accepted). */
export function refusal(
  network: FbdNetwork,
  c: Connection,
  lookup: Lookup,
  symbols: readonly SymbolInfo[],
): string | null {
  const target = nodesOf(network).find((n) => n.id === c.to.node);
  const source = nodesOf(network).find((n) => n.id === c.from.node);
  if (!target || !source) return "Both ends of a wire must be nodes of this network.";
  // a block's output back into its own input is a feedback loop (the previous scan's value, issue 22 item 6)
  if (c.from.node === c.to.node && kindOf(source) !== "block") return "A wire cannot connect a node to itself.";
  const occupied = wiresOf(network).find(
    (w) => w.to.node === c.to.node && w.to.pin.toUpperCase() === c.to.pin.toUpperCase(),
  );
  if (occupied) {
    return `Input ${c.to.pin} of ${c.to.node} is already wired from ${occupied.from.node}.${occupied.from.pin}: FBD has no wired OR (use an OR block), delete that wire first.`;
  }
  const from = outputType(network, c.from, lookup, symbols);
  const to = nodePins(target, network, lookup, symbols).inputs.find(
    (p) => p.name.toUpperCase() === c.to.pin.toUpperCase(),
  )?.type;
  if (!compatible(from, to)) {
    const sentence = `${article(describeType(from!))} output (${c.from.node}.${c.from.pin}) cannot feed ${article(to!)} input (${c.to.node}.${c.to.pin}).`;
    return sentence[0]!.toUpperCase() + sentence.slice(1);
  }
  return null;
}

/** "an INT", "a BOOL", "an integer literal": the article by the first sound of the type name. */
const article = (type: string): string =>
  type.startsWith("an ") ? type : /^[AEIOU]/i.test(type) ? `an ${type}` : `a ${type}`;
