import { describe, expect, it } from "vitest";
import { chartData, LANE, legendValue } from "./chartData";
import { SampleRing } from "./ring";

function ring() {
  const r = new SampleRing(4, 3);
  r.push(3, 30, [0, 5, 1]);
  r.push(4, 40, [1, NaN, 0]);
  return r.columnsInOrder();
}

describe("chartData", () => {
  it("stacks each BOOL in its own lane and keeps numbers on the y scale, x in ms since the origin", () => {
    const chart = chartData(["MAIN.A", "MAIN.N", "MAIN.B"], ["bool", "number", "bool"], ring(), 30, true);
    expect(chart.series).toEqual([
      { path: "MAIN.A", kind: "bool", scale: "lanes", offset: 0 },
      { path: "MAIN.N", kind: "number", scale: "y", offset: 0 },
      { path: "MAIN.B", kind: "bool", scale: "lanes", offset: LANE },
    ]);
    expect(chart.lanes).toBe(2);
    expect(chart.data).toEqual([
      [0, 10],
      [0, 1],
      [5, null],
      [1 + LANE, LANE],
    ]);
  });

  it("draws BOOLs as 0/1 on the y scale without the lane view", () => {
    const chart = chartData(["MAIN.A", "MAIN.N", "MAIN.B"], ["bool", "number", null], ring(), 0, false);
    expect(chart.series.map((s) => [s.scale, s.offset, s.kind])).toEqual([
      ["y", 0, "bool"],
      ["y", 0, "number"],
      ["y", 0, "number"],
    ]);
    expect(chart.data[3]).toEqual([1, 0]);
  });

  it("shows the value under the cursor without the lane offset", () => {
    const lane = { path: "MAIN.B", kind: "bool" as const, scale: "lanes" as const, offset: LANE };
    expect([legendValue(lane, 1 + LANE), legendValue(lane, LANE), legendValue(lane, null)]).toEqual([
      "TRUE",
      "FALSE",
      "—",
    ]);
    expect(legendValue({ path: "MAIN.N", kind: "number", scale: "y", offset: 0 }, 12.5)).toBe("12.5");
    const mode = { name: "MODE", names: { "0": "Idle", "5": "Run" } };
    const series = chartData(["MAIN.M"], ["number"], new SampleRing(1, 1).columnsInOrder(), 0, false, [mode]).series;
    expect(legendValue(series[0]!, 5)).toBe("Run"); // an enumeration: its value's name, as declared
  });
});
