import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { applyMessage, emptyMonitor } from "./monitor";
import type { ValuesMessage } from "./protocol";
import { formatClock, formatValue, parseValue, realText } from "./values";

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
    expect(formatValue(0, "TIME")).toBe("T#0s");
    expect(formatValue(-1500, "time")).toBe("T#-1s500ms");
    expect(formatValue(90061001, "TIME")).toBe("T#1d1h1m1s1ms");
    expect(formatValue(1714521600000, { name: "DATE" })).toBe("D#2024-05-01");
    expect(formatValue(45015500, { name: "TIME_OF_DAY" })).toBe("TOD#12:30:15.5");
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

describe("REAL values (issue 17: a REAL 50.4 shows 50.4, not 50.400001525878906)", () => {
  it("shows the single-precision value the server widened to a double in its shortest form", () => {
    expect(formatValue(Math.fround(50.4), "REAL")).toBe("50.4");
    expect(formatValue(50.400001525878906, { name: "REAL" })).toBe("50.4");
    expect(formatValue(Math.fround(0.1), "REAL")).toBe("0.1");
    expect(formatValue(Math.fround(-3.75), "REAL")).toBe("-3.75");
    // As IEC real literals, the way the engine's TO_STRING writes them (iec/value_text.py).
    expect(formatValue(50, "REAL")).toBe("50.0");
    expect(formatValue(Math.fround(16777217), "REAL")).toBe("16777216.0");
    expect(formatValue(Math.fround(1e-7), "REAL")).toBe("1.0E-7");
    expect(formatValue(Math.fround(1e20), "REAL")).toBe("1.0E20");
    expect(formatValue(Math.fround(1234567), "REAL")).toBe("1234567.0");
    expect(formatValue(Math.fround(-0.00025), "REAL")).toBe("-0.00025");
    // An LREAL is a double: its shortest digits.
    expect(formatValue(50.400001525878906, "LREAL")).toBe("50.400001525878906");
    expect(formatValue(50.4, "LREAL")).toBe("50.4");
    expect(formatValue(1e16, "LREAL")).toBe("1.0E16");
    expect(formatValue(1e15, "LREAL")).toBe("1000000000000000.0");
  });

  it("always names the same single, and never with more than 6 digits unless needed (property)", () => {
    fc.assert(
      fc.property(fc.float({ noNaN: true, noDefaultInfinity: true }), (f) => {
        const single = Math.fround(f);
        const text = realText(single, true);
        expect(Math.fround(Number(text)) === single).toBe(true); // -0 shows as 0

        const digits = text
          .replace(/^-/, "")
          .replace(/E.*$/, "")
          .replace(".", "")
          .replace(/^0+/, "")
          .replace(/0+$/, "");
        if (digits.length > 6) {
          // Beyond the 6 digits it is rounded to, one significant digit fewer no longer reads back.
          expect(Math.fround(Number(single.toPrecision(digits.length - 1)))).not.toBe(single);
        }
      }),
    );
  });
});

describe("the virtual clock", () => {
  it("reads h:mm:ss.mmm", () => {
    expect(formatClock(0)).toBe("0:00:00.000");
    expect(formatClock(3_723_004)).toBe("1:02:03.004");
  });
});
