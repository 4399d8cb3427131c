import { describe, expect, it } from "vitest";
import { bodyOf, c, library, motorMain, net, par, q } from "./fixtures";
import { layoutBody, METRICS, type NetworkLayout } from "./layout";
import { insertNear, wrapInParallel } from "./ops";

const { gap, line, leftRail, branchGap, rowHeight } = METRICS;
const el = (n: NetworkLayout, id: string) => {
  const found = n.elements.find((e) => e.id === id);
  if (!found) throw new Error(`no element ${id}`);
  return found;
};

describe("series layout (GR-11, GR-13)", () => {
  it("places elements left to right with a wire gap and pushes the coil to the right rail", () => {
    const layout = layoutBody(bodyOf(net("n1", c("a"), c("b"), q("m"))));
    const [n] = layout.networks;
    expect(layout.rightRailX).toBe(METRICS.minRightRail);
    expect(n!.rungTop).toBe(METRICS.header + 6);
    const a = el(n!, "a");
    const b = el(n!, "b");
    const m = el(n!, "m");
    expect([a.x, a.width]).toEqual([leftRail + gap, METRICS.minElement]);
    expect(b.x).toBe(a.x + a.width + gap);
    expect(m.x + m.width + gap).toBe(layout.rightRailX);
    expect(new Set([a.lineY, b.lineY, m.lineY])).toEqual(new Set([n!.rungTop + line]));
    // one wire per gap: before a, between a-b, b-m (stretched), after m
    const wires = n!.wires.filter((w) => w.kind === "wire");
    expect(wires.map((w) => w.power)).toEqual([null, "a", "b", "m"]);
    expect(wires[2]!.x2 - wires[2]!.x1).toBe(m.x - (b.x + b.width));
    expect(n!.reachesRightRail).toBe(true);
  });

  it("leaves a rung without coils short of the right rail", () => {
    const [n] = layoutBody(bodyOf(net("n1", c("a")))).networks;
    expect(n!.reachesRightRail).toBe(false);
    expect(Math.max(...n!.wires.map((w) => w.x2))).toBe(leftRail + gap + METRICS.minElement + gap);
  });

  it("widens an element for a long operand and moves the right rail for a wide rung", () => {
    const long = "Conveyor_Section_Entry_Light_Barrier";
    const contacts = Array.from({ length: 9 }, (_, i) => c(`k${i}`, long));
    const layout = layoutBody(bodyOf(net("n1", ...contacts, q("m"))));
    expect(el(layout.networks[0]!, "k0").width).toBe(METRICS.maxElement);
    const natural = leftRail + 10 * gap + 9 * METRICS.maxElement + METRICS.minElement + gap;
    expect(layout.rightRailX).toBe(natural);
  });

  it("has insertion slots before, between and after the elements", () => {
    const [n] = layoutBody(bodyOf(net("n1", c("a"), q("m")))).networks;
    expect(n!.slots.map((s) => s.place.index)).toEqual([0, 1, 2]);
    expect(n!.slots[1]!.x).toBeGreaterThan(el(n!, "a").x + el(n!, "a").width);
    expect(n!.slots[1]!.x).toBeLessThan(el(n!, "m").x);
  });

  it("gives an empty network one slot on a short rung", () => {
    const [n] = layoutBody(bodyOf(net("n1"))).networks;
    expect(n!.elements).toEqual([]);
    expect(n!.slots).toEqual([
      {
        place: { series: { kind: "network", network: "n1" }, index: 0 },
        x: leftRail + METRICS.emptySeries / 2,
        y: n!.rungTop + line,
      },
    ]);
    expect(n!.height).toBe(n!.rungTop + rowHeight + METRICS.networkPad);
  });
});

