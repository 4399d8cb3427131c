// fast-check generators of valid LD bodies for the property tests: random series/parallel trees of
// contacts, compares and boxes (with pins fed by series), ending in coils, parallel coils, a jump or
// a return. Ids are numbered after generation so they are unique.
import fc from "fast-check";
import type { ElementSpec } from "./ops";
import {
  COIL_MODES,
  CONTACT_MODES,
  COMPARE_OPS,
  type LdBody,
  type LdElement,
  type LdNetwork,
  type Series,
} from "./model";

type Draft = ElementSpec;

const contact = fc.record({
  type: fc.constant("contact" as const),
  var: fc.constantFrom("A", "B", "Motor", ""),
  mode: fc.constantFrom(...CONTACT_MODES),
});
const compare = fc.record({
  type: fc.constant("compare" as const),
  op: fc.constantFrom(...COMPARE_OPS),
  left: fc.constantFrom("N", "1"),
  right: fc.constantFrom("M", "10"),
});
const coil = fc.record({
  type: fc.constant("coil" as const),
  var: fc.constantFrom("Q1", "Q2", ""),
  mode: fc.constantFrom(...COIL_MODES),
});

const { inputSeries } = fc.letrec<{ inputElement: Draft; inputSeries: Draft[] }>((tie) => ({
  inputElement: fc.oneof(
    { maxDepth: 3, depthIdentifier: "ld" },
    contact,
    compare,
    fc
      .array(tie("inputSeries"), { minLength: 2, maxLength: 3 })
      .map((branches) => ({ type: "parallel" as const, branches: branches as LdElement[][] })),
    fc.record({
      type: fc.constant("box" as const),
      call: fc.constantFrom("TON", "CTU", "ADD", "Mystery"),
      instance: fc.constantFrom(null, "T1"),
      en: fc.boolean(),
      inputs: fc.dictionary(
        fc.constantFrom("PT", "R", "IN2"),
        fc.oneof(fc.constantFrom("T#1s", "5"), tie("inputSeries") as fc.Arbitrary<LdElement[]>),
        { maxKeys: 2 },
      ),
      outputs: fc.dictionary(fc.constantFrom("Q", "CV", "ET"), fc.constantFrom("V", "W"), { maxKeys: 2 }),
    }),
  ),
  inputSeries: fc.array(tie("inputElement"), { minLength: 1, maxLength: 3, depthIdentifier: "ld" }),
}));

const none = fc.constant<Draft[]>([]);
const outputs: fc.Arbitrary<Draft[]> = fc.oneof(
  none,
  fc.array(coil, { minLength: 1, maxLength: 2 }),
  fc
    .array(fc.tuple(fc.array(contact, { maxLength: 1 }), coil), { minLength: 2, maxLength: 3 })
    .map((bs) => [{ type: "parallel" as const, branches: bs.map(([pre, q]) => [...pre, q]) as LdElement[][] }]),
);
const terminal: fc.Arbitrary<Draft[]> = fc.oneof(
  none,
  fc.constant<Draft[]>([{ type: "return" }]),
  fc.constant<Draft[]>([{ type: "jump", target: "L1" }]),
);

const network = fc.record({
  inputs: fc.oneof(none, inputSeries),
  outputs,
  terminal,
  label: fc.constantFrom(null, "L1", "7"),
  comment: fc.constantFrom(null, "note"),
});

/** Gives every element and network a unique id, in drawing order. */
function numbered(networks: { elements: Draft[]; label: string | null; comment: string | null }[]): LdBody {
  let next = 0;
  const seriesIds = (series: Draft[]): Series => series.map(elementIds);
  const elementIds = (draft: Draft): LdElement => {
    const id = `e${(next += 1)}`;
    const e = { ...draft, id } as LdElement;
    if (e.type === "parallel") return { ...e, branches: e.branches.map((b) => seriesIds(b)) };
    if (e.type === "box") {
      return {
        ...e,
        inputs: Object.fromEntries(
          Object.entries(e.inputs ?? {}).map(([k, v]) => [k, Array.isArray(v) ? seriesIds(v) : v]),
        ),
      };
    }
    return e;
  };
  const labels = new Set<string>();
  return {
    networks: networks.map((n, i): LdNetwork => {
      const label = n.label && !labels.has(n.label) ? n.label : null;
      if (label) labels.add(label);
      return { id: `n${i + 1}`, label, comment: n.comment, elements: seriesIds(n.elements) };
    }),
  };
}

export const ldBody: fc.Arbitrary<LdBody> = fc
  .array(network, { minLength: 1, maxLength: 4 })
  .map((ns) =>
    numbered(
      ns.map((n) => ({ elements: [...n.inputs, ...n.outputs, ...n.terminal], label: n.label, comment: n.comment })),
    ),
  );
