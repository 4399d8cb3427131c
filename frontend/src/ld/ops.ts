// Editing operations on an LD body: pure functions from a body to a new body. Each one checks its
// result with ldProblems() and refuses (ok: false, with a reason) rather than return a broken rung,
// so whatever sequence of edits the user makes, the model stays valid.
import { freshId, idPrefix, usedIds, withFreshIds } from "./ids";
import {
  boxInputs,
  boxOutputs,
  COIL_MODES,
  CONTACT_MODES,
  elementsOf,
  locate,
  mapNetworks,
  networksOf,
  sameSeries,
  seriesAt,
  updateElement,
  updateSeries,
  walk,
  type CoilMode,
  type CompareOp,
  type ContactMode,
  type LdBody,
  type LdElement,
  type LdNetwork,
  type Location,
  type Place,
  type Series,
} from "./model";
import { isOutput, isValidLabel, ldProblems } from "./validate";

/** A new element before it gets its id. */
export type ElementSpec = LdElement extends infer E ? (E extends LdElement ? Omit<E, "id"> : never) : never;

export type EditResult =
  { ok: true; body: LdBody; /** ids to select after the edit */ select: string[] } | { ok: false; error: string };

/** Which text of an element an operand edit changes. */
export type OperandField =
  | { kind: "var" }
  | { kind: "left" }
  | { kind: "right" }
  | { kind: "instance" }
  | { kind: "target" }
  | { kind: "input"; pin: string }
  | { kind: "output"; pin: string };

export const contact = (mode: ContactMode = "no", variable = ""): ElementSpec => ({
  type: "contact",
  mode,
  var: variable,
});
export const coil = (mode: CoilMode = "normal", variable = ""): ElementSpec => ({ type: "coil", mode, var: variable });
export const compare = (op: CompareOp = "GT"): ElementSpec => ({ type: "compare", op, left: "", right: "" });
export const jump = (target = ""): ElementSpec => ({ type: "jump", target });
export const ret = (): ElementSpec => ({ type: "return" });
export const box = (call: string, instance: string | null = null, en = false): ElementSpec => ({
  type: "box",
  call,
  instance,
  inputs: {},
  outputs: {},
  en,
});

const seriesOf = (body: LdBody, ref: Place["series"]): Series => seriesAt(body, ref) ?? [];

const fail = (error: string): EditResult => ({ ok: false, error });

/** Accepts `next` only when it is valid; the first problem becomes the refusal's reason. */
function finish(next: LdBody, select: string[]): EditResult {
  const problems = ldProblems(next);
  return problems.length ? fail(problems[0]!.message) : { ok: true, body: next, select };
}

const specIsOutput = (spec: ElementSpec): boolean => isOutput({ ...spec, id: "" } as LdElement);

function withId(spec: ElementSpec, used: Set<string>): LdElement {
  const probe = { ...spec, id: "" } as LdElement;
  return { ...spec, id: freshId(idPrefix(probe), used) } as LdElement;
}

function spliceAt(body: LdBody, place: Place, elements: LdElement[], remove = 0): LdBody {
  return updateSeries(body, place.series, (series) => [
    ...series.slice(0, place.index),
    ...elements,
    ...series.slice(place.index + remove),
  ]);
}

/** Why a place is not on a wire of this body, or null when it is. */
function placeProblem(body: LdBody, place: Place): string | null {
  const series = seriesAt(body, place.series);
  return series && place.index >= 0 && place.index <= series.length ? null : "no such place in this diagram";
}

/** Inserts a new element at a place on a wire (no fallback). */
export function insertAt(body: LdBody, place: Place, spec: ElementSpec): EditResult {
  const problem = placeProblem(body, place);
  if (problem) return fail(problem);
  const element = withId(spec, usedIds(body));
  return finish(spliceAt(body, place, [element]), [element.id]);
}

/** Where a rung ends: its last index, before a final jump or return. */
function rungEnd(body: LdBody, network: string): Place | undefined {
  const net = networksOf(body).find((n) => n.id === network);
  if (!net) return undefined;
  const elements = elementsOf(net);
  const last = elements[elements.length - 1];
  const index = last && (last.type === "jump" || last.type === "return") ? elements.length - 1 : elements.length;
  return { series: { kind: "network", network }, index };
}

