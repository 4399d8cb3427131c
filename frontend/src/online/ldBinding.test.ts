import { describe, expect, it } from "vitest";
import type { SymbolInfo } from "../generated/api";
import { bodyOf, c, net, par, q } from "../ld/fixtures";
import type { LdElement } from "../ld/model";
import { bindLd, ldOnlineView, operandPath, operandsOf } from "./ldBinding";
import { applyMessage, emptyMonitor } from "./monitor";

const sym = (name: string, type: string, var_class = "VAR"): SymbolInfo => ({
  name,
  type,
  var_class,
  initial: null,
  address: null,
  comment: null,
  retain: false,
  constant: false,
});
const SYMBOLS = [
  sym("Start", "BOOL"),
  sym("Stop", "BOOL"),
  sym("Motor", "BOOL"),
  sym("T1", "TON"),
  sym("Count", "INT"),
  sym("Alarm", "BOOL", "VAR_GLOBAL"),
];

// Motor := (Start OR Motor) AND NOT Stop
const motorRung = bodyOf(
  net("n1", par("p1", [c("c1", "Start")], [c("c2", "Motor")]), c("c3", "Stop", "nc"), q("q1", "Motor")),
  net("n2", c("c4", "Alarm"), q("q2", "Count")),
);

describe("operand paths of the online LD", () => {
  it("puts the POU's own variables under the instance and leaves globals bare", () => {
    expect(operandPath("Start", "MAIN", SYMBOLS)).toBe("MAIN.START");
    expect(operandPath(" T1.Q ", "MAIN", SYMBOLS)).toBe("MAIN.T1.Q");
    expect(operandPath("Alarm", "MAIN", SYMBOLS)).toBe("ALARM");
    expect(operandPath("arr[3]", "MAIN.FB1", SYMBOLS)).toBe("MAIN.FB1.ARR[3]");
  });

  it("has no path for literals, addresses and empty operands", () => {
    for (const text of ["TRUE", "false", "5", "T#1s", "%IX0.0", "", "A + B"])
      expect(operandPath(text, "MAIN", SYMBOLS)).toBeNull();
  });

  it("lists every operand an element shows", () => {
    const box: LdElement = {
      type: "box",
      id: "b1",
      call: "TON",
      instance: "T1",
      inputs: { IN: [c("c5", "Start")], PT: "T#5s" },
      outputs: { ET: "Elapsed" },
    };
    expect(operandsOf(box)).toEqual(["T#5s", "Elapsed"]);
    expect(operandsOf({ type: "compare", id: "k", op: "GT", left: "Count", right: "10" })).toEqual(["Count", "10"]);
  });
});

describe("bindLd", () => {
  it("subscribes the elements and variables of the visible networks only", () => {
    const binding = bindLd(motorRung, "MAIN", SYMBOLS, new Set(["n1"]));
    expect(binding.paths.sort()).toEqual(["MAIN.MOTOR", "MAIN.START", "MAIN.STOP"]);
    expect(binding.elements).toEqual([{ pou_instance: "MAIN", ids: ["p1", "c1", "c2", "c3", "q1"] }]);
    const all = bindLd(motorRung, "MAIN", SYMBOLS);
    expect(all.paths.sort()).toEqual(["ALARM", "MAIN.COUNT", "MAIN.MOTOR", "MAIN.START", "MAIN.STOP"]);
  });

  it("subscribes nothing for networks out of view", () => {
    expect(bindLd(motorRung, "MAIN", SYMBOLS, new Set())).toMatchObject({ paths: [], elements: [] });
  });
});

describe("ldOnlineView", () => {
  it("colours from the engine's power of its own instance, dims skipped elements, labels values and marks forces by operand", () => {
    const binding = bindLd(motorRung, "MAIN", SYMBOLS);
    const monitor = applyMessage(emptyMonitor, {
      type: "values",
      scan: 4,
      time_ms: 40,
      changed: { "MAIN.START": true, "MAIN.STOP": true, "MAIN.MOTOR": false, "MAIN.COUNT": 7 },
      forced: ["MAIN.STOP"],
      power: {
        "MAIN/p1": true,
        "MAIN/c1": true,
        "MAIN/c2": false,
        "MAIN/c3": false,
        "MAIN/q1": false,
        "MAIN/c4": null,
        "MAIN/q2": null,
        "OTHER/c1": false,
      },
    });
    const view = ldOnlineView(monitor, binding);
    expect(view.power).toEqual({ p1: true, c1: true, c2: false, c3: false, q1: false });
    expect(view.executed).toEqual({ c4: false, q2: false });
    expect(view.values).toEqual({ START: true, STOP: true, MOTOR: false, COUNT: "7" }); // non-BOOL values as IEC text
    expect([...view.forced!]).toEqual(["STOP"]);
  });
});
