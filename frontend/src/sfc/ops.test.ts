import { describe, expect, it } from "vitest";
import { actionChartOf, chartOf, isStepLike, kindOf, locate, walk, type Sequence, type SfcBody } from "./model";
import { layoutChart, neighbour } from "./layout";
import * as ops from "./ops";

const ok = (result: ops.EditResult) => {
  if ("error" in result) throw new Error(result.error);
  return result;
};

/** Every sequence alternates step-like and transition-like elements and only ends with a jump. */
function wellFormed(sequence: Sequence): boolean {
  for (let i = 0; i < sequence.length; i += 1) {
    const e = sequence[i]!;
    if (kindOf(e) === "jump") return i === sequence.length - 1;
    if (i > 0 && isStepLike(e) === isStepLike(sequence[i - 1]!)) return false;
    if ("branches" in e && !e.branches.every(wellFormed)) return false;
  }
  return true;
}

const shape = (sequence: Sequence): unknown[] =>
  sequence.map((e) =>
    "branches" in e
      ? { [kindOf(e)]: e.branches.map(shape) }
      : kindOf(e) === "step"
        ? (e as { name: string }).name
        : kindOf(e),
  );

function chart(): SfcBody {
  let body: SfcBody = { chart: { elements: [] } };
  body = ok(ops.insertBelow(body, null)).body; // Init
  const init = chartOf(body)[0]!.id;
  body = ok(ops.insertBelow(body, init)).body; // Init, t, Step1
  return body;
}

describe("SFC edits keep the chart well formed", () => {
  it("starts with the initial step and adds a transition and a step below a step", () => {
    const body = chart();
    expect(shape(chartOf(body))).toEqual(["Init1", "transition", "Step1"]);
    expect(wellFormed(chartOf(body))).toBe(true);
  });

  it("adds a step and a transition below a transition, and a jump (with its transition) after the last step", () => {
    let body = chart();
    body = ok(ops.insertBelow(body, chartOf(body)[1]!.id)).body;
    expect(shape(chartOf(body))).toEqual(["Init1", "transition", "Step2", "transition", "Step1"]);
    body = ok(ops.addJump(body, chartOf(body)[4]!.id)).body;
    expect(shape(chartOf(body))).toEqual(["Init1", "transition", "Step2", "transition", "Step1", "transition", "jump"]);
    expect((chartOf(body)[6] as { target: string }).target).toBe("Init1");
    expect(ops.insertBelow(body, chartOf(body)[6]!.id)).toEqual({
      error: "Nothing goes below a jump: it ends its sequence.",
    });
    expect("error" in ops.addJump(body, chartOf(body)[1]!.id)).toBe(true);
    expect(wellFormed(chartOf(body))).toBe(true);
  });

  it("divides a transition into alternative branches and a step into simultaneous ones", () => {
    let body = chart();
    const transition = chartOf(body)[1]!.id;
    body = ok(ops.addAlternative(body, transition)).body;
    const alternative = chartOf(body)[1]!;
    expect(kindOf(alternative)).toBe("alternative");
    body = ok(ops.addAlternative(body, alternative.id)).body;
    expect((chartOf(body)[1] as { branches: Sequence[] }).branches).toHaveLength(3);
    const step = chartOf(body)[2]!.id;
    body = ok(ops.addParallel(body, step)).body;
    expect(shape(chartOf(body))).toEqual([
      "Init1",
      { alternative: [["transition"], ["transition"], ["transition"]] },
      { parallel: [["Step1"], ["Step2"]] },
    ]);
    expect(wellFormed(chartOf(body))).toBe(true);
    expect(ops.addParallel(body, chartOf(body)[0]!.id)).toEqual({
      error: "The initial step cannot be divided: add the simultaneous branches below it.",
    });
  });

  it("removes an element with its partner and unwraps a divergence left with one branch", () => {
    let body = chart();
    body = ok(ops.addParallel(body, chartOf(body)[2]!.id)).body;
    const branch2 = (chartOf(body)[2] as { branches: Sequence[] }).branches[1]![0]!.id;
    body = ok(ops.remove(body, branch2)).body;
    expect(shape(chartOf(body))).toEqual(["Init1", "transition", "Step1"]);
    body = ok(ops.remove(body, chartOf(body)[2]!.id)).body;
    expect(shape(chartOf(body))).toEqual(["Init1"]);
  });

  it("renames a step and the jumps to it, an action and the associations naming it", () => {
    let body = chart();
    body = ok(ops.addJump(body, chartOf(body)[2]!.id)).body;
    body = ok(ops.setStep(body, chartOf(body)[0]!.id, { name: "Start" })).body;
    expect((chartOf(body)[4] as { target: string }).target).toBe("Start");
    body = ok(ops.addAction(body, "Fill", "st")).body;
    body = ok(ops.addAssociation(body, chartOf(body)[2]!.id, { qualifier: "L", action: "Fill", time: "T#5s" })).body;
    body = ok(ops.renameAction(body, "Fill", "Load")).body;
    const step = locate(body, chartOf(body)[2]!.id)!.element as { actions: { action: string; time: string }[] };
    expect(step.actions[0]).toMatchObject({ action: "Load", time: "T#5s" });
    expect(ops.setStep(body, chartOf(body)[2]!.id, { name: "Load" })).toEqual({
      error: "Load is already the name of a step, action or transition.",
    });
    expect("error" in ops.setStep(body, chartOf(body)[2]!.id, { name: "a__b" })).toBe(true);
  });

  it("adds actions and named transitions written in IL as text (SFC-02): an empty action, a transition LD FALSE", () => {
    let body = chart();
    body = ok(ops.addAction(body, "Count", "il")).body;
    body = ok(ops.addNamedTransition(body, "Ready", "il")).body;
    expect(body.actions).toEqual([{ name: "Count", language: "il", body: "" }]);
    expect(body.transitions).toEqual([{ name: "Ready", language: "il", body: "LD FALSE" }]);
  });

  it("copies a step with its transition and pastes it below a transition with new ids and names", () => {
    let body = chart();
    body = ok(ops.insertBelow(body, chartOf(body)[2]!.id)).body; // Init1 t Step1 t Step2
    const fragment = ops.copyFragment(body, chartOf(body)[2]!.id)!;
    expect(fragment.map(kindOf)).toEqual(["step", "transition"]);
    const clip = ops.parseFragment(ops.serializeFragment(fragment))!;
    const pasted = ok(ops.pasteFragment(body, chartOf(body)[1]!.id, clip));
    const ids = [...walk(chartOf(pasted.body))].map((p) => p.element.id);
    expect(new Set(ids).size).toBe(ids.length);
    expect(wellFormed(chartOf(pasted.body))).toBe(true);
    expect(ops.pasteFragment(body, chartOf(body)[0]!.id, clip)).toEqual({ error: "Paste steps below a transition." });
  });
});

