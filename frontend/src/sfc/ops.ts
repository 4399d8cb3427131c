// Editing an SFC chart: pure functions from a body to the next body (or the reason an edit cannot be made).
// Every edit keeps a sequence alternating step-like and transition-like elements, so the editor cannot draw an
// invalid chart: a step comes with a transition (below a step: transition then step; below a transition: step
// then transition), an alternative replaces a transition by branches of transitions, a simultaneous
// divergence a step by branches of steps, a jump ends a sequence after a transition. Removing an element
// takes its partner along. Renaming a step, an action or a named transition renames what refers to it.
import {
  chartOf,
  freshId,
  freshName,
  isStepLike,
  isTransitionLike,
  kindOf,
  locate,
  steps,
  usedIds,
  usedNames,
  walk,
  type Place,
  type Qualifier,
  type Sequence,
  type SfcAssociation,
  type SfcBody,
  type SfcElement,
  type SfcStep,
  type SfcTransition,
} from "./model";
import type { SfcAction, SfcNamedTransition } from "../generated/api";

export type EditResult = { body: SfcBody; select?: string } | { error: string };

const clone = (body: SfcBody): SfcBody => structuredClone({ ...body, chart: { elements: chartOf(body) } });

function edit(body: SfcBody, id: string, change: (place: Place, copy: SfcBody) => EditResult): EditResult {
  const copy = clone(body);
  const place = locate(copy, id);
  return place ? change(place, copy) : { error: "Select an element of the chart first." };
}

const newStep = (ids: Set<string>, names: Set<string>): SfcStep => ({
  type: "step",
  id: freshId("s", ids),
  name: freshName("Step", names),
  actions: [],
});

const newTransition = (ids: Set<string>, condition = "FALSE"): SfcTransition => ({
  type: "transition",
  id: freshId("t", ids),
  condition,
});

/** Below the selection: a transition and a step after a step, a step and a transition after a transition. An
 * empty chart gets its initial step. */
export function insertBelow(body: SfcBody, id: string | null): EditResult {
  const copy = clone(body);
  const ids = usedIds(copy);
  const names = usedNames(copy);
  const chart = chartOf(copy);
  if (chart.length === 0) {
    const first = { ...newStep(ids, names), name: freshName("Init", names) };
    copy.chart = { elements: [first] };
    return { body: copy, select: first.id };
  }
  let place = id ? locate(copy, id) : undefined;
  if (!place) {
    const last = chart.length - 1;
    const index = kindOf(chart[last]!) === "jump" ? last - 1 : last;
    place = { sequence: chart, index, element: chart[index]! };
  }
  if (kindOf(place.element) === "jump") return { error: "Nothing goes below a jump: it ends its sequence." };
  const step = newStep(ids, names);
  const transition = newTransition(ids);
  const added = isStepLike(place.element) ? [transition, step] : [step, transition];
  place.sequence.splice(place.index + 1, 0, ...added);
  return { body: copy, select: step.id };
}

/** An alternative divergence: the selected transition becomes its first branch, a new one its second; on an
 * alternative, one more branch; on a step, the transition after it is divided. */
export function addAlternative(body: SfcBody, id: string): EditResult {
  return edit(body, id, (place, copy) => {
    const ids = usedIds(copy);
    const { sequence } = place;
    let { index, element } = place;
    if (isStepLike(element)) {
      const next = sequence[index + 1];
      if (!next || !isTransitionLike(next)) return { error: "Add a transition below the step first." };
      index += 1;
      element = next;
    }
    const added = newTransition(ids);
    if (kindOf(element) === "alternative") {
      (element as { branches: Sequence[] }).branches.push([added]);
    } else if (kindOf(element) === "transition") {
      sequence[index] = { type: "alternative", id: freshId("alt", ids), branches: [[element], [added]] };
    } else {
      return { error: "An alternative branch starts at a transition or a step." };
    }
    return { body: copy, select: added.id };
  });
}

/** A simultaneous divergence: the selected step becomes its first branch, a new step its second; on a
 * simultaneous divergence, one more branch; on a transition, the step after it is divided. */
export function addParallel(body: SfcBody, id: string): EditResult {
  return edit(body, id, (place, copy) => {
    const ids = usedIds(copy);
    const names = usedNames(copy);
    const { sequence } = place;
    let { index, element } = place;
    if (isTransitionLike(element)) {
      const next = sequence[index + 1];
      if (!next || !isStepLike(next)) return { error: "Add a step below the transition first." };
      index += 1;
      element = next;
    }
    if (place.sequence === chartOf(copy) && index === 0 && kindOf(element) === "step")
      return { error: "The initial step cannot be divided: add the simultaneous branches below it." };
    const added = newStep(ids, names);
    if (kindOf(element) === "parallel") {
      (element as { branches: Sequence[] }).branches.push([added]);
    } else if (kindOf(element) === "step") {
      sequence[index] = { type: "parallel", id: freshId("par", ids), branches: [[element], [added]] };
    } else {
      return { error: "A simultaneous branch starts at a step or a transition." };
    }
    return { body: copy, select: added.id };
  });
}

