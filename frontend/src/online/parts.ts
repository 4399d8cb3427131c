// The diagrams of an SFC POU's actions and named transitions are lowered with their element ids under the part's
// path ("actions/Fill/c1": each body has ids of its own, ir/lower_sfc.py), so the LD and FBD online hooks
// subscribe the part's ids with that prefix and read the power back without it.
import { powerKey, type MonitorState } from "./monitor";
import type { ElementSubscription } from "./protocol";

/** `elements` with every id under `part` (none: as they are). */
export function partElements(elements: readonly ElementSubscription[], part?: string): ElementSubscription[] {
  if (!part) return [...elements];
  return elements.map((e) => ({ ...e, ids: e.ids ? e.ids.map((id) => `${part}/${id}`) : e.ids }));
}

/** The monitor as the part's diagram reads it: the power of `<instance>/<part>/<id>` as `<instance>/<id>`. */
export function partMonitor(monitor: MonitorState, instance: string | null, part?: string): MonitorState {
  if (!part || !instance) return monitor;
  const prefix = powerKey(instance, `${part}/`);
  const power: Record<string, MonitorState["power"][string]> = {};
  for (const [key, state] of Object.entries(monitor.power))
    if (key.startsWith(prefix)) power[powerKey(instance, key.slice(prefix.length))] = state;
  return { ...monitor, power };
}
