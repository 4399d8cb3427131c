import fc from "fast-check";
import { describe, expect, it } from "vitest";
import {
  applyMessage,
  emptyMonitor,
  haltedCall,
  haltedStack,
  keepSubscribed,
  LOG_LIMIT,
  operandPath,
  pathKey,
  setGlobalListNames,
  type MonitorState,
} from "./monitor";
import { parseServerMessage, type ServerMessage, type ValuesMessage } from "./protocol";

const values = (
  scan: number,
  changed: Record<string, boolean | number | string>,
  extra: Partial<ValuesMessage> = {},
): ValuesMessage => ({
  type: "values",
  scan,
  time_ms: scan * 10,
  changed,
  forced: [],
  power: {},
  ...extra,
});

const fold = (messages: ServerMessage[], start: MonitorState = emptyMonitor) => messages.reduce(applyMessage, start);

describe("monitor message handling (issue 6 websocket messages)", () => {
  it("takes the first values message as a snapshot and later ones as diffs", () => {
    const s = fold([
      values(
        1,
        { "MAIN.START": false, "main.motor": false, "MAIN.COUNT": 0 },
        { power: { c1: false, q1: false }, forced: [] },
      ),
      values(2, { "MAIN.START": true }, { power: { c1: true } }),
    ]);
    expect(s.scan).toBe(2);
    expect(s.timeMs).toBe(20);
    expect(s.values).toEqual({ "MAIN.START": true, "MAIN.MOTOR": false, "MAIN.COUNT": 0 });
    expect(s.power).toEqual({ c1: true, q1: false });
  });

  it("takes the forced list of every message as the whole set of forces", () => {
    const s1 = fold([values(1, {}, { forced: ["main.Stop", "MAIN.X"] })]);
    expect([...s1.forced].sort()).toEqual(["MAIN.STOP", "MAIN.X"]);
    const s2 = applyMessage(s1, values(2, { "MAIN.X": 1 }, { forced: ["MAIN.X"] }));
    expect([...s2.forced]).toEqual(["MAIN.X"]);
    const s3 = applyMessage(s2, values(3, {}));
    expect([...s3.forced]).toEqual([]);
  });

  it("keeps a null power as 'not executed', distinct from FALSE", () => {
    const s = fold([values(1, {}, { power: { j1: true, c9: null, q9: null } })]);
    expect(s.power).toEqual({ j1: true, c9: null, q9: null });
  });

  it("records status and the halt location only while halted", () => {
    let s = applyMessage(emptyMonitor, { type: "status", state: "halted", at: { pou: "Main", network: "n1" } });
    expect(s.state).toBe("halted");
    expect(s.at).toEqual({ pou: "Main", network: "n1" });
    s = applyMessage(s, { type: "status", state: "running" });
    expect(s.state).toBe("running");
    expect(s.at).toBeNull();
  });

  it("keeps the call stack of a halt until the next state, and finds the call of a POU in it", () => {
    const stack = [
      { kind: "program" as const, at: { pou: "MAIN", instance: "MAIN", line: 3 } },
      { kind: "method" as const, at: { pou: "MOTOR.START", instance: "MAIN.M", line: 2 }, variables: [] },
    ];
    let s = applyMessage(emptyMonitor, { type: "status", state: "halted", at: stack[1]!.at, stack });
    expect(haltedCall(s, "Motor.Start")).toBe(stack[1]);
    expect(haltedCall(s, "Clamp")).toBeNull();
    expect(haltedCall({ ...s, history: { first: 1, last: 2, stepping: { at: null } } }, "Motor.Start")).toBeNull();
    const past = { first: 1, last: 2, stepping: { at: stack[1]!.at, stack: [stack[1]!] } };
    expect(haltedCall({ ...s, state: "running", history: past }, "Motor.Start")).toBe(stack[1]); // a step's own stack
    expect(haltedStack({ ...s, state: "running", history: past })).toEqual([stack[1]]);
    s = applyMessage(s, { type: "status", state: "running", stack });
    expect(s.stack).toEqual([]);
    expect(haltedCall(s, "Motor.Start")).toBeNull();
  });

  it("appends log and error messages in order with their scan (the server's, else the current one)", () => {
    const s = fold([
      values(7, {}),
      { type: "log", level: "info", message: "force MAIN.STOP := TRUE" },
      { type: "log", level: "warning", message: "watchdog", scan: 3 },
      { type: "error", code: "bad_path", message: "no variable MAIN.NOPE" },
    ]);
    expect(s.log.map((e) => [e.seq, e.level, e.message, e.scan])).toEqual([
      [1, "info", "force MAIN.STOP := TRUE", 7],
      [2, "warning", "watchdog", 3],
      [3, "error", "bad_path: no variable MAIN.NOPE", 7],
    ]);
  });

  it("bounds the log to the newest entries", () => {
    const messages: ServerMessage[] = Array.from({ length: LOG_LIMIT + 5 }, (_, i) => ({
      type: "log",
      level: "info",
      message: `m${i}`,
    }));
    const s = fold(messages);
    expect(s.log).toHaveLength(LOG_LIMIT);
    expect(s.log[0]!.message).toBe("m5");
    expect(s.log[LOG_LIMIT - 1]!.message).toBe(`m${LOG_LIMIT + 4}`);
  });

  it("drops values and power that a new subscription no longer covers", () => {
    const s = fold([values(1, { "MAIN.A": 1, "MAIN.B": 2 }, { power: { e1: true, e2: false } })]);
    const kept = keepSubscribed(s, ["main.b"], ["e2"]);
    expect(kept.values).toEqual({ "MAIN.B": 2 });
    expect(kept.power).toEqual({ e2: false });
  });

  it("ends with the last value written to each path, whatever the sequence of diffs (property)", () => {
    const path = fc.constantFrom("MAIN.A", "main.a", "MAIN.B", "GVL.C", "c");
    const diff = fc.dictionary(path, fc.oneof(fc.boolean(), fc.integer()));
    fc.assert(
      fc.property(fc.array(diff, { maxLength: 12 }), (diffs) => {
        const s = fold(diffs.map((d, i) => values(i + 1, d)));
        const expected: Record<string, unknown> = {};
        for (const d of diffs)
          for (const [p, v] of Object.entries(d)) expected[p.toUpperCase().replace(/^GVL\./, "")] = v; // GVL.C is C
        expect(s.values).toEqual(expected);
        expect(s.scan).toBe(diffs.length);
      }),
    );
  });
});