/** The first index of the trailing outputs of a series (its length when it has none). */
function firstOutput(series: Series): number {
  const i = series.findIndex(isOutput);
  return i < 0 ? series.length : i;
}

/**
 * Inserts next to an element or at the end of a network's rung, landing where the element can go:
 * a contact, compare or box asked for after a coil goes before the coils of that series; a coil,
 * jump or return asked for inside the inputs goes to the end of that series, else to the rung end.
 */
export function insertNear(
  body: LdBody,
  anchor: { element: string; side: "before" | "after" } | { network: string },
  spec: ElementSpec,
): EditResult {
  const candidates: Place[] = [];
  if ("network" in anchor) {
    const end = rungEnd(body, anchor.network);
    if (!end) return fail(`no network ${anchor.network}`);
    const series = elementsOf(networksOf(body).find((n) => n.id === anchor.network)!);
    candidates.push(specIsOutput(spec) ? end : { series: end.series, index: firstOutput(series) });
  } else {
    const where = locate(body, anchor.element);
    if (!where) return fail(`no element ${anchor.element}`);
    const series = seriesOf(body, where.series);
    candidates.push({ series: where.series, index: where.index + (anchor.side === "after" ? 1 : 0) });
    if (specIsOutput(spec)) {
      candidates.push({ series: where.series, index: series.length });
      const end = rungEnd(body, where.network);
      if (end) candidates.push(end);
    } else {
      candidates.push({ series: where.series, index: Math.min(firstOutput(series), where.index + 1) });
    }
  }
  let first: EditResult | undefined;
  for (const place of candidates) {
    const result = insertAt(body, place, spec);
    if (result.ok) return result;
    first ??= result;
  }
  return first!;
}

/**
 * The ids from `anchor` to `focus` when both are in one series (in series order), else just
 * `focus`: the range a shift-selection covers and a parallel branch wraps.
 */
export function rangeIds(body: LdBody, anchor: string, focus: string): string[] {
  const a = locate(body, anchor);
  const b = locate(body, focus);
  if (!a || !b) return b ? [focus] : [];
  if (!sameSeries(a.series, b.series)) return [focus];
  const series = seriesOf(body, a.series);
  const [lo, hi] = a.index <= b.index ? [a.index, b.index] : [b.index, a.index];
  return series.slice(lo, hi + 1).map((e) => e.id);
}

/** Finds a contiguous run of `ids` in one series: the place of its first element and its length. */
function runOf(body: LdBody, ids: string[]): { place: Place; length: number } | string {
  if (ids.length === 0) return "nothing selected";
  const locations = ids.map((id) => locate(body, id));
  if (locations.some((l) => !l)) return "the selection names an element that does not exist";
  const first = locations[0]!;
  if (!locations.every((l) => sameSeries(l!.series, first.series))) return "select elements of one branch";
  const indexes = locations.map((l) => l!.index).sort((x, y) => x - y);
  if (indexes.some((v, i) => v !== indexes[0]! + i)) return "select adjacent elements";
  return { place: { series: first.series, index: indexes[0]! }, length: ids.length };
}

/**
 * Wraps the selected run in a parallel with a second branch holding one new element: a coil when
 * the run holds an output (parallel coils), a contact otherwise (an OR).
 */
export function wrapInParallel(body: LdBody, ids: string[]): EditResult {
  const run = runOf(body, ids);
  if (typeof run === "string") return fail(run);
  const series = seriesOf(body, run.place.series);
  const wrapped = series.slice(run.place.index, run.place.index + run.length);
  const used = usedIds(body);
  const added = withId(wrapped.some(isOutput) ? coil() : contact(), used);
  const parallel: LdElement = { type: "parallel", id: freshId("par", used), branches: [wrapped, [added]] };
  return finish(spliceAt(body, run.place, [parallel], run.length), [added.id]);
}

/** Adds a branch below the others with one new element (a coil when the parallel drives outputs). */
export function addBranch(body: LdBody, parallelId: string): EditResult {
  const where = locate(body, parallelId);
  if (where?.element.type !== "parallel") return fail("select a parallel branch to add a branch to it");
  const added = withId(isOutput(where.element) ? coil() : contact(), usedIds(body));
  const next = updateElement(body, parallelId, (e) =>
    e.type === "parallel" ? { ...e, branches: [...e.branches, [added]] } : e,
  );
  return finish(next, [added.id]);
}

