// @vitest-environment jsdom
// FBD <-> CFC conversion (issue 26 brief item 5): networks stacked on one chart numbered in their FBD order;
// a chart back to FBD only when its numbers are the data-flow order.
import { describe, expect, it } from "vitest";
import { cfcToFbd, fbdToCfc } from "./convert";
import { arithmetic, bodyOf, wire } from "./fixtures";
import type { FbdNetwork } from "./model";

const second = (): FbdNetwork => ({
  id: "n2",
  nodes: [
    { type: "input", id: "x", expr: "result", pos: { x: 0, y: 10 } },
    { type: "output", id: "y", var: "copy", pos: { x: 200, y: 10 } },
  ],
  wires: [wire("x", "OUT", "y", "IN")],
});

describe("FBD -> CFC", () => {
  it("stacks the networks and numbers the executed elements network by network, in their FBD order", () => {
    const orders = new Map([
      ["n1", ["a", "b", "add", "c", "sub", "r"]],
      ["n2", ["x", "y"]],
    ]);
    const result = fbdToCfc(bodyOf(arithmetic(), second()), orders, () => 150);
    expect(result.ok).toBe(true);
    const chart = result.ok ? result.body.networks![0]! : null;
    expect(chart?.id).toBe("chart");
    expect(chart?.order).toEqual(["add", "sub", "r", "y"]); // inputs have no number (read where used)
    expect(chart?.wires).toHaveLength(6);
    // the second network sits below the first: its y moved by the first's height and the gap
    expect(chart?.nodes?.find((n) => n.id === "y")?.pos).toEqual({ x: 200, y: 10 + 150 + 40 });
    expect(chart?.nodes?.find((n) => n.id === "add")?.pos).toEqual({ x: 200, y: 0 });
  });

  it("refuses a jump and a connector name two networks use, and waits for every order", () => {
    const jumping = { ...second(), nodes: [...second().nodes!, { type: "jump" as const, id: "j", target: "End" }] };
    const orders = new Map([
      ["n1", ["a"]],
      ["n2", ["x"]],
    ]);
    expect(fbdToCfc(bodyOf(arithmetic(), jumping), orders, () => 100)).toEqual({
      ok: false,
      error:
        "Network 2 jumps to End: a CFC chart has no networks to jump to (its jumps go to label elements). Remove the jump first.",
    });
    const k = (network: FbdNetwork): FbdNetwork => ({
      ...network,
      nodes: [...network.nodes!, { type: "connector", id: `k${network.id}`, name: "sum" }],
    });
    expect(fbdToCfc(bodyOf(k(arithmetic()), k(second())), orders, () => 100)).toEqual({
      ok: false,
      error: "Networks 1 and 2 both have a connector sum: on one chart the names must differ. Rename one first.",
    });
    expect(fbdToCfc(bodyOf(arithmetic(), second()), new Map([["n1", ["a"]]]), () => 100)).toEqual({
      ok: false,
      error: "The execution order of network 2 is not known yet: try again.",
    });
  });
});

describe("CFC -> FBD", () => {
  const chart = () => bodyOf({ ...arithmetic(), id: "chart" });
  const flow = ["a", "b", "add", "c", "sub", "r"];

  it("makes the chart one network when its numbers are the data-flow order", () => {
    const result = cfcToFbd(chart(), ["add", "sub", "r"], flow);
    expect(result).toEqual({
      ok: true,
      body: { networks: [{ ...arithmetic(), id: "n1", order: ["add", "sub", "r"] }] },
    });
  });

  it("refuses a chart that runs an element before the block feeding it, naming both", () => {
    expect(cfcToFbd(chart(), ["sub", "add", "r"], flow)).toEqual({
      ok: false,
      error:
        'The chart runs SUB as number 1, where data flow would run ADD: FBD cannot keep that order. Use "Order by ' +
        'data flow" first (it changes what the chart computes), or keep the chart.',
    });
  });

  it("refuses a chart with jumps or labels (issue 26: CFC jumps go to label elements, FBD jumps to networks)", () => {
    const labelled = bodyOf({
      ...arithmetic(),
      id: "chart",
      nodes: [...arithmetic().nodes!, { type: "label" as const, id: "l", name: "Again" }],
    });
    expect(cfcToFbd(labelled, ["add", "sub", "r"], flow)).toEqual({
      ok: false,
      error:
        "The chart has a label: a chart's jumps go to its label elements, FBD's to whole networks. Remove the " +
        "jumps and labels first, or keep the chart.",
    });
  });
});