describe("parseServerMessage", () => {
  it("reads the known message types and ignores anything else", () => {
    expect(parseServerMessage('{"type":"values","scan":3,"time_ms":30,"changed":{}}')).toEqual({
      type: "values",
      scan: 3,
      time_ms: 30,
      changed: {},
    });
    expect(parseServerMessage('{"type":"status","state":"running"}')).toEqual({ type: "status", state: "running" });
    expect(parseServerMessage('{"type":"trace","MAIN.A":[1]}')).toBeNull();
    expect(parseServerMessage('{"type":"values"}')).toBeNull();
    expect(parseServerMessage("not json")).toBeNull();
    expect(parseServerMessage("[1]")).toBeNull();
  });
});

describe("paths into global variable lists", () => {
  it("name a list's variable as the server does, by its own name", () => {
    setGlobalListNames(["GVL_IO"]);
    expect(pathKey(" gvl_io . bStart")).toBe("BSTART");
    expect(pathKey("GVL.bStart")).toBe("BSTART");
    expect(pathKey("Main.GVL_IO")).toBe("MAIN.GVL_IO");
    expect(operandPath("GVL_IO.bStart", "MAIN", [])).toBe("BSTART");
    setGlobalListNames([]);
    expect(pathKey("GVL_IO.bStart")).toBe("GVL_IO.BSTART");
  });

  it("keep the list of a name several lists declare, as the server names it", () => {
    setGlobalListNames(["GVL_A", "GVL_B"], ["x"]);
    expect(pathKey("gvl_a . x")).toBe("GVL_A.X");
    expect(pathKey("GVL_B.x[2].f")).toBe("GVL_B.X[2].F");
    expect(pathKey("GVL_B.xy")).toBe("XY");
    setGlobalListNames(["GVL", "GVL_B"], ["X"]);
    expect(pathKey("gvl.x")).toBe("GVL.X"); // a list called GVL: GVL.x is its variable
    expect(pathKey("GVL.y")).toBe("Y");
    setGlobalListNames([]);
  });
});
