// @vitest-environment jsdom
// Auto-arrange of a network with a feedback loop (issue 22 item 6): data flows left to right, the wire that
// closes the loop is the only one running back, around the blocks, and the execution order is kept.
import { describe, expect, it } from "vitest";
import { arrange } from "./arrange";
import { wire } from "./fixtures";
import type { FbdBody, FbdNetwork, FbdNode, Position } from "./model";
import * as ops from "./ops";
import { route, type Box } from "./route";

/** in -> ADD(add).IN1, add -> MUL(mul).IN1, mul -> out, and mul back into add.IN2 (an accumulator's loop);
 * the nodes listed so that a walk starting at add sees mul first. */
const loop = (): FbdNetwork => ({
  id: "n1",
  nodes: [
    { type: "block", id: "add", call: "ADD" },
    { type: "output", id: "out", var: "Total" },
    { type: "block", id: "mul", call: "MUL" },
    { type: "input", id: "in", expr: "Step" },
    { type: "input", id: "k", expr: "2" },
  ],
  wires: [
    wire("in", "OUT", "add", "IN1"),
    wire("add", "OUT", "mul", "IN1"),
    wire("k", "OUT", "mul", "IN2"),
    wire("mul", "OUT", "out", "IN"),
    wire("mul", "OUT", "add", "IN2"),
  ],
});

const HEIGHT = 60;
const WIDTH = 100; // the widest block drawn here (fbd.css: min-width 96px)
const box = (p: Position): Box => ({ x: p.x, y: p.y, width: WIDTH, height: HEIGHT });
const overlap = (a: Box, b: Box) =>
  a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;

function checkLayout(pos: Map<string, Position>) {
  const x = (id: string) => pos.get(id)!.x;
  // the data flow runs left to right through the loop: in, add, mul, out
  expect(x("in")).toBeLessThan(x("add"));
  expect(x("add")).toBeLessThan(x("mul"));
  expect(x("k")).toBeLessThan(x("mul"));
  expect(x("mul")).toBeLessThan(x("out"));
  // no two boxes overlap
  const boxes = [...pos.values()].map(box);
  for (const a of boxes) for (const b of boxes) if (a !== b) expect(overlap(a, b)).toBe(false);
  // the back wire (mul.OUT -> add.IN2) goes around both blocks, inside the drawing (y >= 0)
  const source = { x: x("mul") + WIDTH, y: pos.get("mul")!.y + 30 };
  const target = { x: x("add"), y: pos.get("add")!.y + 40 };
  const points = route(source, target, boxes);
  for (const [a, b] of points.slice(1).map((p, i) => [points[i]!, p] as const))
    for (const node of boxes) {
      const horizontal = a.y === b.y;
      const [lo, hi] = horizontal ? [Math.min(a.x, b.x), Math.max(a.x, b.x)] : [Math.min(a.y, b.y), Math.max(a.y, b.y)];
      const inside = horizontal
        ? a.y > node.y && a.y < node.y + node.height && hi > node.x && lo < node.x + node.width
        : a.x > node.x && a.x < node.x + node.width && hi > node.y && lo < node.y + node.height;
      expect(inside).toBe(false);
    }
  expect(Math.min(...points.map((p) => p.y))).toBeGreaterThanOrEqual(0);
  expect(points[1]!.x).toBeGreaterThan(source.x); // leaves the later block to the right
  expect(points[points.length - 2]!.x).toBeLessThan(target.x); // enters the earlier block from the left
}

describe("auto-arrange of a feedback loop (issue 22 item 6)", () => {
  it("keeps the loop's data flow left to right with the execution order the backend reported", () => {
    checkLayout(arrange(loop(), () => HEIGHT, ["in", "add", "k", "mul", "out"]));
  });

  it("finds the loop's back wire from the inputs when the order is not known yet", () => {
    checkLayout(arrange(loop(), () => HEIGHT));
  });

  it("keeps the order the loop runs in (stored as the network's order)", () => {
    const body: FbdBody = { networks: [loop()] };
    const result = ops.arrangeNetwork(body, "n1", () => HEIGHT, ["in", "add", "k", "mul", "out"]);
    expect(result.ok && result.body.networks![0]!.order).toEqual(["add", "mul", "out"]);
  });

  it("a block fed by its own output stays in its column, right of its input", () => {
    const self: FbdNetwork = {
      id: "n1",
      nodes: [{ type: "block", id: "add", call: "ADD" } as FbdNode, { type: "input", id: "in", expr: "x" }],
      wires: [wire("in", "OUT", "add", "IN1"), wire("add", "OUT", "add", "IN2")],
    };
    const pos = arrange(self, () => HEIGHT);
    expect(pos.get("in")!.x).toBeLessThan(pos.get("add")!.x);
  });
});
