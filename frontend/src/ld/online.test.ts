import { describe, expect, it } from "vitest";
import type { LibraryEntry } from "../generated/api";
import { bodyOf, c, net, par, q } from "./fixtures";
import type { LdElement } from "./model";
import { bindLd, ldOnlineView, operandsOf } from "./online";
import { applyMessage, emptyMonitor, operandPath } from "../online/monitor";
import { symbol } from "../test/symbols";

const SYMBOLS = [
  symbol("Start", "BOOL"),
  symbol("Stop", "BOOL"),
  symbol("Motor", "BOOL"),
  symbol("T1", "TON"),
  symbol("Count", "INT"),
  symbol("Alarm", "BOOL", "VAR_GLOBAL"),
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
    expect(operandPath("w.%x3", "MAIN", SYMBOLS)).toBe("MAIN.W.%X3"); // a bit or part (issue 25)
    expect(operandPath("w.3", "MAIN", SYMBOLS)).toBe("MAIN.W.%X3");
    expect(operandPath("arr[2].%B1", "MAIN", SYMBOLS)).toBe("MAIN.ARR[2].%B1");
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

const pin = (name: string, type: string) => ({ name, type });
const entry = (name: string, kind: LibraryEntry["kind"], inputs: Pin[], outputs: Pin[], ret: string | null = null) => ({
  name,
  kind,
  source: "standard" as const,
  comment: null,
  extensible: false,
  inputs,
  in_outs: [],
  outputs,
  return_type: ret,
});
type Pin = { name: string; type: string };
const LIBRARY: Record<string, LibraryEntry> = {
  TON: entry("TON", "function_block", [pin("IN", "BOOL"), pin("PT", "TIME")], [pin("Q", "BOOL"), pin("ET", "TIME")]),
  ADD: entry("ADD", "function", [pin("IN1", "ANY_NUM"), pin("IN2", "ANY_NUM")], [], "ANY_NUM"),
};
const lookup = (call: string) => LIBRARY[call.toUpperCase()];
const noLibrary = () => undefined;

describe("bindLd", () => {
  it("subscribes the elements and variables of the visible networks only", () => {
    const binding = bindLd(motorRung, "MAIN", SYMBOLS, noLibrary, new Set(["n1"]));
    expect(binding.paths.sort()).toEqual(["MAIN.MOTOR", "MAIN.START", "MAIN.STOP"]);
    expect(binding.elements).toEqual([{ pou_instance: "MAIN", ids: ["p1", "c1", "c2", "c3", "q1"] }]);
    const all = bindLd(motorRung, "MAIN", SYMBOLS, noLibrary);
    expect(all.paths.sort()).toEqual(["ALARM", "MAIN.COUNT", "MAIN.MOTOR", "MAIN.START", "MAIN.STOP"]);
  });

  it("subscribes nothing for networks out of view", () => {
    expect(bindLd(motorRung, "MAIN", SYMBOLS, noLibrary, new Set())).toMatchObject({ paths: [], elements: [] });
  });
});

// Start -| TON T1 (PT T#5s, ET unconnected) |- Motor; Count := ADD(Count, Speed) with EN.
const boxes = bodyOf(
  net(
    "n1",
    c("c1", "Start"),
    { type: "box", id: "t", call: "TON", instance: "T1", inputs: { PT: "T#5s" }, outputs: {} },
    q("q1", "Motor"),
  ),
  net("n2", c("c2", "Start"), {
    type: "box",
    id: "add",
    call: "ADD",
    en: true,
    inputs: { IN1: "Count", IN2: "Speed" },
    outputs: { OUT: "Count" },
  }),
);
const BOX_SYMBOLS = [...SYMBOLS, symbol("Speed", "REAL"), symbol("Total", "REAL")];

describe("box pins online (issue 17: values on every pin)", () => {
  it("reads every pin of an FB instance from the instance, wired or not (a TON's ET)", () => {
    const binding = bindLd(boxes, "MAIN", BOX_SYMBOLS, lookup);
    expect(binding.pins.get("t")!.map((p) => [p.side, p.name, p.source])).toEqual([
      ["in", "IN", { path: "MAIN.T1.IN" }],
      ["in", "PT", { path: "MAIN.T1.PT" }],
      ["out", "Q", { path: "MAIN.T1.Q" }],
      ["out", "ET", { path: "MAIN.T1.ET" }],
    ]);
    expect(binding.paths).toEqual(expect.arrayContaining(["MAIN.T1.IN", "MAIN.T1.PT", "MAIN.T1.Q", "MAIN.T1.ET"]));
  });

  it("reads a function's inputs from their variables and its outputs from the engine's probes", () => {
    const binding = bindLd(boxes, "MAIN", BOX_SYMBOLS, lookup);
    expect(binding.pins.get("add")!.map((p) => [p.side, p.name, p.source])).toEqual([
      ["in", "EN", null], // power: drawn from the element feeding it
      ["in", "IN1", { path: "MAIN.COUNT" }],
      ["in", "IN2", { path: "MAIN.SPEED" }],
      ["out", "ENO", { probe: "add" }],
      ["out", "OUT", { probe: "add.OUT" }],
    ]);
    expect(binding.elements[0]!.ids).toEqual(["c1", "t", "q1", "c2", "add", "add.OUT"]);
  });

  it("shows each pin's value as IEC text of its type: TIME as a literal, a generic output in its inputs' type", () => {
    const binding = bindLd(boxes, "MAIN", BOX_SYMBOLS, lookup);
    const monitor = applyMessage(emptyMonitor, {
      type: "values",
      scan: 1,
      time_ms: 10,
      changed: {
        "MAIN.T1.IN": true,
        "MAIN.T1.PT": 5000,
        "MAIN.T1.Q": false,
        "MAIN.T1.ET": 2300,
        "MAIN.COUNT": 50.400001525878906,
        "MAIN.SPEED": 0.5,
      },
      forced: ["MAIN.T1.PT"],
      power: { "MAIN/add": true, "MAIN/add.OUT": 50.900001525878906 },
      types: {
        "MAIN.T1.IN": { name: "BOOL" },
        "MAIN.T1.PT": { name: "TIME" },
        "MAIN.T1.Q": { name: "BOOL" },
        "MAIN.T1.ET": { name: "TIME" },
        "MAIN.COUNT": { name: "REAL" },
        "MAIN.SPEED": { name: "REAL" },
      },
    });
    const view = ldOnlineView(monitor, binding, { "MAIN.T1.IN": false });
    const text = (box: string) => Object.fromEntries(Object.entries(view.pins![box]!).map(([k, v]) => [k, v.text]));
    expect(text("t")).toEqual({ "in:IN": "TRUE", "in:PT": "T#5s", "out:Q": "FALSE", "out:ET": "T#2s300ms" });
    expect(text("add")).toEqual({ "in:IN1": "50.4", "in:IN2": "0.5", "out:ENO": "TRUE", "out:OUT": "50.9" });
    expect(view.pins!.t!["in:PT"]!.forced).toBe(true);
    expect(view.pins!.t!["in:IN"]).toMatchObject({ bool: true, prepared: "FALSE" });
  });
});

describe("ldOnlineView", () => {
  it("colours from the engine's power of its own instance, dims skipped elements, labels values and marks forces by operand", () => {
    const binding = bindLd(motorRung, "MAIN", SYMBOLS, noLibrary);
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
    const view = ldOnlineView(monitor, binding, { "MAIN.MOTOR": true });
    expect(view.power).toEqual({ p1: true, c1: true, c2: false, c3: false, q1: false });
    expect(view.executed).toEqual({ c4: false, q2: false });
    const operands = Object.fromEntries(Object.entries(view.operands!).map(([k, v]) => [k, [v.text, v.bool]]));
    expect(operands).toEqual({
      START: ["TRUE", true],
      STOP: ["TRUE", true],
      MOTOR: ["FALSE", false],
      COUNT: ["7", null],
    });
    expect(Object.keys(view.operands!).filter((k) => view.operands![k]!.forced)).toEqual(["STOP"]);
    expect(view.operands!.MOTOR!.prepared).toBe("TRUE");
  });
});
