import { describe, expect, it } from "vitest";
import { sampleOfScan } from "./scrub";

describe("the trace chart's cursor and the history's scan (issue 23)", () => {
  it("finds the sample of a scan, else the newest before it, else none", () => {
    const scans = [3, 4, 5, 8, 9];
    expect(sampleOfScan(scans, 3)).toBe(0);
    expect(sampleOfScan(scans, 5)).toBe(2);
    expect(sampleOfScan(scans, 7)).toBe(2); // scans 6 and 7 were not sampled (the trace was waiting)
    expect(sampleOfScan(scans, 9)).toBe(4);
    expect(sampleOfScan(scans, 100)).toBe(4);
    expect(sampleOfScan(scans, 2)).toBeNull();
    expect(sampleOfScan([], 1)).toBeNull();
  });
});
