import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { MAX_SAMPLES, SampleRing, sampleNumber } from "./ring";

const scansOf = (ring: SampleRing) => Array.from(ring.columnsInOrder().scans);

describe("SampleRing", () => {
  it("keeps samples in order until full, then overwrites the oldest", () => {
    const ring = new SampleRing(3, 2);
    ring.push(1, 10, [1, 100]);
    ring.push(2, 20, [0, 200]);
    expect(ring.length).toBe(2);
    expect(scansOf(ring)).toEqual([1, 2]);
    ring.push(3, 30, [1, 300]);
    ring.push(4, 40, [0, 400]); // wraps: scan 1 is gone
    ring.push(5, 50, [1, 500]);
    const columns = ring.columnsInOrder();
    expect(Array.from(columns.scans)).toEqual([3, 4, 5]);
    expect(Array.from(columns.times)).toEqual([30, 40, 50]);
    expect(columns.values.map((c) => Array.from(c))).toEqual([
      [1, 0, 1],
      [300, 400, 500],
    ]);
    expect(ring.sample(0)).toEqual({ scan: 3, timeMs: 30, values: [1, 300] });
    expect(ring.sample(2)).toEqual({ scan: 5, timeMs: 50, values: [1, 500] });
    expect(() => ring.sample(3)).toThrow("no sample 3 (holding 3)");
    expect([ring.length, ring.total]).toEqual([3, 5]);
  });

  it("holds the newest min(n, capacity) samples, oldest first, for any number pushed", () => {
    fc.assert(
      fc.property(fc.integer({ min: 1, max: 40 }), fc.integer({ min: 0, max: 130 }), (capacity, n) => {
        const ring = new SampleRing(capacity, 1);
        for (let s = 1; s <= n; s++) ring.push(s, s * 10, [s * 2]);
        const kept = Array.from({ length: Math.min(n, capacity) }, (_, i) => n - Math.min(n, capacity) + 1 + i);
        const columns = ring.columnsInOrder();
        expect(Array.from(columns.scans)).toEqual(kept);
        expect(Array.from(columns.times)).toEqual(kept.map((s) => s * 10));
        expect(Array.from(columns.values[0]!)).toEqual(kept.map((s) => s * 2));
      }),
    );
  });

  it("refuses a capacity outside 1..10,000", () => {
    expect(() => new SampleRing(0, 1)).toThrow("capacity must be 1..10000, not 0");
    expect(() => new SampleRing(MAX_SAMPLES + 1, 1)).toThrow("capacity must be 1..10000, not 10001");
    expect(new SampleRing(MAX_SAMPLES, 20).capacity).toBe(10_000);
  });

  it("stores BOOLs as 1/0 and the server's non-finite REALs as numbers", () => {
    expect([true, false, 42, -1.5, "NaN", "Infinity", "-Infinity", null].map(sampleNumber)).toEqual([
      1,
      0,
      42,
      -1.5,
      NaN,
      Infinity,
      -Infinity,
      NaN,
    ]);
  });
});
