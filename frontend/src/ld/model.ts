// The LD model as the editor sees it: the generated project types plus the defaults the schema
// leaves optional, and addressing of series lists so pure edits can rebuild only what changed.
import type { Box, LdBody, LdNetwork } from "../generated/api";

export type { Box, Coil, Compare, Contact, Jump, LdBody, LdNetwork, Parallel, Return } from "../generated/api";

/** One element of a series list (contact, compare, coil, parallel, box, jump, return). */
export type LdElement = NonNullable<LdNetwork["elements"]>[number];
/** A series list: an AND chain from left to right. */
export type Series = LdElement[];
export type ContactMode = "no" | "nc" | "p" | "n";
export type CoilMode = "normal" | "negated" | "set" | "reset" | "p" | "n";
export type CompareOp = "GT" | "GE" | "EQ" | "LE" | "LT" | "NE";

export const CONTACT_MODES: readonly ContactMode[] = ["no", "nc", "p", "n"];
export const COIL_MODES: readonly CoilMode[] = ["normal", "negated", "set", "reset", "p", "n"];
export const COMPARE_OPS: readonly CompareOp[] = ["GT", "GE", "EQ", "LE", "LT", "NE"];

/** Where a series list lives: a network's rung, a branch of a parallel, or a box input pin. */
export type SeriesRef =
  | { kind: "network"; network: string }
  | { kind: "branch"; parallel: string; branch: number }
  | { kind: "pin"; box: string; pin: string };

/** A point on a wire: before element `index` of a series (index == length is its right end). */
export interface Place {
  series: SeriesRef;
  index: number;
}

/** Where an element sits: its series, its index there and the network holding it. */
export interface Location {
  network: string;
  series: SeriesRef;
  index: number;
  element: LdElement;
}

export const networksOf = (body: LdBody): LdNetwork[] => body.networks ?? [];
export const elementsOf = (network: LdNetwork): Series => network.elements ?? [];
export const boxInputs = (box: Box): NonNullable<Box["inputs"]> => box.inputs ?? {};
export const boxOutputs = (box: Box): NonNullable<Box["outputs"]> => box.outputs ?? {};

export function sameSeries(a: SeriesRef, b: SeriesRef): boolean {
  if (a.kind === "network" && b.kind === "network") return a.network === b.network;
  if (a.kind === "branch" && b.kind === "branch") return a.parallel === b.parallel && a.branch === b.branch;
  if (a.kind === "pin" && b.kind === "pin") return a.box === b.box && a.pin === b.pin;
  return false;
}

/** The series lists nested directly in an element, with their refs (branches, then box pins). */
export function childSeries(element: LdElement): { ref: SeriesRef; series: Series }[] {
  if (element.type === "parallel") {
    return element.branches.map((series, branch) => ({
      ref: { kind: "branch", parallel: element.id, branch },
      series,
    }));
  }
  if (element.type === "box") {
    return Object.entries(boxInputs(element))
      .filter((entry): entry is [string, Series] => Array.isArray(entry[1]))
      .map(([pin, series]) => ({ ref: { kind: "pin", box: element.id, pin }, series }));
  }
  return [];
}

/** Every element of the body, depth first in drawing order, with its location. */
export function* walk(body: LdBody): Generator<Location> {
  function* inSeries(network: string, ref: SeriesRef, series: Series): Generator<Location> {
    for (const [index, element] of series.entries()) {
      yield { network, series: ref, index, element };
      for (const child of childSeries(element)) yield* inSeries(network, child.ref, child.series);
    }
  }
  for (const network of networksOf(body)) {
    yield* inSeries(network.id, { kind: "network", network: network.id }, elementsOf(network));
  }
}

export function locate(body: LdBody, id: string): Location | undefined {
  for (const location of walk(body)) if (location.element.id === id) return location;
  return undefined;
}

/** The series list a ref points at, or undefined when it does not exist. */
export function seriesAt(body: LdBody, ref: SeriesRef): Series | undefined {
  if (ref.kind === "network") {
    const network = networksOf(body).find((n) => n.id === ref.network);
    return network ? elementsOf(network) : undefined;
  }
  const owner = locate(body, ref.kind === "branch" ? ref.parallel : ref.box)?.element;
  if (ref.kind === "branch") return owner?.type === "parallel" ? owner.branches[ref.branch] : undefined;
  const value = owner?.type === "box" ? boxInputs(owner)[ref.pin] : undefined;
  return Array.isArray(value) ? value : undefined;
}

/** The network a series lives in. */
export function networkOfSeries(body: LdBody, ref: SeriesRef): string | undefined {
  if (ref.kind === "network") return ref.network;
  return locate(body, ref.kind === "branch" ? ref.parallel : ref.box)?.network;
}

/**
 * Rebuilds the body with the series at `ref` replaced by `update(series)`. Everything off the path
 * keeps its identity, so views memoised on networks re-render only the network that changed.
 */
export function updateSeries(body: LdBody, ref: SeriesRef, update: (series: Series) => Series): LdBody {
  const mapSeries = (series: Series): Series => {
    let changed = false;
    const out = series.map((element) => {
      const next = mapElement(element);
      if (next !== element) changed = true;
      return next;
    });
    return changed ? out : series;
  };
  const mapElement = (element: LdElement): LdElement => {
    if (element.type === "parallel") {
      let changed = false;
      const branches = element.branches.map((branch, i) => {
        const next =
          ref.kind === "branch" && ref.parallel === element.id && ref.branch === i ? update(branch) : mapSeries(branch);
        if (next !== branch) changed = true;
        return next;
      });
      return changed ? { ...element, branches } : element;
    }
    if (element.type === "box") {
      let changed = false;
      const inputs = Object.fromEntries(
        Object.entries(boxInputs(element)).map(([pin, value]) => {
          if (!Array.isArray(value)) return [pin, value];
          const next =
            ref.kind === "pin" && ref.box === element.id && ref.pin === pin ? update(value) : mapSeries(value);
          if (next !== value) changed = true;
          return [pin, next];
        }),
      );
      return changed ? { ...element, inputs } : element;
    }
    return element;
  };
  return mapNetworks(body, (network) => {
    const elements = elementsOf(network);
    const next = ref.kind === "network" && ref.network === network.id ? update(elements) : mapSeries(elements);
    return next === elements ? network : { ...network, elements: next };
  });
}

/** Replaces one element (found anywhere) by `update(element)`. */
export function updateElement(body: LdBody, id: string, update: (element: LdElement) => LdElement): LdBody {
  const where = locate(body, id);
  if (!where) return body;
  return updateSeries(body, where.series, (series) => series.map((e, i) => (i === where.index ? update(e) : e)));
}

export function mapNetworks(body: LdBody, update: (network: LdNetwork) => LdNetwork): LdBody {
  const networks = networksOf(body);
  let changed = false;
  const next = networks.map((network) => {
    const out = update(network);
    if (out !== network) changed = true;
    return out;
  });
  return changed ? { ...body, networks: next } : body;
}