/** A jump to `target` (default: the initial step) at the end of a sequence: after its last transition, or
 * after its last step with a transition before the jump. */
export function addJump(body: SfcBody, id: string, target?: string): EditResult {
  return edit(body, id, ({ sequence, index, element }, copy) => {
    if (index !== sequence.length - 1 || kindOf(element) === "jump")
      return { error: "A jump ends a sequence: select the last step or transition of the sequence (or of a branch)." };
    const ids = usedIds(copy);
    if (isStepLike(element)) sequence.push(newTransition(ids));
    const jump = { type: "jump" as const, id: freshId("j", ids), target: target ?? steps(copy)[0]?.name ?? "" };
    sequence.push(jump);
    return { body: copy, select: jump.id };
  });
}

/** Removes the element with its partner (a step with the transition after it, a transition with the step
 * after it); a divergence keeps its first branch; a branch left alone is no divergence any more. */
export function remove(body: SfcBody, id: string): EditResult {
  return edit(body, id, ({ sequence, index, element }, copy) => {
    const kind = kindOf(element);
    if (kind === "jump") {
      sequence.splice(index, 1);
    } else if (kind === "alternative" || kind === "parallel") {
      sequence.splice(index, 1, ...(element as { branches: Sequence[] }).branches[0]!);
    } else {
      const next = sequence[index + 1];
      const previous = sequence[index - 1];
      if (next && (kindOf(next) === "jump" || isStepLike(element) !== isStepLike(next))) sequence.splice(index, 2);
      else if (previous && isStepLike(element) !== isStepLike(previous)) sequence.splice(index - 1, 2);
      else sequence.splice(index, 1);
    }
    dropEmptyBranches(chartOf(copy));
    return { body: copy };
  });
}

/** Removes the branch of a divergence that holds the element. */
export function removeBranch(body: SfcBody, id: string): EditResult {
  const copy = clone(body);
  for (const { element } of walk(chartOf(copy))) {
    if (!("branches" in element)) continue;
    const index = element.branches.findIndex((b) => b.some((e) => e.id === id));
    if (index >= 0) {
      element.branches.splice(index, 1);
      dropEmptyBranches(chartOf(copy));
      return { body: copy };
    }
  }
  return { error: "Select an element of a branch first." };
}

/** Divergences with one branch left become that branch; empty branches go. */
function dropEmptyBranches(sequence: Sequence): void {
  for (let i = 0; i < sequence.length; i += 1) {
    const element = sequence[i]!;
    if (!("branches" in element)) continue;
    element.branches = element.branches.filter((b) => b.length > 0);
    element.branches.forEach(dropEmptyBranches);
    if (element.branches.length === 0) {
      sequence.splice(i, 1);
      i -= 1;
    } else if (element.branches.length === 1) {
      sequence.splice(i, 1, ...element.branches[0]!);
      i -= 1;
    }
  }
}

// ------------------------------------------------------------------ properties

/** Renames a step (jumps to it follow); `patch` also sets entry/exit actions, time limits and the comment. */
export function setStep(
  body: SfcBody,
  id: string,
  patch: Partial<Pick<SfcStep, "name" | "entry" | "exit" | "min_time" | "max_time" | "comment">>,
): EditResult {
  return edit(body, id, ({ element }, copy) => {
    if (kindOf(element) !== "step") return { error: "Select a step." };
    const step = element as SfcStep;
    if (patch.name !== undefined && patch.name.toUpperCase() !== step.name.toUpperCase()) {
      const problem = nameProblem(copy, patch.name);
      if (problem) return { error: problem };
      for (const { element: other } of walk(chartOf(copy)))
        if (kindOf(other) === "jump" && (other as { target: string }).target.toUpperCase() === step.name.toUpperCase())
          (other as { target: string }).target = patch.name;
    }
    Object.assign(step, clean(patch));
    return { body: copy, select: id };
  });
}

export function setTransition(
  body: SfcBody,
  id: string,
  patch: Partial<Pick<SfcTransition, "condition" | "priority" | "comment">>,
): EditResult {
  return edit(body, id, ({ element }, copy) => {
    if (kindOf(element) !== "transition") return { error: "Select a transition." };
    Object.assign(element, clean(patch));
    return { body: copy, select: id };
  });
}

