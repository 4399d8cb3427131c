// Zoom geometry (issue 22 item 7): the fit zoom shows the whole diagram, as large as the view allows,
// and the steps of the keys and the wheel.
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { FIT_MIN, fitZoom, ZOOM_MAX, ZOOM_MIN, zoomed, zoomedTo } from "./zoom";

describe("fit zoom", () => {
  it("fits the tighter side: a wide diagram by its width, a tall one by its height", () => {
    expect(fitZoom({ width: 1000, height: 200 }, { width: 800, height: 600 })).toBe(0.8);
    expect(fitZoom({ width: 300, height: 1200 }, { width: 800, height: 600 })).toBe(0.5);
    expect(fitZoom({ width: 300, height: 2000 }, { width: 800, height: 600 })).toBe(0.3); // below the keys' 50 %
    expect(fitZoom({ width: 400, height: 300 }, { width: 800, height: 450 })).toBe(1.5);
  });

  it("rounds down to whole percent, so the diagram never overflows by rounding", () => {
    expect(fitZoom({ width: 300, height: 100 }, { width: 200, height: 600 })).toBe(0.66);
    expect(fitZoom({ width: 25, height: 20 }, { width: 28, height: 23 })).toBe(1.12); // 25 * 1.12 = 28.000000000000004 in floats
  });

  it("stays within the zoom range, and at 100 % for nothing to fit", () => {
    expect(fitZoom({ width: 50, height: 50 }, { width: 800, height: 600 })).toBe(ZOOM_MAX);
    expect(fitZoom({ width: 8000, height: 50 }, { width: 800, height: 600 })).toBe(FIT_MIN);
    expect(fitZoom({ width: 8000, height: 50 }, { width: 800, height: 600 }, 0.1, 4)).toBe(0.1);
    expect(fitZoom({ width: 0, height: 0 }, { width: 800, height: 600 })).toBe(1);
    expect(fitZoom({ width: 100, height: 100 }, { width: 0, height: 600 })).toBe(1);
  });

  it("makes every diagram the range allows fit inside the view, and a whole percent larger would not", () => {
    const size = fc.integer({ min: 20, max: 4000 });
    fc.assert(
      fc.property(size, size, size, size, (cw, ch, vw, vh) => {
        const zoom = fitZoom({ width: cw, height: ch }, { width: vw, height: vh });
        const exact = Math.min(vw / cw, vh / ch);
        if (exact < FIT_MIN || exact > ZOOM_MAX) return; // clamped, checked above
        // (up to a float's error both ways: 25 * 1.12 is 28.000000000000004, and 0.67 computed as 0.66999...
        // fits a hair's breadth under; a millionth of a pixel is no overflow)
        expect(cw * zoom).toBeLessThanOrEqual(vw + 1e-6);
        expect(ch * zoom).toBeLessThanOrEqual(vh + 1e-6);
        expect(cw * (zoom + 0.01) > vw - 1e-6 || ch * (zoom + 0.01) > vh - 1e-6).toBe(true);
      }),
    );
  });
});

describe("zoom steps", () => {
  it("steps LD's zoom by 10 % within 50-200 %", () => {
    expect(zoomed(1, "in")).toBe(1.1);
    expect(zoomed(0.73, "out")).toBe(0.6);
    expect(zoomed(ZOOM_MIN, "out")).toBe(ZOOM_MIN);
    expect(zoomed(ZOOM_MAX, "in")).toBe(ZOOM_MAX);
    expect(zoomed(1.7, "reset")).toBe(1);
    expect(zoomed(0.3, "out")).toBe(0.3); // a fit below 50 %: out stays, in steps up
    expect(zoomed(0.3, "in")).toBe(0.4);
    let zoom = 1;
    for (let i = 0; i < 7; i++) zoom = zoomed(zoom, "in");
    expect(zoom).toBe(1.7); // no float drift (0.1 seven times)
  });

  it("steps to the next preset level, from a fitted zoom between levels too", () => {
    const levels = [0.5, 1, 2];
    expect(zoomedTo(levels, 1, "in")).toBe(2);
    expect(zoomedTo(levels, 0.7, "in")).toBe(1);
    expect(zoomedTo(levels, 0.7, "out")).toBe(0.5);
    expect(zoomedTo(levels, 2, "in")).toBe(2);
    expect(zoomedTo(levels, 0.5, "out")).toBe(0.5);
  });
});
