// @vitest-environment jsdom
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import type { Panel } from "../generated/api";
import { faultModes } from "./FaultDialog";
import {
  alignWidgets,
  bindingsOf,
  deleteWidgets,
  distributeWidgets,
  duplicateWidgets,
  freeSpot,
  makeWidget,
  motionOffset,
  moveWidgets,
  PALETTE,
  pushValue,
  resizeWidget,
  sevenSegmentText,
  sliderValue,
  stateOf,
  typedValue,
  type Widget,
} from "./model";
import { panelTarget } from "./panelTarget";
import { appendSample } from "./trend";
import { durationMs, parseUntil } from "./until";

const lamp = (id: string, x: number, y: number, w = 30, h = 30): Widget => ({
  type: "lamp",
  id,
  x,
  y,
  w,
  h,
  bind: "A",
});
const panel = (...widgets: Widget[]): Panel => ({ name: "P", width: 400, height: 300, grid: 10, widgets });
const places = (p: Panel) => (p.widgets ?? []).map((w) => [w.id, w.x, w.y, w.w, w.h]);

describe("editing panels", () => {
  it("makes every palette widget inside the panel, snapped, with an id of its own", () => {
    let p = panel();
    for (const entry of PALETTE) {
      const w = makeWidget(p, entry.type, 397, 299);
      expect(w.x + w.w).toBeLessThanOrEqual(400);
      expect(w.y + w.h).toBeLessThanOrEqual(300);
      expect(w.x % 10).toBe(0);
      p = { ...p, widgets: [...(p.widgets ?? []), w] };
    }
    expect(new Set(p.widgets!.map((w) => w.id)).size).toBe(PALETTE.length);
    expect(makeWidget(p, "lamp", 0, 0).id).toBe("lamp2");
  });

  it("moves on the grid and never past the edges", () => {
    const p = panel(lamp("a", 10, 10), lamp("b", 100, 100));
    expect(places(moveWidgets(p, new Set(["a"]), 14, 26))).toEqual([
      ["a", 20, 40, 30, 30],
      ["b", 100, 100, 30, 30],
    ]);
    expect(places(moveWidgets(p, new Set(["a", "b"]), 1000, -1000))).toEqual([
      ["a", 370, 0, 30, 30],
      ["b", 370, 0, 30, 30],
    ]);
  });

  it("resizes on the grid within the panel", () => {
    const p = panel(lamp("a", 350, 10));
    expect(places(resizeWidget(p, "a", 64, 500))).toEqual([["a", 350, 10, 50, 290]]);
    expect(places(resizeWidget(p, "a", 1, 1))).toEqual([["a", 350, 10, 10, 10]]);
  });

  it("aligns on the first selected widget", () => {
    const p = panel(lamp("a", 10, 10, 40, 20), lamp("b", 100, 60, 20, 40), lamp("c", 200, 90));
    expect(places(alignWidgets(p, ["b", "a"], "top"))).toEqual([
      ["a", 10, 60, 40, 20],
      ["b", 100, 60, 20, 40],
      ["c", 200, 90, 30, 30],
    ]);
    expect(places(alignWidgets(p, ["a", "b"], "right")).slice(0, 2)).toEqual([
      ["a", 10, 10, 40, 20],
      ["b", 30, 60, 20, 40],
    ]);
    expect(places(alignWidgets(p, ["a", "b"], "middle"))[1]).toEqual(["b", 100, 0, 20, 40]);
    expect(alignWidgets(p, ["a"], "left")).toBe(p);
  });

  it("spaces three widgets evenly between the outermost", () => {
    const p = panel(lamp("a", 0, 0, 20), lamp("b", 30, 0, 40), lamp("c", 200, 0, 20));
    // free space 200 - 20 - 40 = 140 between a's end (20) and c (200): gaps of 70
    expect(places(distributeWidgets(p, ["a", "b", "c"], "x"))[1]).toEqual(["b", 90, 0, 40, 30]);
  });

  it("deletes and duplicates with new ids", () => {
    const p = panel(lamp("lamp1", 0, 0), lamp("lamp2", 50, 0));
    expect(places(deleteWidgets(p, new Set(["lamp1"])))).toEqual([["lamp2", 50, 0, 30, 30]]);
    const [copied, made] = duplicateWidgets(p, new Set(["lamp1"]));
    expect(made).toEqual(["lamp3"]);
    expect(places(copied)[2]).toEqual(["lamp3", 20, 20, 30, 30]);
  });

  it("finds a free spot away from every widget", () => {
    fc.assert(
      fc.property(
        fc.array(fc.tuple(fc.integer({ min: 0, max: 360 }), fc.integer({ min: 0, max: 260 })), { maxLength: 12 }),
        (spots) => {
          const p = panel(...spots.map(([x, y], i) => lamp(`w${i}`, x, y)));
          const { x, y } = freeSpot(p, 40, 30);
          const overlaps = (p.widgets ?? []).some(
            (o) => x < o.x + o.w && o.x < x + 40 && y < o.y + o.h && o.y < y + 30,
          );
          expect(overlaps && !(x === 0 && y === 0)).toBe(false);
        },
      ),
    );
  });

  it("lists what a panel reads once each", () => {
    const p = panel(
      {
        type: "lamp",
        id: "a",
        x: 0,
        y: 0,
        w: 9,
        h: 9,
        bind: "Main.Go",
        visible: "main.go",
        move_x: { path: "Tank.Level", distance: 9 },
      },
      { type: "trend", id: "t", x: 0, y: 0, w: 9, h: 9, paths: ["Tank.Level", "Temp"] },
      { type: "label", id: "l", x: 0, y: 0, w: 9, h: 9, text: "x" },
    );
    expect(bindingsOf(p)).toEqual(["Main.Go", "Tank.Level", "Temp"]);
  });
});

