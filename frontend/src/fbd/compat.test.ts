// @vitest-environment jsdom
// Which wires the FBD editor accepts (issue 9: "Wires only connect type-compatible pins").
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { ELEMENTARY, widens } from "../iec/vocabulary";
import { compatible, FAMILIES, outputType, refusal, typeSet } from "./compat";
import { arithmetic, lookup, SYMBOLS, wire } from "./fixtures";
import type { FbdNetwork } from "./model";

const elementary = fc.constantFrom(...ELEMENTARY);
const family = fc.constantFrom(...Object.keys(FAMILIES));

describe("type compatibility", () => {
  it("refuses an INT output into a BOOL input and accepts the same type", () => {
    expect(compatible("INT", "BOOL")).toBe(false);
    expect(compatible("INT", "INT")).toBe(true);
    expect(compatible("BOOL", "ANY_BIT")).toBe(true);
    expect(compatible("ANY_NUM", "ANY_BIT")).toBe(false);
    expect(compatible("TIME", "ANY_NUM")).toBe(false);
    expect(compatible("tod", "TIME_OF_DAY")).toBe(true);
  });

  it("accepts lossless widenings only (st/types.py assignable)", () => {
    expect(compatible("INT", "DINT")).toBe(true);
    expect(compatible("DINT", "INT")).toBe(false);
    expect(compatible("USINT", "INT")).toBe(true);
    expect(compatible("UINT", "INT")).toBe(false);
    expect(compatible("INT", "REAL")).toBe(false); // ST-20: integer -> REAL needs a conversion
    expect(compatible("REAL", "LREAL")).toBe(true);
    expect(compatible("ANY_LITERAL_INT", "BOOL")).toBe(true);
  });

  it("every elementary type feeds itself and every family holding it", () => {
    fc.assert(fc.property(elementary, (t) => compatible(t, t)));
    fc.assert(fc.property(elementary, family, (t, f) => !FAMILIES[f]!.includes(t) || compatible(t, f)));
  });

  it("a family feeds a concrete type exactly when one member is it or widens to it", () => {
    fc.assert(
      fc.property(family, elementary, (f, t) => compatible(f, t) === FAMILIES[f]!.some((m) => m === t || widens(m, t))),
    );
  });

  it("widening is a strict order: irreflexive, antisymmetric, transitive", () => {
    fc.assert(
      fc.property(elementary, elementary, elementary, (a, b, c) => {
        expect(widens(a, a)).toBe(false);
        if (widens(a, b)) expect(widens(b, a)).toBe(false);
        if (widens(a, b) && widens(b, c)) expect(widens(a, c)).toBe(true);
      }),
    );
  });

  it("accepts what it cannot resolve: user types, arrays, unknown pins", () => {
    fc.assert(
      fc.property(
        fc.constantFrom("MyStruct", "ARRAY[1..3] OF INT", "STRING[20]", undefined),
        elementary,
        (u, t) => compatible(u, t) && compatible(t, u),
      ),
    );
    expect(typeSet("MyStruct")).toBeNull();
  });
});

describe("refusal of a wire", () => {
  const net = (): FbdNetwork => ({
    ...arithmetic(),
    nodes: [
      ...(arithmetic().nodes ?? []),
      { type: "block", id: "and", call: "AND" },
      { type: "input", id: "f", expr: "flag" },
      { type: "output", id: "o", var: "flag" },
    ],
  });

  it("names the types when an INT output would feed a BOOL input", () => {
    expect(refusal(net(), { from: { node: "a", pin: "OUT" }, to: { node: "o", pin: "IN" } }, lookup, SYMBOLS)).toBe(
      "An INT output (a.OUT) cannot feed a BOOL input (o.IN).",
    );
  });

  it("accepts a block's output back into its own input (a feedback loop), not a node wired to itself", () => {
    const loop = { from: { node: "add", pin: "OUT" }, to: { node: "add", pin: "IN1" } };
    const own = net();
    own.wires = own.wires!.filter((w) => !(w.to.node === "add" && w.to.pin === "IN1"));
    expect(refusal(own, loop, lookup, SYMBOLS)).toBeNull();
    expect(outputType(own, { node: "add", pin: "OUT" }, lookup, SYMBOLS)).toBe("INT"); // from IN2, around the loop
    const connector = { ...own, nodes: [...own.nodes!, { type: "connector" as const, id: "k", name: "x" }] };
    expect(refusal(connector, { from: { node: "k", pin: "OUT" }, to: { node: "k", pin: "IN" } }, lookup, SYMBOLS)).toBe(
      "A wire cannot connect a node to itself.",
    );
  });

  it("follows a generic result back to its inputs: ADD of two INTs is an INT", () => {
    expect(outputType(net(), { node: "add", pin: "OUT" }, lookup, SYMBOLS)).toBe("INT");
    expect(
      refusal(net(), { from: { node: "sub", pin: "OUT" }, to: { node: "and", pin: "IN1" } }, lookup, SYMBOLS),
    ).toBe("An INT output (sub.OUT) cannot feed an ANY_BIT input (and.IN1).");
    expect(
      refusal(net(), { from: { node: "f", pin: "OUT" }, to: { node: "and", pin: "IN1" } }, lookup, SYMBOLS),
    ).toBeNull();
  });

  it("refuses a second wire into an occupied input (GR-30: no wired OR)", () => {
    expect(refusal(net(), { from: { node: "c", pin: "OUT" }, to: { node: "add", pin: "IN1" } }, lookup, SYMBOLS)).toBe(
      "Input IN1 of add is already wired from a.OUT: FBD has no wired OR (use an OR block), delete that wire first.",
    );
  });

  it("follows a continuation to what feeds its connector", () => {
    const n: FbdNetwork = {
      id: "n",
      nodes: [
        { type: "input", id: "a", expr: "var1" },
        { type: "connector", id: "k", name: "x" },
        { type: "continuation", id: "k2", name: "X" },
        { type: "output", id: "o", var: "flag" },
      ],
      wires: [wire("a", "OUT", "k", "IN")],
    };
    expect(outputType(n, { node: "k2", pin: "OUT" }, lookup, SYMBOLS)).toBe("INT");
    expect(refusal(n, { from: { node: "k2", pin: "OUT" }, to: { node: "o", pin: "IN" } }, lookup, SYMBOLS)).toMatch(
      /cannot feed a BOOL input/,
    );
  });
});
