// Online LD: which variable paths and element ids the visible networks need, and how the
// monitor's values map back onto the operand texts and box pins the diagram draws. Power comes from
// the engine per element id (never recomputed here); an element the last scan skipped has power null.
import type { LibraryEntry, SymbolInfo } from "../generated/api";
import { walk, type Box, type LdBody, type LdElement } from "./model";
import { boxPins } from "./pins";
import type { OnlineView } from "./view/types";
import { operandPath, powerKey, type MonitorState } from "../online/monitor";
import {
  bindBoxPins,
  diagramBinding,
  diagramValues,
  pinProbes,
  type DiagramBinding,
  type PinBinding,
  type PinSource,
} from "../online/pinValues";
import type { Prepared } from "../online/shown";

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

/** What an LD view subscribes and how the values map back onto its operands and boxes. */
export type LdBinding = DiagramBinding;

/**
 * A box's pins online: an FB instance's from the instance, a function's outputs from their probes
 * (ENO: the box's own power), operand inputs from their variables; power-fed inputs are drawn from
 * the power of the element feeding them (the layout knows it), so they need nothing here.
 */
function bindBox(box: Box, entry: LibraryEntry | undefined, path: (operand: string) => string | null): PinBinding[] {
  const { inputs, outputs } = boxPins(box, entry);
  const pins = [
    ...inputs.map((p) => ({ side: "in" as const, name: p.name, type: p.type, value: p.value })),
    ...outputs.map((p) => ({ side: "out" as const, name: p.name, type: p.type, value: p.value })),
  ].filter((p) => p.name);
  const instance = box.instance?.trim() ? path(box.instance) : null;
  return bindBoxPins(entry, instance, pins, (pin): PinSource => {
    if (pin.side === "out")
      return { probe: pin.name.toUpperCase() === "ENO" ? box.id : `${box.id}.${pin.name.toUpperCase()}` };
    const value = pins.find((p) => p.side === "in" && p.name === pin.name)?.value;
    const variable = typeof value === "string" ? path(value) : null;
    return variable ? { path: variable } : null;
  });
}

/** What to subscribe for `networks` (ids; all when undefined) of an LD body shown for `instance`. */
export function bindLd(
  body: LdBody,
  instance: string,
  symbols: readonly SymbolInfo[],
  library: (call: string) => LibraryEntry | undefined,
  networks?: ReadonlySet<string>,
): LdBinding {
  const pathOf = new Map<string, string>();
  const pins = new Map<string, PinBinding[]>();
  const ids: string[] = [];
  const path = (operand: string) => operandPath(operand, instance, symbols);
  for (const { network, element } of walk(body)) {
    if (networks && !networks.has(network)) continue;
    ids.push(element.id);
    for (const operand of operandsOf(element)) {
      const p = path(operand);
      if (p) pathOf.set(operand.trim().toUpperCase(), p);
    }
    if (element.type === "box") {
      const bound = bindBox(element, library(element.call), path);
      pins.set(element.id, bound);
      for (const probe of pinProbes(bound)) if (probe !== element.id) ids.push(probe);
    }
  }
  return diagramBinding(instance, ids, pathOf, pins);
}

/** The diagram's online view of a binding: power and dimming by element id, values by operand and box pin. */
export function ldOnlineView(monitor: MonitorState, binding: LdBinding, prepared: Prepared = {}): OnlineView {
  const power: Record<string, boolean> = {};
  const executed: Record<string, boolean> = {};
  for (const { pou_instance, ids } of binding.elements) {
    for (const id of ids ?? []) {
      const state = monitor.power[powerKey(pou_instance, id)];
      if (state === null) executed[id] = false;
      else if (typeof state === "boolean") power[id] = state;
    }
  }
  return { power, executed, ...diagramValues(monitor, binding, prepared) };
}