/**
 * Removes empty branches and box input series, and dissolves a parallel left with one branch into
 * its series: the tidy-up after elements were taken out.
 */
function normaliseSeries(series: Series): Series {
  const out: Series = [];
  for (const element of series) {
    if (element.type === "parallel") {
      const branches = element.branches.map(normaliseSeries).filter((b) => b.length > 0);
      if (branches.length === 1) out.push(...branches[0]!);
      else if (branches.length > 1) out.push({ ...element, branches });
    } else if (element.type === "box") {
      const inputs = Object.fromEntries(
        Object.entries(boxInputs(element))
          .map(([pin, value]) => [pin, Array.isArray(value) ? normaliseSeries(value) : value] as const)
          .filter(([, value]) => !Array.isArray(value) || value.length > 0),
      );
      out.push({ ...element, inputs });
    } else {
      out.push(element);
    }
  }
  return out;
}

function withoutIds(body: LdBody, ids: Set<string>): LdBody {
  const strip = (series: Series): Series =>
    series
      .filter((e) => !ids.has(e.id))
      .map((e) => {
        if (e.type === "parallel") return { ...e, branches: e.branches.map(strip) };
        if (e.type === "box") {
          const inputs = Object.fromEntries(
            Object.entries(boxInputs(e)).map(([pin, v]) => [pin, Array.isArray(v) ? strip(v) : v]),
          );
          return { ...e, inputs };
        }
        return e;
      });
  return mapNetworks(body, (network) => {
    const elements = elementsOf(network);
    if (!containsAny(elements, ids)) return network;
    return { ...network, elements: normaliseSeries(strip(elements)) };
  });
}

function containsAny(series: Series, ids: Set<string>): boolean {
  return series.some(
    (e) =>
      ids.has(e.id) ||
      (e.type === "parallel" && e.branches.some((b) => containsAny(b, ids))) ||
      (e.type === "box" && Object.values(boxInputs(e)).some((v) => Array.isArray(v) && containsAny(v, ids))),
  );
}

/** Deletes elements (with everything nested in them); selects what took the first one's place. */
export function deleteElements(body: LdBody, ids: string[]): EditResult {
  if (ids.length === 0) return fail("nothing selected");
  const first = locate(body, ids[0]!);
  if (!first) return fail(`no element ${ids[0]}`);
  const next = withoutIds(body, new Set(ids));
  const problems = ldProblems(next);
  if (problems.length) return fail(`cannot delete: ${problems[0]!.message}`);
  const survivor = neighbourAfterDelete(body, next, first);
  return { ok: true, body: next, select: survivor ? [survivor] : [] };
}

/**
 * What to select after deleting: the next surviving element of the same series, else the previous
 * one, else (one level up) whatever took the place of the enclosing parallel or box, and so on.
 */
function neighbourAfterDelete(body: LdBody, next: LdBody, first: Location): string | undefined {
  const candidates: string[] = [];
  let at: Location | undefined = first;
  while (at) {
    const series = seriesOf(body, at.series);
    candidates.push(
      ...series.slice(at.index + 1).map((e) => e.id),
      ...series
        .slice(0, at.index)
        .reverse()
        .map((e) => e.id),
    );
    const owner: string | undefined =
      at.series.kind === "branch" ? at.series.parallel : at.series.kind === "pin" ? at.series.box : undefined;
    at = owner === undefined ? undefined : locate(body, owner);
    if (at) candidates.push(...[...walk({ networks: [{ id: "", elements: [at.element] }] })].map((l) => l.element.id));
  }
  return candidates.find((id) => locate(next, id));
}

/** Sets a contact's or coil's mode (GR-15..GR-25). */
export function setMode(body: LdBody, id: string, mode: ContactMode | CoilMode): EditResult {
  const where = locate(body, id);
  const e = where?.element;
  if (e?.type === "contact" && (CONTACT_MODES as readonly string[]).includes(mode)) {
    return finish(
      updateElement(body, id, () => ({ ...e, mode: mode as ContactMode })),
      [id],
    );
  }
  if (e?.type === "coil" && (COIL_MODES as readonly string[]).includes(mode)) {
    return finish(
      updateElement(body, id, () => ({ ...e, mode: mode as CoilMode })),
      [id],
    );
  }
  return fail(e ? `a ${e.type} has no mode ${mode}` : `no element ${id}`);
}

