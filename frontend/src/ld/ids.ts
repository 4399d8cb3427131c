// Fresh ids for new elements and networks. Ids are unique within a POU (they are the probe ids of
// live power flow), short and readable in the saved JSON: a type prefix and the smallest free number.
import { networksOf, walk, type LdBody, type LdElement } from "./model";

const PREFIX: Record<NonNullable<LdElement["type"]>, string> = {
  contact: "contact",
  compare: "compare",
  coil: "coil",
  parallel: "par",
  box: "box",
  jump: "jump",
  return: "ret",
};

/** Every id used in the body: networks and elements at any depth. */
export function usedIds(body: LdBody): Set<string> {
  const ids = new Set(networksOf(body).map((n) => n.id));
  for (const { element } of walk(body)) ids.add(element.id);
  return ids;
}

/** The first `<prefix><n>` not in `used`; adds it to `used` so repeated calls stay unique. */
export function freshId(prefix: string, used: Set<string>): string {
  let n = 1;
  while (used.has(`${prefix}${n}`)) n += 1;
  const id = `${prefix}${n}`;
  used.add(id);
  return id;
}

export const idPrefix = (element: LdElement): string => PREFIX[element.type ?? "contact"];

/**
 * A deep copy of `element` whose id and nested ids are fresh where they clash with `used`
 * (ids that are still free are kept, so pasting into another POU keeps the original ids).
 */
export function withFreshIds(element: LdElement, used: Set<string>): LdElement {
  const id = used.has(element.id) ? freshId(idPrefix(element), used) : (used.add(element.id), element.id);
  const copySeries = (series: LdElement[]) => series.map((e) => withFreshIds(e, used));
  if (element.type === "parallel") return { ...element, id, branches: element.branches.map(copySeries) };
  if (element.type === "box") {
    const inputs = Object.fromEntries(
      Object.entries(element.inputs ?? {}).map(([pin, v]) => [pin, Array.isArray(v) ? copySeries(v) : v]),
    );
    return { ...element, id, inputs, outputs: { ...element.outputs } };
  }
  return { ...element, id };
}
