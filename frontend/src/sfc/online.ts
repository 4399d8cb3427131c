// What the SFC editor subscribes to online and how the monitor becomes its online view (SFC-09, ON-17):
// the probes of the instance (a step's probe runs while it is active; a transition's "<id>.COND" probe is its
// condition every scan; its own probe runs when it fires) and the paths of the steps' X and T and the actions'
// Q and A (ir/lower_sfc.py names them so), and the BOOL variables associated to steps as actions (their
// value is their action flag: IEC 61131-3 6.7.4.2).
import type { MonitorState } from "../online/monitor";
import { pathKey, powerKey } from "../online/monitor";
import { timeLiteral } from "../online/values";
import { chartOf, conditionProbe, kindOf, walk, type SfcBody, type SfcStep } from "./model";
import type { SfcOnlineView } from "./SfcDiagram";

export interface SfcBinding {
  instance: string;
  paths: string[];
  elements: { pou_instance: string; ids: string[] }[];
  steps: { id: string; name: string }[];
  transitions: string[];
  actions: string[];
  /** BOOL variables associated to steps in place of an action. */
  variables: string[];
}

export function bindSfc(body: SfcBody, instance: string): SfcBinding {
  const steps: { id: string; name: string }[] = [];
  const transitions: string[] = [];
  const associated = new Set<string>();
  for (const { element } of walk(chartOf(body))) {
    if (kindOf(element) === "step") {
      const step = element as SfcStep;
      steps.push({ id: step.id, name: step.name });
      for (const row of step.actions ?? []) associated.add(row.action.trim());
    }
    if (kindOf(element) === "transition") transitions.push(element.id);
  }
  const actions = (body.actions ?? []).map((a) => a.name);
  const named = new Set(actions.map((a) => a.toUpperCase()));
  const variables = [...associated].filter((name) => name && !named.has(name.toUpperCase()));
  const paths = [
    ...steps.flatMap((s) => [`${instance}.${s.name}.X`, `${instance}.${s.name}.T`]),
    ...actions.flatMap((a) => [`${instance}.${a}.Q`, `${instance}.${a}.A`]),
    ...variables.map((v) => `${instance}.${v}`),
  ];
  const ids = [...steps.map((s) => s.id), ...transitions, ...transitions.map(conditionProbe)];
  return { instance, paths, elements: [{ pou_instance: instance, ids }], steps, transitions, actions, variables };
}

export function sfcOnlineView(monitor: MonitorState, binding: SfcBinding): SfcOnlineView {
  const { instance } = binding;
  const value = (path: string) => monitor.values[pathKey(path)];
  const power = (id: string) => monitor.power[powerKey(instance, id)];
  const active = new Set<string>();
  const times: Record<string, string> = {};
  const forced = new Set<string>();
  for (const step of binding.steps) {
    const x = value(`${instance}.${step.name}.X`);
    if (x === true || (x === undefined && power(step.id) != null)) active.add(step.id);
    const t = value(`${instance}.${step.name}.T`);
    if (typeof t === "number") times[step.id] = timeLiteral(t);
    if (monitor.forced.has(pathKey(`${instance}.${step.name}.X`))) forced.add(step.id);
  }
  const conditions: Record<string, boolean | null> = {};
  const fired = new Set<string>();
  for (const id of binding.transitions) {
    const c = power(conditionProbe(id));
    conditions[id] = typeof c === "boolean" ? c : null;
    if (power(id) != null) fired.add(id);
  }
  const running = new Set<string>();
  const flagged = new Set<string>();
  for (const action of binding.actions) {
    if (value(`${instance}.${action}.A`) === true) running.add(action.toUpperCase());
    if (value(`${instance}.${action}.Q`) === true) flagged.add(action.toUpperCase());
  }
  for (const variable of binding.variables)
    if (value(`${instance}.${variable}`) === true) {
      running.add(variable.toUpperCase());
      flagged.add(variable.toUpperCase());
    }
  return { active, times, conditions, fired, running, flagged, forced };
}
