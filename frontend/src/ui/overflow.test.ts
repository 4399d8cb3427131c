import { describe, expect, it } from "vitest";
import { fitItems, rowWidth } from "./overflow";

const request = (widths: number[], available: number, extra: Partial<Parameters<typeof fitItems>[0]> = {}) =>
  fitItems({ widths, pinned: widths.map(() => false), gap: 2, available, more: 28, ...extra });

describe("rowWidth", () => {
  it("adds the widths and the gaps between them", () => {
    expect(rowWidth([28, 28, 50], 2)).toBe(110);
    expect(rowWidth([], 2)).toBe(0);
  });
});

describe("fitItems", () => {
  it("shows every item when the row fits, without a More button", () => {
    // 4 x 28 + 3 x 2 = 118: exactly the width
    expect(request([28, 28, 28, 28], 118)).toEqual([true, true, true, true]);
  });

  it("drops items from the end until they fit next to the More button", () => {
    // 117 px: the four (118) do not fit; three and More are 3 x 28 + 2 x 2 + 2 + 28 = 118, two and More 88
    expect(request([28, 28, 28, 28], 117)).toEqual([true, true, false, false]);
    expect(request([28, 28, 28, 28], 88)).toEqual([true, true, false, false]);
    expect(request([28, 28, 28, 28], 87)).toEqual([true, false, false, false]);
  });

  it("keeps pinned items (the active tab, a status) and drops the others around them", () => {
    const pinned = [false, false, false, true];
    // 60 + 2 + 28 (More) + 2 + 28 = 120: the pinned last item and the first one
    expect(request([28, 28, 28, 60], 120, { pinned })).toEqual([true, false, false, true]);
    expect(request([28, 28, 28, 60], 10, { pinned })).toEqual([false, false, false, true]);
  });

  it("drops the lowest priority first, the last among equals", () => {
    const priority = [2, 0, 1, 0];
    // all four do not fit in 100; without item 3 (priority 0, last): 3 x 28 + 2 x 2 + 2 + 28 = 118 > 100;
    // without item 1 too: 2 x 28 + 2 + 2 + 28 = 88
    expect(request([28, 28, 28, 28], 100, { priority })).toEqual([true, false, true, false]);
    expect(request([28, 28, 28, 28], 60, { priority })).toEqual([true, false, false, false]);
  });

  it("never drops more than it must: a wide item leaving frees room for the rest", () => {
    // all: 28 + 200 + 28 + 2 x 2 = 260 > 200; the wide one (priority 0) leaves first: 28 + 28 + 2 + 2 + 28 = 88,
    // so both narrow ones stay
    expect(request([28, 200, 28], 200, { priority: [1, 0, 1] })).toEqual([true, false, true]);
  });
});