describe("SFC layout", () => {
  it("draws branches side by side and moves the selection between them with the arrows", () => {
    let body = chart();
    body = ok(ops.addParallel(body, chartOf(body)[2]!.id)).body;
    const layout = layoutChart(chartOf(body));
    const [left, right] = (chartOf(body)[2] as { branches: Sequence[] }).branches.map((b) => b[0]!.id);
    const l = layout.items.find((i) => i.element.id === left)!;
    const r = layout.items.find((i) => i.element.id === right)!;
    expect(l.y).toBe(r.y);
    expect(r.x).toBeGreaterThan(l.x);
    expect(layout.lines.filter((line) => line.double)).toHaveLength(2); // the divergence and the convergence
    expect(neighbour(layout, left!, "right")).toBe(right);
    expect(neighbour(layout, left!, "up")).toBe(chartOf(body)[1]!.id);
  });
});

describe("actions written in SFC (issue 24 item 1)", () => {
  it("a new SFC action gets a chart of its own whose step and ids are unique across the POU's charts", () => {
    let body = chart(); // Init, t, Step1 with ids s1, t1, s2 ...
    body = ok(ops.addAction(body, "Seq", "sfc")).body;
    const seq = body.actions!.find((a) => a.name === "Seq")!;
    expect(seq.language).toBe("sfc");
    const inner = (seq.body as { elements: Sequence }).elements;
    expect(shape(inner)).toEqual(["Seq_Init1", "transition", "jump"]);
    const outerIds = new Set([...walk(chartOf(body))].map((p) => p.element.id));
    expect(inner.map((e) => e.id).filter((id) => outerIds.has(id))).toEqual([]);
    // a second one does not reuse the first one's ids or step name
    body = ok(ops.addAction(body, "Seq2", "sfc")).body;
    const second = (body.actions!.find((a) => a.name === "Seq2")!.body as { elements: Sequence }).elements;
    expect(second.map((e) => e.id).filter((id) => inner.some((e) => e.id === id))).toEqual([]);
    // a step added to the POU's chart gets an id no action chart uses
    const step = ok(ops.insertBelow(body, chartOf(body)[0]!.id));
    const added = [...walk(chartOf(step.body))].map((p) => p.element.id).filter((id) => !outerIds.has(id));
    expect(added.filter((id) => [...inner, ...second].some((e) => e.id === id))).toEqual([]);
    // edited as a body of its own, an action's chart keeps off the POU's chart (its `enclosing`)
    const edited = { ...body, chart: { elements: inner }, enclosing: body.chart };
    const grown = ok(ops.insertBelow(edited, inner[1]!.id)).body;
    const fresh = [...walk(chartOf(grown))].map((p) => p.element.id).filter((id) => !inner.some((e) => e.id === id));
    expect(fresh).toHaveLength(2);
    expect(fresh.filter((id) => outerIds.has(id))).toEqual([]);
    // a halt at an element of an action's chart names that action (the view opens it)
    expect(actionChartOf(body, inner[0]!.id)).toBe("actions/Seq");
    expect(actionChartOf(body, second[0]!.id)).toBe("actions/Seq2");
    expect(actionChartOf(body, chartOf(body)[0]!.id)).toBeNull();
  });
});