/** The next mode in the IEC order (contact no -> nc -> p -> n; coil normal -> ... -> n), wrapping. */
export function cycleMode(body: LdBody, id: string): EditResult {
  const e = locate(body, id)?.element;
  if (e?.type === "contact") {
    const i = CONTACT_MODES.indexOf(e.mode ?? "no");
    return setMode(body, id, CONTACT_MODES[(i + 1) % CONTACT_MODES.length]!);
  }
  if (e?.type === "coil") {
    const i = COIL_MODES.indexOf(e.mode ?? "normal");
    return setMode(body, id, COIL_MODES[(i + 1) % COIL_MODES.length]!);
  }
  if (e?.type === "compare") return setCompareOp(body, id, nextOp(e.op));
  return fail("only contacts, coils and compare contacts have a mode");
}

const OPS: readonly CompareOp[] = ["GT", "GE", "EQ", "LE", "LT", "NE"];
const nextOp = (op: CompareOp): CompareOp => OPS[(OPS.indexOf(op) + 1) % OPS.length]!;

export function setCompareOp(body: LdBody, id: string, op: CompareOp): EditResult {
  const e = locate(body, id)?.element;
  if (e?.type !== "compare") return fail("not a compare contact");
  return finish(
    updateElement(body, id, () => ({ ...e, op })),
    [id],
  );
}

/** Sets an operand text. An empty box pin text disconnects the pin (the key is removed). */
export function setOperand(body: LdBody, id: string, field: OperandField, text: string): EditResult {
  const e = locate(body, id)?.element;
  if (!e) return fail(`no element ${id}`);
  const value = text.trim();
  let next: LdElement | undefined;
  if (field.kind === "var" && (e.type === "contact" || e.type === "coil")) next = { ...e, var: value };
  else if (field.kind === "left" && e.type === "compare") next = { ...e, left: value };
  else if (field.kind === "right" && e.type === "compare") next = { ...e, right: value };
  else if (field.kind === "target" && e.type === "jump") next = { ...e, target: value };
  else if (field.kind === "instance" && e.type === "box") next = { ...e, instance: value || null };
  else if (field.kind === "input" && e.type === "box") {
    const { [field.pin]: _old, ...rest } = boxInputs(e);
    next = { ...e, inputs: value ? { ...rest, [field.pin]: value } : rest };
  } else if (field.kind === "output" && e.type === "box") {
    const { [field.pin]: _old, ...rest } = boxOutputs(e);
    next = { ...e, outputs: value ? { ...rest, [field.pin]: value } : rest };
  }
  if (!next) return fail(`a ${e.type} has no ${field.kind} operand`);
  const replaced = next;
  return finish(
    updateElement(body, id, () => replaced),
    [id],
  );
}

/** Shows or hides a box's EN/ENO pins. */
export function toggleEn(body: LdBody, id: string): EditResult {
  const e = locate(body, id)?.element;
  if (e?.type !== "box") return fail("only boxes have EN/ENO");
  return finish(
    updateElement(body, id, () => ({ ...e, en: !(e.en ?? false) })),
    [id],
  );
}

/** Feeds a box input from the left rail through a new series holding one contact. */
export function feedPinFromRail(body: LdBody, boxId: string, pin: string): EditResult {
  const e = locate(body, boxId)?.element;
  if (e?.type !== "box") return fail("not a box");
  const added = withId(contact(), usedIds(body));
  return finish(
    updateElement(body, boxId, () => ({ ...e, inputs: { ...boxInputs(e), [pin]: [added] } })),
    [added.id],
  );
}

/**
 * Moves a run of elements to a place (given in the body before the move). A marker holds the
 * place while the run is taken out, so indexes need no adjusting.
 */
export function moveElements(body: LdBody, ids: string[], place: Place): EditResult {
  const run = runOf(body, ids);
  if (typeof run === "string") return fail(run);
  const series = seriesOf(body, run.place.series);
  const moved = series.slice(run.place.index, run.place.index + run.length);
  const used = usedIds(body);
  const marker: LdElement = { type: "contact", id: freshId("__drop", used), var: "" };
  const problem = placeProblem(body, place);
  if (problem) return fail(problem);
  const marked = spliceAt(body, place, [marker]);
  const taken = withoutIds(marked, new Set(ids));
  const at = locate(taken, marker.id);
  if (!at) return fail("cannot move an element into itself");
  const next = spliceAt(taken, { series: at.series, index: at.index }, moved, 1);
  return finish(next, ids);
}

