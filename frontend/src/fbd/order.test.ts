// @vitest-environment jsdom
// A CFC chart's execution order (docs/diagrams.md "CFC", CFC-02): numbers over the executed elements,
// moves that may go against the wiring, and "order by data flow" from the backend's FBD order.
import { describe, expect, it } from "vitest";
import { arithmetic, bodyOf } from "./fixtures";
import type { FbdBody } from "./model";
import { arrangeNetwork } from "./ops";
import { IEC } from "../generated/iec";
import { EXECUTED, feedbackPins, moveInOrder, orderByDataFlow, orderNumbers } from "./order";

// arithmetic(): inputs a, b -> add -> sub (with input c) -> output r
const chart = (): FbdBody =>
  bodyOf({ ...arithmetic(), nodes: [...(arithmetic().nodes ?? []), { type: "return", id: "ret" }] });
const network = () => chart().networks![0]!;
const reported = ["a", "b", "add", "c", "sub", "r", "ret"];

describe("CFC execution order", () => {
  it("numbers the executed elements only: inputs are read where used (CFC-02)", () => {
    expect([...orderNumbers(network(), reported)]).toEqual([
      ["add", 1],
      ["sub", 2],
      ["r", 3],
      ["ret", 4],
    ]);
  });

  it("moves an element before the block feeding it, which FBD refuses", () => {
    expect(moveInOrder(chart(), "n1", reported, "sub", -1).ok).toBe(false);
    const moved = moveInOrder(chart(), "n1", reported, "sub", -1, true);
    expect(moved.ok && moved.body.networks![0]!.order).toEqual(["sub", "add", "r", "ret"]);
    const ret = moveInOrder(chart(), "n1", reported, "ret", -1, true);
    expect(ret.ok && ret.body.networks![0]!.order).toEqual(["add", "sub", "ret", "r"]);
    expect(moveInOrder(chart(), "n1", reported, "a", 1, true)).toEqual({
      ok: false,
      error: "Inputs have no execution order number: they are read where their consumer runs.",
    });
  });

  it("orders by data flow: the executed elements of the FBD order, stored as the chart's order", () => {
    const result = orderByDataFlow(chart(), "n1", ["a", "b", "add", "c", "sub", "r", "ret"]);
    expect(result.ok && result.body.networks![0]!.order).toEqual(["add", "sub", "r", "ret"]);
  });

  it("keeps jumps and labels at their numbers, ordering by data flow only between them (issue 26)", () => {
    const jumping = bodyOf({
      ...arithmetic(),
      nodes: [
        ...(arithmetic().nodes ?? []),
        { type: "jump", id: "j", target: "L" },
        { type: "label", id: "l", name: "L" },
      ],
    });
    // numbered: sub, j, r, add, l -> the data flow (add before sub before r) may not carry add over the jump
    const flow = ["a", "b", "add", "c", "sub", "r", "j", "l"];
    const result = orderByDataFlow(jumping, "n1", flow, ["sub", "j", "r", "add", "l"]);
    expect(result.ok && result.body.networks![0]!.order).toEqual(["sub", "j", "add", "r", "l"]);
    // without the chart's numbers (not known yet), the FBD order as it is
    const plain = orderByDataFlow(jumping, "n1", flow);
    expect(plain.ok && plain.body.networks![0]!.order).toEqual(["add", "sub", "r", "j", "l"]);
  });
});

describe("auto-arrange on a chart", () => {
  it("keeps every execution order number, the return's too", () => {
    const order = ["a", "b", "c", "sub", "add", "ret", "r"];
    const result = arrangeNetwork(chart(), "n1", () => 60, order, true);
    expect(result.ok && result.body.networks![0]!.order).toEqual(["sub", "add", "ret", "r"]);
    const fbd = arrangeNetwork(chart(), "n1", () => 60, order);
    expect(fbd.ok && fbd.body.networks![0]!.order).toEqual(["sub", "add", "r"]);
  });
});

describe("feedback pins online", () => {
  it("are the inputs fed by an element with the same or a later place in the order", () => {
    // add feeds sub.IN1; with sub before add (a chart's numbers) that wire runs against the order
    expect([...feedbackPins(network(), ["sub", "add", "r"])]).toEqual(["sub/in:IN1"]);
    expect([...feedbackPins(network(), ["a", "b", "add", "c", "sub", "r"])]).toEqual([]);
    // a block's output into its own input (FBD loop)
    const loop = {
      ...network(),
      wires: [...(network().wires ?? []), { from: { node: "sub", pin: "OUT" }, to: { node: "sub", pin: "IN2" } }],
    };
    expect([...feedbackPins(loop, ["add", "sub", "r"])]).toEqual(["sub/in:IN2"]);
  });
});

describe("the elements with an execution order number", () => {
  it("are the backend's (model/fbd.py EXECUTED_ELEMENTS, through iec.json)", () => {
    expect([...EXECUTED].sort()).toEqual([...IEC.cfc_executed_elements].sort());
  });
});
