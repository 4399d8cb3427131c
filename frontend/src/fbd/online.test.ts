// @vitest-environment jsdom
// Online FBD (issue 9 "Online mode for FBD"): the probes a view subscribes and what wires show.
import { describe, expect, it } from "vitest";
import { emptyMonitor, powerKey } from "../online/monitor";
import { arithmetic, bodyOf, lookup, SYMBOLS, wire } from "./fixtures";
import type { FbdNetwork } from "./model";
import { bindFbd, executed, fbdOnlineView, nodeOfProbe, probeOf } from "./online";

describe("online FBD", () => {
  const body = bodyOf(arithmetic(), {
    id: "n2",
    nodes: [
      { type: "block", id: "t", call: "TON", instance: "t1", en: true },
      { type: "jump", id: "j", target: "L" },
    ],
  });

  it("subscribes every block output pin, the variable nodes and their variables", () => {
    const binding = bindFbd(body, "MAIN", lookup, SYMBOLS);
    expect(binding.elements).toEqual([
      { pou_instance: "MAIN", ids: ["a", "b", "c", "add.OUT", "sub.OUT", "r", "t.ENO", "t.Q", "t.ET", "j"] },
    ]);
    expect([...binding.paths].sort()).toEqual(
      [
        ...["MAIN.VAR1", "MAIN.VAR2", "MAIN.VAR3"], // the input nodes' (the add block's inputs take their types)
        ...["MAIN.T1.IN", "MAIN.T1.PT", "MAIN.T1.Q", "MAIN.T1.ET"], // every pin of the FB instance
        "MAIN.RESULT",
      ].sort(),
    );
    expect(bindFbd(body, "MAIN", lookup, SYMBOLS, new Set(["n2"])).elements[0]!.ids).toEqual([
      "t.ENO",
      "t.Q",
      "t.ET",
      "j",
    ]);
  });

  it("shows on a block input fed over a feedback wire the value the block read, not its producer's new one", () => {
    // ADD's OUT wired back into its own IN1 (issue 22 item 6): the engine probes add.IN1 before the call
    const loop = bodyOf({
      id: "n",
      nodes: [
        { type: "block", id: "add", call: "ADD" },
        { type: "input", id: "one", expr: "1" },
      ],
      wires: [wire("add", "OUT", "add", "IN1"), wire("one", "OUT", "add", "IN2")],
    });
    const binding = bindFbd(loop, "MAIN", lookup, SYMBOLS, undefined, new Set(["add/in:IN1"]));
    expect(binding.elements[0]!.ids).toEqual(["add.OUT", "add.IN1", "one"]);
    // not (yet) known as a feedback pin: no read probe subscribed (the engine has none for other inputs)
    expect(bindFbd(loop, "MAIN", lookup, SYMBOLS).elements[0]!.ids).toEqual(["add.OUT", "one"]);
    const monitor = {
      ...emptyMonitor,
      power: { [powerKey("MAIN", "add.OUT")]: 4, [powerKey("MAIN", "add.IN1")]: 3 },
    };
    const view = fbdOnlineView(monitor, binding);
    expect([view.pins.add!["in:IN1"]!.text, view.pins.add!["out:OUT"]!.text]).toEqual(["3", "4"]);
    // the read value is a pin's, not a sign the block ran: with its output not executed (EN FALSE) it is dimmed
    const skipped = { ...monitor, power: { [powerKey("MAIN", "add.OUT")]: null, [powerKey("MAIN", "add.IN1")]: 3 } };
    expect(executed(fbdOnlineView(skipped, binding), "add")).toBe(false);
    // an input the engine records no read value for shows its producer's value
    const plain = { ...monitor, power: { [powerKey("MAIN", "add.OUT")]: 4 } };
    expect(fbdOnlineView(plain, binding).pins.add!["in:IN1"]!.text).toBe("4");
  });

  it("reads wire values from the producer's probe, through continuations", () => {
    const n: FbdNetwork = {
      id: "n",
      nodes: [
        { type: "block", id: "add", call: "ADD" },
        { type: "connector", id: "k", name: "sum" },
        { type: "continuation", id: "k2", name: "SUM" },
        { type: "input", id: "a", expr: "var1" },
      ],
      wires: [wire("add", "OUT", "k", "IN")],
    };
    expect(probeOf(n, { node: "k2", pin: "OUT" })).toBe("add.OUT");
    expect(probeOf(n, { node: "a", pin: "OUT" })).toBe("a");
    expect(probeOf(n, { node: "k", pin: "IN" })).toBeNull();
  });

  it("marks blocks whose probes are null as not executed, and forced operands", () => {
    const binding = bindFbd(body, "MAIN", lookup, SYMBOLS);
    const monitor = {
      ...emptyMonitor,
      power: {
        [powerKey("MAIN", "add.OUT")]: 12,
        [powerKey("MAIN", "t.Q")]: null,
        [powerKey("MAIN", "t.ET")]: null,
        [powerKey("MAIN", "t.ENO")]: null,
      },
      forced: new Set(["MAIN.VAR1"]),
    };
    const view = fbdOnlineView(monitor, binding);
    expect(view.probes["add.OUT"]).toBe(12);
    expect(executed(view, "add")).toBe(true);
    expect(executed(view, "t")).toBe(false);
    expect(executed(view, "sub")).toBe(true); // nothing known yet: not dimmed
    expect(view.operands).toEqual({}); // no values arrived yet
  });

  it("shows every pin of an FB instance block from the instance, a function's from its wires and probes", () => {
    const binding = bindFbd(body, "MAIN", lookup, SYMBOLS);
    expect(binding.pins.get("t")!.map((p) => [p.side, p.name, p.source])).toEqual([
      ["in", "EN", null],
      ["in", "IN", { path: "MAIN.T1.IN" }],
      ["in", "PT", { path: "MAIN.T1.PT" }],
      ["out", "ENO", { probe: "t.ENO" }],
      ["out", "Q", { path: "MAIN.T1.Q" }],
      ["out", "ET", { path: "MAIN.T1.ET" }],
    ]);
    expect(binding.pins.get("add")!.map((p) => [p.side, p.name, p.source])).toEqual([
      ["in", "IN1", { probe: "a", typeOf: "MAIN.VAR1" }],
      ["in", "IN2", { probe: "b", typeOf: "MAIN.VAR2" }],
      ["out", "OUT", { probe: "add.OUT" }],
    ]);
    const monitor = {
      ...emptyMonitor,
      values: { "MAIN.T1.ET": 1500, "MAIN.VAR1": 1.5 },
      types: { "MAIN.T1.ET": { name: "TIME" }, "MAIN.VAR1": { name: "REAL" }, "MAIN.VAR2": { name: "REAL" } },
      power: {
        [powerKey("MAIN", "a")]: 1.5,
        [powerKey("MAIN", "b")]: 0.10000000149011612,
        [powerKey("MAIN", "add.OUT")]: 1.600000023841858,
      },
      forced: new Set(["MAIN.VAR1"]),
    };
    const view = fbdOnlineView(monitor, binding);
    expect(view.pins.t!["out:ET"]!.text).toBe("T#1s500ms");
    expect(Object.fromEntries(Object.entries(view.pins.add!).map(([k, v]) => [k, v.text]))).toEqual({
      "in:IN1": "1.5",
      "in:IN2": "0.1",
      "out:OUT": "1.6",
    });
    expect(view.operands.VAR1).toEqual({ text: "1.5", bool: null, forced: true, prepared: null });
  });

  it("maps a halt's probe id back to its node", () => {
    expect(nodeOfProbe(body, "sub.OUT")).toBe("sub");
    expect(nodeOfProbe(body, "r")).toBe("r");
    expect(nodeOfProbe(body, "nothing.X")).toBe("nothing.X");
  });
});