describe("what widgets show and send", () => {
  it("moves by the value's share of its range, held at the ends", () => {
    fc.assert(
      fc.property(
        fc.double({ min: -1e6, max: 1e6, noNaN: true }),
        fc.integer({ min: -400, max: 400 }),
        (value, distance) => {
          const offset = motionOffset({ path: "x", min: 0, max: 100, distance }, value);
          expect(Math.abs(offset)).toBeLessThanOrEqual(Math.abs(distance));
          if (value >= 0 && value <= 100) expect(offset).toBeCloseTo((value / 100) * distance, 6);
        },
      ),
    );
    expect(motionOffset({ path: "x", min: 20, max: 40, distance: 100 }, 30)).toBe(50);
    expect(motionOffset(null, 30)).toBe(0);
  });

  it("picks the state of a value, BOOLs as 0/1", () => {
    const states = [
      { value: 0, text: "idle" },
      { value: 1, text: "run" },
    ];
    expect(stateOf(states, 1)?.text).toBe("run");
    expect(stateOf(states, true)?.text).toBe("run");
    expect(stateOf(states, 7)).toBeUndefined();
  });

  it("writes seven-segment digits right-aligned, dashes when too long", () => {
    expect(sevenSegmentText(42, 4)).toBe("  42");
    expect(sevenSegmentText(-5.7, 3)).toBe(" -5");
    expect(sevenSegmentText(12345, 4)).toBe("----");
    expect(sevenSegmentText(undefined, 2)).toBe("  ");
  });

  it("sends TRUE while a normally open button is held, FALSE while a normally closed one is", () => {
    expect([pushValue(true, false), pushValue(false, false), pushValue(true, true), pushValue(false, true)]).toEqual([
      true,
      false,
      false,
      true,
    ]);
  });

  it("reads typed values as numbers or IEC literal text", () => {
    expect([typedValue("12"), typedValue("-1.5e3"), typedValue("T#2s"), typedValue("  ")]).toEqual([
      12,
      -1500,
      "T#2s",
      null,
    ]);
  });

  it("puts slider values on their steps within the range", () => {
    fc.assert(
      fc.property(fc.double({ min: -1, max: 2, noNaN: true }), (at) => {
        const v = sliderValue(at, 0, 4, 0.5);
        expect(v).toBeGreaterThanOrEqual(0);
        expect(v).toBeLessThanOrEqual(4);
        expect((v * 2) % 1).toBe(0);
      }),
    );
  });

  it("offers faults by type", () => {
    expect(faultModes("BOOL").map((m) => m.mode)).toEqual(["stuck_true", "stuck_false", "open", "noisy"]);
    expect(faultModes("REAL").map((m) => m.mode)).toEqual(["stuck", "open", "noisy"]);
    expect(faultModes("TIME")).toEqual([]);
  });

  it("keeps the trend's last span of virtual time, one sample per scan", () => {
    let columns: (number | null)[][] = [[], []];
    for (const t of [10, 20, 20, 30, 5000]) columns = appendSample(columns, t, [t / 10], 1000);
    expect(columns).toEqual([[5], [500]]);
    columns = appendSample([[], []], 10, [1], 1000);
    expect(appendSample(columns, 20, [2], 1000)).toEqual([
      [0.01, 0.02],
      [1, 2],
    ]);
  });
});

describe("run until and the panel window's address", () => {
  it("reads durations as virtual time from now, anything else as a condition", () => {
    expect(durationMs("T#1m30s")).toBe(90_000);
    expect(durationMs("500ms")).toBe(500);
    expect(durationMs("Level >= 80")).toBeNull();
    expect(parseUntil("2s", 1000)).toEqual({ time_ms: 3000 });
    expect(parseUntil("Tank.Level >= 80", 0)).toEqual({ condition: "Tank.Level >= 80" });
    expect(parseUntil(" ", 0)).toHaveProperty("error");
  });

  it("finds the panel and the simulation in the address", () => {
    expect(panelTarget("?panel=lab%2FRoom&simulation=s1")).toEqual({ project: "lab", panel: "Room", simulation: "s1" });
    expect(panelTarget("?panel=lab/Room")).toEqual({ project: "lab", panel: "Room", simulation: null });
    expect(panelTarget("")).toBeNull();
  });
});
