// Online LD: which variable paths and element ids the visible networks need, and how the
// monitor's values map back onto the operand texts the diagram draws. Power comes from the engine
// per element id (never recomputed here); an element the last scan skipped has power null.
import type { SymbolInfo } from "../generated/api";
import { walk, type LdBody, type LdElement } from "../ld/model";
import type { OnlineView } from "../ld/view/types";
import { pathKey, powerKey, type MonitorState } from "./monitor";
import { formatValue } from "./values";
import type { ElementSubscription } from "./protocol";

/** A variable operand: names with member/index access (`T1.Q`, `A[3]`); literals and addresses are not. */
const VARIABLE = /^[A-Za-z_][A-Za-z0-9_]*(\.[A-Za-z_][A-Za-z0-9_]*|\[\s*\d+\s*\])*$/;
const LITERALS = new Set(["TRUE", "FALSE"]);

/** The variable operands one element shows (contact/coil variable, compare sides, box pins). */
export function operandsOf(element: LdElement): string[] {
  switch (element.type) {
    case "contact":
    case "coil":
      return [element.var];
    case "compare":
      return [element.left, element.right];
    case "box":
      return [
        ...Object.values(element.inputs ?? {}).filter((v): v is string => typeof v === "string"),
        ...Object.values(element.outputs ?? {}),
      ];
    default:
      return [];
  }
}

/**
 * The canonical simulation path of an operand in POU instance `instance`, as the server names it
 * in its messages: the instance's own variable (`MAIN.START`) or a global (`ALARM`); null for
 * literals and addresses.
 */
export function operandPath(operand: string, instance: string, symbols: readonly SymbolInfo[]): string | null {
  const text = operand.trim();
  if (!VARIABLE.test(text) || LITERALS.has(text.toUpperCase())) return null;
  const head = text.split(/[.[]/, 1)[0]!.toUpperCase();
  const symbol = symbols.find((s) => s.name.toUpperCase() === head);
  const global = symbol?.var_class === "VAR_GLOBAL" || symbol?.var_class === "VAR_EXTERNAL";
  return pathKey(global ? text : `${instance}.${text}`);
}

export interface LdBinding {
  instance: string;
  /** Paths to subscribe, upper case, without repeats. */
  paths: string[];
  elements: ElementSubscription[];
  /** Upper-case operand text -> its path. */
  pathOf: ReadonlyMap<string, string>;
}

/** What to subscribe for `networks` (ids; all when undefined) of an LD body shown for `instance`. */
export function bindLd(
  body: LdBody,
  instance: string,
  symbols: readonly SymbolInfo[],
  networks?: ReadonlySet<string>,
): LdBinding {
  const pathOf = new Map<string, string>();
  const ids: string[] = [];
  for (const { network, element } of walk(body)) {
    if (networks && !networks.has(network)) continue;
    ids.push(element.id);
    for (const operand of operandsOf(element)) {
      const path = operandPath(operand, instance, symbols);
      if (path) pathOf.set(operand.trim().toUpperCase(), path);
    }
  }
  return {
    instance,
    paths: [...new Set(pathOf.values())],
    elements: ids.length ? [{ pou_instance: instance, ids }] : [],
    pathOf,
  };
}

/** The diagram's online view of a binding: power and dimming by element id, values and forces by operand. */
export function ldOnlineView(monitor: MonitorState, binding: LdBinding): OnlineView {
  const power: Record<string, boolean> = {};
  const executed: Record<string, boolean> = {};
  for (const { pou_instance, ids } of binding.elements) {
    for (const id of ids ?? []) {
      const state = monitor.power[powerKey(pou_instance, id)];
      if (state === null) executed[id] = false;
      else if (typeof state === "boolean") power[id] = state;
    }
  }
  const values: Record<string, string | number | boolean> = {};
  const forced = new Set<string>();
  for (const [operand, path] of binding.pathOf) {
    const value = monitor.values[path];
    if (typeof value === "boolean") values[operand] = value;
    else if (typeof value === "number" || typeof value === "string")
      values[operand] = formatValue(value, monitor.types[path]);
    if (monitor.forced.has(path)) forced.add(operand);
  }
  return { power, executed, values, forced };
}
