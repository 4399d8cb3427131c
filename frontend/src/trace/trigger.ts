// The trace trigger as the panel edits it (a path, a condition, a level typed as text) and the
// `trigger` of `trace_start` it becomes. The server evaluates the trigger after every scan
// (backend/ladderlab/simulation/trace.py); here the form is checked so a mistake is named at once.
import type { TraceTrigger } from "../generated/monitor";

export type Condition = NonNullable<TraceTrigger["condition"]>;

export interface TriggerForm {
  /** Empty: no trigger, recording starts at once. */
  path: string;
  condition: Condition;
  /** Text of the level of a crossing (a number; TIME in ms). */
  level: string;
}

export const noTrigger: TriggerForm = { path: "", condition: "rising", level: "" };

export const CONDITIONS: readonly { value: Condition; label: string }[] = [
  { value: "rising", label: "rising edge (BOOL)" },
  { value: "falling", label: "falling edge (BOOL)" },
  { value: "cross_up", label: "crosses the level upwards" },
  { value: "cross_down", label: "crosses the level downwards" },
];

export const isCrossing = (condition: Condition): boolean => condition === "cross_up" || condition === "cross_down";

export type TriggerResult = { ok: true; trigger: TraceTrigger | null } | { ok: false; error: string };

/** The `trace_start.trigger` of a form, or why the form is not a trigger. */
export function triggerOf(form: TriggerForm): TriggerResult {
  const path = form.path.trim();
  if (!path) return { ok: true, trigger: null };
  if (!isCrossing(form.condition)) return { ok: true, trigger: { path, condition: form.condition } };
  const text = form.level.trim();
  const level = text === "" ? NaN : Number(text);
  if (!Number.isFinite(level))
    return {
      ok: false,
      error: text ? `the trigger level must be a number, not '${text}'` : "a level crossing needs a level",
    };
  return { ok: true, trigger: { path, condition: form.condition, level } };
}

/** One line saying what the trace waits for, e.g. "MAIN.GO rising" or "MAIN.T crosses 50 upwards". */
export function describeTrigger(trigger: TraceTrigger): string {
  switch (trigger.condition ?? "rising") {
    case "rising":
      return `${trigger.path} rising`;
    case "falling":
      return `${trigger.path} falling`;
    case "cross_up":
      return `${trigger.path} crosses ${trigger.level} upwards`;
    case "cross_down":
      return `${trigger.path} crosses ${trigger.level} downwards`;
  }
}