describe("parallel layout (GR-14)", () => {
  it("stacks branches between two vertical links and extends the short branch", () => {
    const [n] = layoutBody(bodyOf(net("n1", par("p", [c("a"), c("b")], [c("s")]), q("m")))).networks;
    const p = el(n!, "p");
    const [a, s] = [el(n!, "a"), el(n!, "s")];
    expect(a.x).toBe(s.x);
    expect(s.lineY - a.lineY).toBe(rowHeight + branchGap);
    expect(p.height).toBe(2 * rowHeight + branchGap);
    const links = n!.wires.filter((w) => w.kind === "branch");
    expect(links).toEqual([
      { x1: p.x, y1: a.lineY, x2: p.x, y2: s.lineY, power: null, kind: "branch" },
      { x1: p.x + p.width, y1: a.lineY, x2: p.x + p.width, y2: s.lineY, power: "p", kind: "branch" },
    ]);
    const extension = n!.wires.find((w) => w.power === "s" && w.y1 === s.lineY && w.x2 === p.x + p.width);
    expect(extension?.x1).toBe(s.x + s.width + gap);
    expect(n!.rungBottom - n!.rungTop).toBe(p.height);
  });

  it("nests parallels: the inner one sits inside the outer branch", () => {
    const body = bodyOf(net("n1", par("outer", [c("a"), par("inner", [c("b")], [c("d")])], [c("e")]), q("m")));
    const [n] = layoutBody(body).networks;
    const [outer, inner, e] = [el(n!, "outer"), el(n!, "inner"), el(n!, "e")];
    expect(inner.x).toBeGreaterThan(outer.x);
    expect(inner.x + inner.width).toBeLessThanOrEqual(outer.x + outer.width);
    expect(e.y).toBe(inner.y + inner.height + branchGap);
    expect(outer.height).toBe(3 * rowHeight + 2 * branchGap);
    expect(n!.slots.filter((s) => s.place.series.kind === "branch").map((s) => s.place.series)).toContainEqual({
      kind: "branch",
      parallel: "inner",
      branch: 1,
    });
  });
});

describe("box layout (GR-27)", () => {
  const [, timer, counter] = layoutBody(motorMain, { library }).networks;

  it("draws the library pins with the power pins on the rung line", () => {
    const ton = el(timer!, "ton");
    expect(ton.pins!.map((p) => [p.side, p.name, p.power, p.value])).toEqual([
      ["in", "IN", true, undefined],
      ["in", "PT", false, "T#5s"],
      ["out", "Q", true, undefined],
      ["out", "ET", false, undefined],
    ]);
    const [inPower, pt, outPower] = ton.pins!;
    expect(inPower!.y).toBe(ton.lineY);
    expect(outPower!.y).toBe(ton.lineY);
    expect(pt!.y - inPower!.y).toBe(METRICS.pinRow);
    expect(ton.body!.x).toBe(inPower!.x);
    expect(el(timer!, "motor_on").lineY).toBe(ton.lineY);
  });

  it("lays a series feeding a pin out to the left of that pin, fed from a rail stub", () => {
    const ctu = el(counter!, "ctu");
    const r = ctu.pins!.find((p) => p.name === "R")!;
    const reset = el(counter!, "reset_count");
    expect(reset.series).toEqual({ kind: "pin", box: "ctu", pin: "R" });
    expect(reset.lineY).toBe(r.y);
    expect(reset.x + reset.width + gap).toBe(r.x);
    const stub = counter!.wires.find((w) => w.kind === "stub")!;
    expect(stub.x1).toBe(reset.x - gap);
    expect(stub.y1).toBeLessThan(r.y);
    expect(stub.y2).toBeGreaterThan(r.y);
    expect(ctu.pins!.find((p) => p.name === "CV")!.value).toBe("StartCount");
  });

  it("shows EN/ENO first when enabled and the function result pin", () => {
    const body = bodyOf(
      net("n1", {
        type: "box",
        id: "add",
        call: "ADD",
        en: true,
        inputs: { IN1: "A", IN2: "B", IN3: "C" },
        outputs: { OUT: "Sum" },
      }),
    );
    const [n] = layoutBody(body, { library }).networks;
    expect(el(n!, "add").pins!.map((p) => `${p.side}:${p.name}`)).toEqual([
      "in:EN",
      "in:IN1",
      "in:IN2",
      "in:IN3",
      "out:ENO",
      "out:OUT",
    ]);
  });

  it("shows only connected pins and an unnamed power pin for an unknown block", () => {
    const body = bodyOf(net("n1", { type: "box", id: "x", call: "Mystery", inputs: { A: "1" }, outputs: {} }));
    const [n] = layoutBody(body, { library }).networks;
    expect(el(n!, "x").pins!.map((p) => `${p.side}:${p.name}`)).toEqual(["in:", "in:A", "out:"]);
  });
});

