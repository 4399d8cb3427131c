// The SFC chart as the editor sees it: the project model's nested sequences (backend model/sfc.py), with
// helpers to find an element and the sequence holding it, walk every element, and name new ones. A sequence
// alternates step-like elements (a step, a simultaneous divergence) and transition-like ones (a transition,
// an alternative divergence) and may end with a jump; the first step of the chart is the initial step.
import type {
  SfcAlternative,
  SfcAssociation,
  SfcBody,
  SfcJump,
  SfcParallel,
  SfcStep,
  SfcTransition,
} from "../generated/api";

export type { SfcAlternative, SfcAssociation, SfcBody, SfcJump, SfcParallel, SfcStep, SfcTransition };
export type SfcElement = SfcStep | SfcTransition | SfcAlternative | SfcParallel | SfcJump;
export type Sequence = SfcElement[];
export type Qualifier = NonNullable<SfcAssociation["qualifier"]>;

export const QUALIFIERS: readonly Qualifier[] = ["N", "R", "S", "L", "D", "P", "P1", "P0", "SD", "DS", "SL"];
/** Qualifiers that need a TIME (SFC-05). */
export const TIMED: ReadonlySet<Qualifier> = new Set(["L", "D", "SD", "DS", "SL"]);
export const QUALIFIER_TEXT: Record<Qualifier, string> = {
  N: "non-stored: while the step is active",
  R: "overriding reset",
  S: "set (stored) until reset",
  L: "time limited",
  D: "time delayed",
  P: "pulse: once on activation",
  P1: "pulse on activation (rising edge)",
  P0: "pulse on deactivation (falling edge)",
  SD: "stored and time delayed",
  DS: "delayed and stored",
  SL: "stored and time limited",
};

export const kindOf = (e: SfcElement): "step" | "transition" | "alternative" | "parallel" | "jump" =>
  e.type ?? ("name" in e ? "step" : "target" in e ? "jump" : "branches" in e ? "alternative" : "transition");

export const isStepLike = (e: SfcElement): boolean => kindOf(e) === "step" || kindOf(e) === "parallel";
export const isTransitionLike = (e: SfcElement): boolean => kindOf(e) === "transition" || kindOf(e) === "alternative";

export const chartOf = (body: SfcBody): Sequence => body.chart?.elements ?? [];

/** Where an element is: the sequence that holds it (and its index there). */
export interface Place {
  sequence: Sequence;
  index: number;
  element: SfcElement;
}

/** Every element of the chart in drawing order, with its place. */
export function* walk(sequence: Sequence): Generator<Place> {
  for (let index = 0; index < sequence.length; index += 1) {
    const element = sequence[index]!;
    yield { sequence, index, element };
    if ("branches" in element) for (const branch of element.branches) yield* walk(branch);
  }
}

export function locate(body: SfcBody, id: string): Place | undefined {
  for (const place of walk(chartOf(body))) if (place.element.id === id) return place;
  return undefined;
}

export const steps = (body: SfcBody): SfcStep[] =>
  [...walk(chartOf(body))].map((p) => p.element).filter((e): e is SfcStep => kindOf(e) === "step");

/** The charts of actions written in SFC (docs/sfc.md "Actions written in SFC"). */
export const actionCharts = (body: SfcBody): Sequence[] =>
  (body.actions ?? []).flatMap((a) =>
    a.language === "sfc" && a.body && typeof a.body === "object" && "elements" in a.body
      ? [(a.body.elements ?? []) as Sequence]
      : [],
  );

/** An action's chart edited as a body of its own: `enclosing` is the POU's chart, whose names and ids it must not
 * reuse (never saved: the edit is written back into the action). */
export type ActionChartBody = SfcBody & { enclosing?: SfcBody["chart"] };

/** The part path ("actions/Seq") of the SFC action whose chart holds element `id`; null if none does. */
export function actionChartOf(body: SfcBody, id: string): string | null {
  const action = (body.actions ?? []).find(
    (a) =>
      a.language === "sfc" &&
      a.body &&
      typeof a.body === "object" &&
      "elements" in a.body &&
      locate({ chart: a.body as SfcBody["chart"] }, id) !== undefined,
  );
  return action ? `actions/${action.name}` : null;
}

/** Every chart of the POU: its own (or the one being edited and the POU's), then its SFC actions'. Steps and
 * element ids are unique across all of them. */
const allCharts = (body: ActionChartBody): Sequence[] => [
  chartOf(body),
  ...(body.enclosing ? [body.enclosing.elements ?? []] : []),
  ...actionCharts(body),
];

/** Every id of the POU's charts (elements and associations): new ones must differ. */
export function usedIds(body: SfcBody): Set<string> {
  const ids = new Set<string>();
  for (const chart of allCharts(body))
    for (const { element } of walk(chart)) {
      ids.add(element.id);
      if (kindOf(element) === "step") for (const a of (element as SfcStep).actions ?? []) ids.add(a.id);
    }
  return ids;
}

/** Names taken by steps (of every chart), actions and named transitions (upper case): a new one must differ. */
export function usedNames(body: SfcBody): Set<string> {
  const stepNames = allCharts(body).flatMap((chart) =>
    [...walk(chart)].flatMap(({ element }) => (kindOf(element) === "step" ? [(element as SfcStep).name] : [])),
  );
  return new Set([
    ...stepNames.map((name) => name.toUpperCase()),
    ...(body.actions ?? []).map((a) => a.name.toUpperCase()),
    ...(body.transitions ?? []).map((t) => t.name.toUpperCase()),
  ]);
}

/** The first `<prefix><n>` not in `used` (compared upper case); reserved from now on. */
export function freshName(prefix: string, used: Set<string>): string {
  let n = 1;
  while (used.has(`${prefix}${n}`.toUpperCase())) n += 1;
  const name = `${prefix}${n}`;
  used.add(name.toUpperCase());
  return name;
}

/** Element ids as the model names them (s1, t1, alt1 ...), unique in the body. */
export function freshId(prefix: string, used: Set<string>): string {
  let n = 1;
  while (used.has(`${prefix}${n}`)) n += 1;
  const id = `${prefix}${n}`;
  used.add(id);
  return id;
}

/** A step or transition in the user's words ("step Rinse", "transition Rinse.T >= T#2s"); null for other ids. */
export function elementText(body: SfcBody, id: string): string | null {
  const element = allCharts(body)
    .map((chart) => locate({ chart: { elements: chart } }, id)?.element)
    .find(Boolean);
  if (!element) return null;
  if (kindOf(element) === "step") return `step ${(element as SfcStep).name}`;
  if (kindOf(element) === "transition") return `transition ${(element as SfcTransition).condition}`;
  return null;
}

/** The id of the element (or association) a probe or breakpoint names: "t3.COND" is transition t3's condition. */
/** The action or named transition a path names ("actions/Fill", as breakpoints and halts name them), with its
 * language; null when the chart has no such part. */
export function partAt(body: SfcBody, path: string): { body: unknown; language: string } | null {
  const [kind, name] = path.split("/", 2);
  const parts: readonly { name: string; language?: string | null; body?: unknown }[] =
    (kind === "actions" ? body.actions : kind === "transitions" ? body.transitions : null) ?? [];
  const part = parts.find((p) => p.name.toUpperCase() === (name ?? "").toUpperCase());
  return part ? { body: part.body, language: part.language ?? "st" } : null;
}

export const conditionProbe = (transition: string): string => `${transition}.COND`;
