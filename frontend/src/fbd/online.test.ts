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
    expect(binding.paths).toEqual(["MAIN.VAR1", "MAIN.VAR2", "MAIN.VAR3", "MAIN.RESULT"]);
    expect(bindFbd(body, "MAIN", lookup, SYMBOLS, new Set(["n2"])).elements[0]!.ids).toEqual([
      "t.ENO",
      "t.Q",
      "t.ET",
      "j",
    ]);
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
    expect([...view.forced]).toEqual(["VAR1"]);
  });

  it("maps a halt's probe id back to its node", () => {
    expect(nodeOfProbe(body, "sub.OUT")).toBe("sub");
    expect(nodeOfProbe(body, "r")).toBe("r");
    expect(nodeOfProbe(body, "nothing.X")).toBe("nothing.X");
  });
});
