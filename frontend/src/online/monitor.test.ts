import fc from "fast-check";
import { describe, expect, it } from "vitest";
import {
  applyMessage,
  emptyMonitor,
  formatValue,
  keepSubscribed,
  LOG_LIMIT,
  parseValue,
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

describe("values typed by the user", () => {
  it("parses booleans and numbers and passes other text on as an IEC literal", () => {
    expect(parseValue(" true ")).toBe(true);
    expect(parseValue("FALSE")).toBe(false);
    expect(parseValue("-12")).toBe(-12);
    expect(parseValue("1.5e3")).toBe(1500);
    expect(parseValue("T#1s")).toBe("T#1s");
    expect(parseValue("16#FF")).toBe("16#FF");
  });

  it("formats values like IEC", () => {
    expect(formatValue(true)).toBe("TRUE");
    expect(formatValue(false)).toBe("FALSE");
    expect(formatValue(42)).toBe("42");
    expect(formatValue(undefined)).toBe("…");
  });

  it("shows TIME, dates and enumerations as IEC text when the type is known (the server sends ms and ints)", () => {
    expect(formatValue(62500, { name: "TIME" })).toBe("T#1m2s500ms");
    expect(formatValue(0, "TIME")).toBe("T#0ms");
    expect(formatValue(-1500, "time")).toBe("T#-1s500ms");
    expect(formatValue(90061001, "TIME")).toBe("T#1d1h1m1s1ms");
    expect(formatValue(1714521600000, { name: "DATE" })).toBe("D#2024-05-01");
    expect(formatValue(45015500, { name: "TIME_OF_DAY" })).toBe("TOD#12:30:15.500");
    expect(formatValue(1714566600000, { name: "DATE_AND_TIME" })).toBe("DT#2024-05-01-12:30:00");
    const mode = { name: "MODE", names: { "0": "IDLE", "5": "RUN" } };
    expect([formatValue(5, mode), formatValue(7, mode)]).toEqual(["RUN", "7"]);
    expect([formatValue(7, "INT"), formatValue("text", "TIME")]).toEqual(["7", "text"]);
  });

  it("writes every duration as units that add up to it, largest first, each once", () => {
    const UNIT_MS: Record<string, number> = { d: 86_400_000, h: 3_600_000, m: 60_000, s: 1000, ms: 1 };
    fc.assert(
      fc.property(fc.integer({ min: -10 * 86_400_000, max: 10 * 86_400_000 }), (ms) => {
        const text = formatValue(ms, "TIME");
        const parts = [...text.slice(ms < 0 ? 3 : 2).matchAll(/(\d+)(ms|d|h|m|s)/g)];
        const units = parts.map((p) => p[2]!);
        expect(parts.reduce((sum, p) => sum + Number(p[1]) * UNIT_MS[p[2]!]!, 0)).toBe(Math.abs(ms));
        expect(units).toEqual(Object.keys(UNIT_MS).filter((u) => units.includes(u)));
      }),
    );
  });

  it("keeps the types of the snapshot after a subscribe for the later diffs", () => {
    const snapshot: ValuesMessage = {
      type: "values",
      scan: 1,
      time_ms: 10,
      changed: { "Main.T": 5 },
      forced: [],
      power: {},
      types: { "Main.T": { name: "TIME" } },
    };
    const diff: ValuesMessage = {
      type: "values",
      scan: 2,
      time_ms: 20,
      changed: { "MAIN.T": 15 },
      forced: [],
      power: {},
    };
    const state = applyMessage(applyMessage(emptyMonitor, snapshot), diff);
    expect(formatValue(state.values["MAIN.T"], state.types["MAIN.T"])).toBe("T#15ms");
  });
});