export function setJump(body: SfcBody, id: string, target: string): EditResult {
  return edit(body, id, ({ element }, copy) => {
    if (kindOf(element) !== "jump") return { error: "Select a jump." };
    (element as { target: string }).target = target;
    return { body: copy, select: id };
  });
}

const clean = <T extends object>(patch: T): T =>
  Object.fromEntries(Object.entries(patch).map(([k, v]) => [k, v === "" ? null : v])) as T;

const IDENTIFIER = /^[A-Za-z_][A-Za-z0-9_]{0,63}$/;

function nameProblem(body: SfcBody, name: string): string | null {
  if (!IDENTIFIER.test(name) || name.includes("__"))
    return `${name || "An empty name"} is not an IEC identifier (letters, digits and single _).`;
  if (usedNames(body).has(name.toUpperCase())) return `${name} is already the name of a step, action or transition.`;
  return null;
}

// ------------------------------------------------------------------ action associations

export function addAssociation(
  body: SfcBody,
  stepId: string,
  association: { qualifier: Qualifier; action: string; time?: string | null },
): EditResult {
  return edit(body, stepId, ({ element }, copy) => {
    if (kindOf(element) !== "step") return { error: "Actions are associated with a step: select one." };
    const made: SfcAssociation = { id: freshId("a", usedIds(copy)), ...association };
    if (!made.time) delete made.time;
    ((element as SfcStep).actions ??= []).push(made);
    return { body: copy, select: stepId };
  });
}

export function setAssociation(
  body: SfcBody,
  stepId: string,
  associationId: string,
  patch: Partial<Omit<SfcAssociation, "id">>,
): EditResult {
  return edit(body, stepId, ({ element }, copy) => {
    const found = (element as SfcStep).actions?.find((a) => a.id === associationId);
    if (!found) return { error: "That association is gone." };
    Object.assign(found, patch);
    if (!found.time) delete found.time;
    return { body: copy, select: stepId };
  });
}

export function removeAssociation(body: SfcBody, stepId: string, associationId: string): EditResult {
  return edit(body, stepId, ({ element }, copy) => {
    const step = element as SfcStep;
    step.actions = (step.actions ?? []).filter((a) => a.id !== associationId);
    return { body: copy, select: stepId };
  });
}

// ------------------------------------------------------------------ actions and named transitions

export type PartLanguage = "st" | "il" | "ld" | "fbd" | "sfc";

/** A new part's body: ST text (`st`), IL text (`il`: a transition is its accumulator at the end), or networks. */
const emptyBody = (language: PartLanguage, st: string, il: string) =>
  language === "st" ? st : language === "il" ? il : { networks: [] };

/** A new action chart: an initial step, a transition FALSE and the jump back, named and numbered to be unique in
 * the POU (steps and element ids are shared by all of its charts). */
function emptyChart(body: SfcBody, action: string): { elements: SfcElement[] } {
  const ids = usedIds(body);
  const names = usedNames(body);
  names.add(action.toUpperCase());
  const name = freshName(`${action}_Init`, names);
  return {
    elements: [
      { type: "step", id: freshId("s", ids), name, actions: [] },
      { type: "transition", id: freshId("t", ids), condition: "FALSE" },
      { type: "jump", id: freshId("j", ids), target: name },
    ] as SfcElement[],
  };
}

export function addAction(body: SfcBody, name: string, language: PartLanguage): EditResult {
  const copy = clone(body);
  const problem = nameProblem(copy, name);
  if (problem) return { error: problem };
  const made = language === "sfc" ? emptyChart(copy, name) : emptyBody(language, "", "");
  (copy.actions ??= []).push({ name, language, body: made } as SfcAction);
  return { body: copy };
}

export function addNamedTransition(body: SfcBody, name: string, language: PartLanguage): EditResult {
  const copy = clone(body);
  const problem = nameProblem(copy, name);
  if (problem) return { error: problem };
  (copy.transitions ??= []).push({
    name,
    language,
    body: emptyBody(language, "FALSE", "LD FALSE"),
  } as SfcNamedTransition);
  return { body: copy };
}

/** Renames an action: the associations and entry/exit actions naming it follow. */
export function renameAction(body: SfcBody, from: string, to: string): EditResult {
  const copy = clone(body);
  const action = copy.actions?.find((a) => a.name === from);
  if (!action) return { error: `There is no action ${from}.` };
  if (to.toUpperCase() !== from.toUpperCase()) {
    const problem = nameProblem(copy, to);
    if (problem) return { error: problem };
  }
  action.name = to;
  const same = (name?: string | null) => name?.toUpperCase() === from.toUpperCase();
  for (const step of steps(copy)) {
    for (const a of step.actions ?? []) if (same(a.action)) a.action = to;
    if (same(step.entry)) step.entry = to;
    if (same(step.exit)) step.exit = to;
  }
  return { body: copy };
}

