import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { route, STUB, type Box, type Point } from "./route";

const inside = (p: Point, b: Box) => p.x > b.x && p.x < b.x + b.width && p.y > b.y && p.y < b.y + b.height;

/** Does the orthogonal polyline cross the inside of the box? (sampled every pixel) */
function hits(points: Point[], box: Box): boolean {
  for (let i = 1; i < points.length; i += 1) {
    const a = points[i - 1]!;
    const b = points[i]!;
    const steps = Math.max(Math.abs(a.x - b.x), Math.abs(a.y - b.y));
    for (let k = 0; k <= steps; k += 1) {
      const t = steps ? k / steps : 0;
      if (inside({ x: a.x + (b.x - a.x) * t, y: a.y + (b.y - a.y) * t }, box)) return true;
    }
  }
  return false;
}

const orthogonal = (points: Point[]) => points.slice(1).every((p, i) => p.x === points[i]!.x || p.y === points[i]!.y);

describe("orthogonal FBD wires", () => {
  it("a wire between two pins on one row is straight", () => {
    expect(route({ x: 100, y: 50 }, { x: 200, y: 50 }, [])).toEqual([
      { x: 100, y: 50 },
      { x: 200, y: 50 },
    ]);
  });

  it("turns in the middle of the gap between two rows", () => {
    expect(route({ x: 100, y: 50 }, { x: 200, y: 90 }, [])).toEqual([
      { x: 100, y: 50 },
      { x: 150, y: 50 },
      { x: 150, y: 90 },
      { x: 200, y: 90 },
    ]);
  });

  it("goes around a block in the way instead of behind it", () => {
    const block = { x: 140, y: 30, width: 40, height: 60 };
    const points = route({ x: 100, y: 60 }, { x: 240, y: 60 }, [block]);
    expect(orthogonal(points)).toBe(true);
    expect(hits(points, block)).toBe(false);
    expect(points[0]).toEqual({ x: 100, y: 60 });
    expect(points[points.length - 1]).toEqual({ x: 240, y: 60 });
  });

  it("a feedback wire leaves right, comes back around and enters from the left", () => {
    const block = { x: 100, y: 40, width: 60, height: 60 };
    const points = route({ x: 160, y: 60 }, { x: 100, y: 80 }, [block]);
    expect(hits(points, block)).toBe(false);
    expect(points[1]!.x).toBeGreaterThanOrEqual(160 + STUB);
    expect(points[points.length - 2]!.x).toBeLessThanOrEqual(100 - STUB);
  });

  it("a loop from a later block back to an earlier one goes around both (property, issue 22 item 6)", () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 0, max: 20 }).map((n) => n * 10),
        fc.integer({ min: 0, max: 20 }).map((n) => n * 10),
        fc.integer({ min: 8, max: 30 }).map((n) => n * 10),
        fc.integer({ min: 0, max: 1 }),
        (y1, y2, gap, pin) => {
          const earlier = { x: 100, y: y1, width: 60, height: 50 };
          const later = { x: 100 + 60 + gap, y: y2, width: 60, height: 50 };
          const source = { x: later.x + later.width, y: later.y + 20 }; // the later block's output
          const target = { x: earlier.x, y: earlier.y + 15 + 20 * pin }; // an input of the earlier block
          const points = route(source, target, [earlier, later]);
          expect(orthogonal(points)).toBe(true);
          expect(hits(points, earlier) || hits(points, later)).toBe(false);
          expect(points[1]!.x).toBeGreaterThanOrEqual(source.x + STUB); // leaves to the right
          expect(points[points.length - 2]!.x).toBeLessThanOrEqual(target.x - STUB); // enters from the left
        },
      ),
    );
  });

  it("never crosses a node when there is room around them (property)", () => {
    const box = fc.record({
      x: fc.integer({ min: 0, max: 40 }).map((n) => n * 10),
      y: fc.integer({ min: 0, max: 30 }).map((n) => n * 10),
      width: fc.constantFrom(40, 60),
      height: fc.constantFrom(30, 50),
    });
    fc.assert(
      fc.property(
        fc.array(box, { maxLength: 4 }),
        fc.integer({ min: 0, max: 300 }),
        fc.integer({ min: 0, max: 300 }),
        (boxes, y1, y2) => {
          const source = { x: -100, y: y1 };
          const target = { x: 600, y: y2 };
          const points = route(source, target, boxes);
          expect(orthogonal(points)).toBe(true);
          expect(points[0]).toEqual(source);
          expect(points[points.length - 1]).toEqual(target);
          const free = boxes.every((b) => !inside(source, b) && !inside(target, b));
          // pins outside every box, boxes with room above and below: a route around them exists
          if (free) expect(boxes.filter((b) => hits(points, b))).toEqual([]);
        },
      ),
    );
  });
});