/** Pastes copies of elements at a place; clashing ids get fresh ones. */
export function pasteElements(body: LdBody, place: Place, elements: LdElement[]): EditResult {
  if (elements.length === 0) return fail("the clipboard holds no elements");
  const problem = placeProblem(body, place);
  if (problem) return fail(problem);
  const used = usedIds(body);
  const copies = elements.map((e) => withFreshIds(e, used));
  return finish(
    spliceAt(body, place, copies),
    copies.map((e) => e.id),
  );
}

// ---- networks ----

function newNetwork(used: Set<string>, elements: Series = []): LdNetwork {
  return { id: freshId("n", used), elements };
}

/** Inserts an empty network at `index` (0 = first). */
export function addNetwork(body: LdBody, index: number): EditResult {
  const networks = networksOf(body);
  const network = newNetwork(usedIds(body));
  const at = Math.max(0, Math.min(index, networks.length));
  return finish({ ...body, networks: [...networks.slice(0, at), network, ...networks.slice(at)] }, [network.id]);
}

export function deleteNetworks(body: LdBody, ids: string[]): EditResult {
  const networks = networksOf(body);
  const remove = new Set(ids);
  if (!networks.some((n) => remove.has(n.id))) return fail("no such network");
  const firstIndex = networks.findIndex((n) => remove.has(n.id));
  const rest = networks.filter((n) => !remove.has(n.id));
  const neighbour = rest[Math.min(firstIndex, rest.length - 1)];
  return finish({ ...body, networks: rest }, neighbour ? [neighbour.id] : []);
}

/** Moves a network to position `index` of the list without it. */
export function moveNetwork(body: LdBody, id: string, index: number): EditResult {
  const networks = networksOf(body);
  const network = networks.find((n) => n.id === id);
  if (!network) return fail(`no network ${id}`);
  const rest = networks.filter((n) => n.id !== id);
  const at = Math.max(0, Math.min(index, rest.length));
  return finish({ ...body, networks: [...rest.slice(0, at), network, ...rest.slice(at)] }, [id]);
}

/** Copies networks into the body at `index` with fresh ids; a label already in use is dropped. */
export function pasteNetworks(body: LdBody, index: number, copies: LdNetwork[]): EditResult {
  if (copies.length === 0) return fail("the clipboard holds no networks");
  const networks = networksOf(body);
  const used = usedIds(body);
  const labels = new Set(networks.map((n) => n.label?.toUpperCase()).filter(Boolean));
  const fresh = copies.map((n) => {
    const label = n.label && !labels.has(n.label.toUpperCase()) ? n.label : null;
    if (label) labels.add(label.toUpperCase());
    const id = used.has(n.id) ? freshId("n", used) : (used.add(n.id), n.id);
    return { ...n, id, label, elements: elementsOf(n).map((e) => withFreshIds(e, used)) };
  });
  const at = Math.max(0, Math.min(index, networks.length));
  return finish(
    { ...body, networks: [...networks.slice(0, at), ...fresh, ...networks.slice(at)] },
    fresh.map((n) => n.id),
  );
}

export function duplicateNetwork(body: LdBody, id: string): EditResult {
  const networks = networksOf(body);
  const index = networks.findIndex((n) => n.id === id);
  if (index < 0) return fail(`no network ${id}`);
  return pasteNetworks(body, index + 1, [networks[index]!]);
}

/** Sets or clears (null or blank) a network label; labels are unique identifiers or numbers. */
export function setNetworkLabel(body: LdBody, id: string, label: string | null): EditResult {
  const value = label?.trim() || null;
  if (value !== null && !isValidLabel(value))
    return fail(`label ${JSON.stringify(value)} is not an identifier or number`);
  return setNetworkField(body, id, { label: value });
}

export function setNetworkComment(body: LdBody, id: string, comment: string | null): EditResult {
  return setNetworkField(body, id, { comment: comment?.trim() ? comment : null });
}

function setNetworkField(body: LdBody, id: string, patch: Partial<LdNetwork>): EditResult {
  if (!networksOf(body).some((n) => n.id === id)) return fail(`no network ${id}`);
  return finish(
    mapNetworks(body, (n) => (n.id === id ? { ...n, ...patch } : n)),
    [id],
  );
}