describe("diagram", () => {
  it("stacks networks and makes room for a comment", () => {
    const layout = layoutBody(motorMain, { library });
    expect(layout.networks.map((n) => n.network.id)).toEqual(["seal_in", "run_timer", "count_starts", "lamp"]);
    layout.networks.forEach((n, i) => {
      expect(n.rungTop).toBe(METRICS.header + METRICS.comment + 6);
      if (i > 0) expect(n.top).toBe(layout.networks[i - 1]!.top + layout.networks[i - 1]!.height);
    });
    expect(layout.height).toBe(layout.networks.reduce((sum, n) => sum + n.height, 0));
  });

  it("reflows after edits: an inserted contact shifts what follows, the coil stays at the rail", () => {
    const body = bodyOf(net("n1", c("a"), q("m")), net("n2", c("z")));
    const before = layoutBody(body);
    const inserted = insertNear(body, { element: "a", side: "before" }, { type: "contact", var: "X", mode: "no" });
    if (!inserted.ok) throw new Error(inserted.error);
    const after = layoutBody(inserted.body);
    const newId = inserted.select[0]!;
    expect(el(after.networks[0]!, newId).x).toBe(el(before.networks[0]!, "a").x);
    expect(el(after.networks[0]!, "a").x).toBe(el(before.networks[0]!, "a").x + METRICS.minElement + gap);
    expect(el(after.networks[0]!, "m").x).toBe(el(before.networks[0]!, "m").x);

    const wrapped = wrapInParallel(inserted.body, ["a"]);
    if (!wrapped.ok) throw new Error(wrapped.error);
    const third = layoutBody(wrapped.body);
    expect(third.networks[0]!.height).toBe(after.networks[0]!.height + rowHeight + branchGap);
    expect(third.networks[1]!.top).toBe(third.networks[0]!.height);
  });

  // How fast is measured in the browser (tests/browser/test_ld_large.py, benchmarks/RESULTS.md), not timed here.
  it("lays out 1,000 networks one below the other", () => {
    const networks = Array.from({ length: 1000 }, (_, i) =>
      net(`n${i}`, par(`p${i}`, [c(`a${i}`)], [c(`b${i}`)]), c(`d${i}`), q(`m${i}`)),
    );
    const layout = layoutBody(bodyOf(...networks));
    expect(layout.networks).toHaveLength(1000);
    for (let i = 1; i < 1000; i++)
      expect(layout.networks[i]!.top).toBe(layout.networks[i - 1]!.top + layout.networks[i - 1]!.height);
  });
});

describe("reuse", () => {
  it("returns the same layout object for networks an edit did not touch", () => {
    const body = bodyOf(net("n1", c("a"), q("m")), net("n2", c("z")), net("n3", c("y")));
    const before = layoutBody(body);
    const edited = insertNear(body, { element: "z", side: "after" }, { type: "contact", var: "X", mode: "no" });
    if (!edited.ok) throw new Error(edited.error);
    const after = layoutBody(edited.body);
    expect(after.networks[0]).toBe(before.networks[0]);
    expect(after.networks[1]).not.toBe(before.networks[1]);
    expect(after.networks[2]).toBe(before.networks[2]);
    expect(layoutBody(edited.body).networks[1]).toBe(after.networks[1]);
  });
});
