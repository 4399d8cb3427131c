// Breakpoints as the monitor protocol names them (BreakpointSet: a POU and exactly one of network,
// element or ST line) and the messages that set, clear and step. Pure, so the store and the panel
// share one notion of "the same breakpoint".
import type { BreakpointClear, BreakpointSet, Step } from "../generated/monitor";
import type { At } from "../online/protocol";

/** `body`: in an SFC POU, the action or named transition a line or network is in (actions/<name>). */
export type Breakpoint = { pou: string; body?: string } & (
  { network: string } | { element: string } | { line: number }
);

export type StepGranularity = NonNullable<Step["granularity"]>;

/** POU names compare case-insensitively (IEC identifiers); network and element ids exactly. */
export function sameBreakpoint(a: Breakpoint, b: Breakpoint): boolean {
  if (a.pou.toUpperCase() !== b.pou.toUpperCase() || (a.body ?? null) !== (b.body ?? null)) return false;
  if ("network" in a) return "network" in b && a.network === b.network;
  if ("element" in a) return "element" in b && a.element === b.element;
  return "line" in b && a.line === b.line;
}

/** One string per breakpoint, equal exactly when `sameBreakpoint` holds (for sets and React keys). */
export function breakpointKey(bp: Breakpoint): string {
  const where =
    "network" in bp ? `network:${bp.network}` : "element" in bp ? `element:${bp.element}` : `line:${bp.line}`;
  return `${bp.pou.toUpperCase()}|${bp.body ? `${bp.body}|` : ""}${where}`;
}

/** Only the location fields (callers may pass richer objects; the server refuses unknown fields). */
function where(bp: Breakpoint): Breakpoint {
  const body = bp.body ? { body: bp.body } : {};
  if ("network" in bp) return { pou: bp.pou, ...body, network: bp.network };
  return "element" in bp ? { pou: bp.pou, ...body, element: bp.element } : { pou: bp.pou, ...body, line: bp.line };
}

export function setMessage(bp: Breakpoint): BreakpointSet {
  return { type: "breakpoint_set", ...where(bp) };
}

export function clearMessage(bp: Breakpoint): BreakpointClear {
  return { type: "breakpoint_clear", ...where(bp) };
}

/** The list with `bp` added, or removed if it was there, and the message that tells the server. */
export function toggle(
  list: readonly Breakpoint[],
  bp: Breakpoint,
): { list: Breakpoint[]; message: BreakpointSet | BreakpointClear } {
  return list.some((b) => sameBreakpoint(b, bp))
    ? { list: list.filter((b) => !sameBreakpoint(b, bp)), message: clearMessage(bp) }
    : { list: [...list, bp], message: setMessage(bp) };
}

/** "Main, network 2" with the network's 1-based position in the POU when it is known. */
export function describeBreakpoint(bp: Breakpoint, networkIds: readonly string[] = []): string {
  const pou = bp.body ? `${bp.pou}, ${partName(bp.body)}` : bp.pou;
  if ("network" in bp) {
    const index = bp.body ? -1 : networkIds.indexOf(bp.network);
    return `${pou}, network ${index >= 0 ? index + 1 : bp.network}`;
  }
  return "element" in bp ? `${pou}, element ${bp.element}` : `${pou}, line ${bp.line}`;
}

/** "actions/Fill" -> "action Fill" (the parts of an SFC POU, as Origin.body names them). */
export const partName = (body: string): string =>
  body.replace(/^actions\//, "action ").replace(/^transitions\//, "transition ");

/** Where a halt is, in words: POU (instance), network/element/line; `networkIds` are those of the body halted in
 * (the POU's, or its SFC action's or transition's when `at.body` names one); `elementText` names the element when
 * known ("step Rinse"). */
export function describeHalt(at: At, networkIds: readonly string[] = [], elementText?: string | null): string {
  const parts = [
    at.instance && at.instance.toUpperCase() !== at.pou.toUpperCase() ? `${at.pou} (${at.instance})` : at.pou,
  ];
  if (at.body) parts.push(partName(at.body));
  if (at.network) {
    const index = networkIds.indexOf(at.network);
    parts.push(`network ${index >= 0 ? index + 1 : at.network}`);
  }
  if (at.element) parts.push(elementText ?? `element ${at.element}`);
  if (at.line != null) parts.push(`line ${at.line}`);
  return parts.join(", ");
}