/** Renames a named transition: the chart transitions whose condition is its name follow. */
export function renameNamedTransition(body: SfcBody, from: string, to: string): EditResult {
  const copy = clone(body);
  const transition = copy.transitions?.find((t) => t.name === from);
  if (!transition) return { error: `There is no transition ${from}.` };
  if (to.toUpperCase() !== from.toUpperCase()) {
    const problem = nameProblem(copy, to);
    if (problem) return { error: problem };
  }
  transition.name = to;
  for (const { element } of walk(chartOf(copy)))
    if (
      kindOf(element) === "transition" &&
      (element as SfcTransition).condition?.trim().toUpperCase() === from.toUpperCase()
    )
      (element as SfcTransition).condition = to;
  return { body: copy };
}

export function removePart(body: SfcBody, kind: "action" | "transition", name: string): EditResult {
  const copy = clone(body);
  if (kind === "action") copy.actions = (copy.actions ?? []).filter((a) => a.name !== name);
  else copy.transitions = (copy.transitions ?? []).filter((t) => t.name !== name);
  return { body: copy };
}

export function setPartBody(
  body: SfcBody,
  kind: "action" | "transition",
  name: string,
  content: SfcAction["body"],
): SfcBody {
  const copy = clone(body);
  const list = (kind === "action" ? copy.actions : copy.transitions) ?? [];
  const part = list.find((p) => p.name === name);
  if (part) part.body = content as never;
  return copy;
}

// ------------------------------------------------------------------ clipboard

/** What a copy takes: the element and its partner (a step with the transition after it, or the reverse). */
export function copyFragment(body: SfcBody, id: string): Sequence | null {
  const place = locate(body, id);
  if (!place) return null;
  const { sequence, index, element } = place;
  const next = sequence[index + 1];
  const fragment =
    next && kindOf(next) !== "jump" && isStepLike(next) !== isStepLike(element) ? [element, next] : [element];
  return structuredClone(fragment);
}

/** Pastes a copied fragment below the selection when it fits there (it starts with what may follow it); new
 * ids, and step names made unique. */
export function pasteFragment(body: SfcBody, id: string, fragment: Sequence): EditResult {
  return edit(body, id, ({ sequence, index, element }, copy) => {
    const first = fragment[0];
    if (!first) return { error: "Nothing to paste." };
    if (kindOf(element) === "jump" || isStepLike(first) === isStepLike(element))
      return { error: isStepLike(first) ? "Paste steps below a transition." : "Paste transitions below a step." };
    const ids = usedIds(copy);
    const names = usedNames(copy);
    const pasted = structuredClone(fragment);
    const renamed = new Map<string, string>();
    for (const place of walk(pasted)) {
      const e = place.element;
      e.id = freshId(kindOf(e) === "step" ? "s" : kindOf(e) === "transition" ? "t" : kindOf(e).slice(0, 3), ids);
      if (kindOf(e) === "step") {
        const step = e as SfcStep;
        for (const a of step.actions ?? []) a.id = freshId("a", ids);
        const fresh = names.has(step.name.toUpperCase()) ? freshName(step.name, names) : step.name;
        names.add(fresh.toUpperCase());
        renamed.set(step.name.toUpperCase(), fresh);
        step.name = fresh;
      }
    }
    for (const { element: e } of walk(pasted))
      if (kindOf(e) === "jump") {
        const jump = e as { target: string };
        jump.target = renamed.get(jump.target.toUpperCase()) ?? jump.target;
      }
    const last = pasted[pasted.length - 1]!;
    const after = sequence[index + 1];
    if (after && kindOf(last) !== "jump" && isStepLike(last) === isStepLike(after))
      return { error: "That does not fit here: the pasted part would stand next to an element of its own kind." };
    sequence.splice(index + 1, 0, ...pasted);
    return { body: copy, select: first.id };
  });
}

export const CLIP_KIND = "ladderlab/sfc";

export function serializeFragment(fragment: Sequence): string {
  return JSON.stringify({ kind: CLIP_KIND, elements: fragment });
}

export function parseFragment(text: string): Sequence | null {
  try {
    const data = JSON.parse(text) as { kind?: unknown; elements?: unknown };
    return data.kind === CLIP_KIND && Array.isArray(data.elements) ? (data.elements as SfcElement[]) : null;
  } catch {
    return null;
  }
}
