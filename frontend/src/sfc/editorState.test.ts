// The SFC editor's transitions without React (issue 19): selection of elements and association rows,
// an edit's outcome, focus requests, overlays, zoom levels and fit, and the pure questions (what Enter
// edits, what Delete removes, what Copy takes and where Paste goes, what Ctrl+Enter opens, what F9 toggles).
import { describe, expect, it } from "vitest";
import { chartOf, type SfcBody } from "./model";
import type { EditResult } from "./ops";
import {
  breakable,
  clipText,
  deletion,
  editingOf,
  INITIAL_STATE,
  openedAction,
  pasting,
  sfcEditorReducer as reduce,
  type SfcEditorAction,
  type SfcEditorState,
} from "./editorState";

/** Fill (N Pump, S Valve) -t1 [Level]- Drain -t2- jump to Fill; the POU has the action Pump only. */
const BODY: SfcBody = {
  chart: {
    elements: [
      {
        type: "step",
        id: "s1",
        name: "Fill",
        actions: [
          { id: "a1", qualifier: "N", action: "Pump" },
          { id: "a2", qualifier: "S", action: "Valve" },
        ],
      },
      { type: "transition", id: "t1", condition: "Level" },
      { type: "step", id: "s2", name: "Drain", actions: [] },
      { type: "transition", id: "t2", condition: "TRUE" },
      { type: "jump", id: "j1", target: "Fill" },
    ],
  },
  actions: [{ name: "Pump", language: "st" }],
};

const run = (...actions: SfcEditorAction[]): SfcEditorState => actions.reduce(reduce, INITIAL_STATE);
const ids = (body: SfcBody) => chartOf(body).map((e) => e.id);

describe("SFC editor state: selection and edits", () => {
  it("selects an element without an association row, or a row of a step", () => {
    const row = run({ type: "selectAssociation", step: "s1", row: "a2" });
    expect([row.selected, row.association]).toEqual(["s1", "a2"]);
    const clicked = reduce(row, { type: "select", id: "t1" });
    expect([clicked.selected, clicked.association]).toEqual(["t1", null]);
  });

  it("shows a failed edit's error and keeps the selection; a good one selects what it names", () => {
    const failed = run({ type: "select", id: "t1" }, { type: "edited", result: { error: "No." } });
    expect([failed.selected, failed.message]).toEqual(["t1", "No."]);
    const good: EditResult = { body: BODY, select: "s2" };
    const done = reduce(failed, { type: "edited", result: good });
    expect([done.selected, done.message]).toEqual(["s2", null]);
    expect(reduce(failed, { type: "edited", result: { body: BODY } }).selected).toBe("t1");
  });

  it("acts on a focus request once per sequence number", () => {
    const focused = run({ type: "focus", focus: { element: "t2", seq: 1 } });
    expect(focused.selected).toBe("t2");
    const moved = reduce(focused, { type: "select", id: "s1" });
    expect(reduce(moved, { type: "focus", focus: { element: "t2", seq: 1 } })).toBe(moved);
    expect(reduce(moved, { type: "focus", focus: { element: "t2", seq: 2 } }).selected).toBe("t2");
  });

  it("opens and closes the overlays", () => {
    const s = run(
      { type: "edit", editing: { kind: "name", id: "s1" } },
      { type: "associating", open: true },
      { type: "help", open: "toggle" },
    );
    expect([s.editing, s.associating, s.help]).toEqual([{ kind: "name", id: "s1" }, true, true]);
    expect(reduce(s, { type: "help", open: "toggle" }).help).toBe(false);
  });
});

describe("SFC editor state: zoom", () => {
  it("steps through the zoom levels and stops at their ends", () => {
    expect(run({ type: "zoom", step: "in" }).zoom).toBe(1.25);
    expect(run({ type: "zoom", step: "out" }, { type: "zoom", step: "out" }).zoom).toBe(0.67);
    const least = run(...Array<SfcEditorAction>(9).fill({ type: "zoom", step: "out" }));
    expect(least.zoom).toBe(0.5);
    expect(run(...Array<SfcEditorAction>(9).fill({ type: "zoom", step: "in" })).zoom).toBe(2);
    expect(reduce(least, { type: "zoom", step: "reset" }).zoom).toBe(1);
  });

  it("takes a fitted zoom and steps on from it to the next level", () => {
    const fitted = run({ type: "zoomTo", zoom: 0.73 });
    expect(fitted.zoom).toBe(0.73);
    expect(reduce(fitted, { type: "zoom", step: "in" }).zoom).toBe(0.8);
    expect(reduce(fitted, { type: "zoom", step: "out" }).zoom).toBe(0.67);
  });
});

describe("SFC editor state: questions", () => {
  it("edits a step's name, a transition's condition, a jump's target", () => {
    expect(editingOf(BODY, "s2")).toEqual({ kind: "name", id: "s2" });
    expect(editingOf(BODY, "t1")).toEqual({ kind: "condition", id: "t1" });
    expect(editingOf(BODY, "j1")).toEqual({ kind: "target", id: "j1" });
    expect(editingOf(BODY, null)).toBeNull();
    expect(editingOf(BODY, "gone")).toBeNull();
  });

  it("deletes the selected association row, else the element with its partner", () => {
    const row = deletion(run({ type: "selectAssociation", step: "s1", row: "a1" }), BODY);
    expect(row && !("error" in row) && (chartOf(row.body)[0] as { actions: { id: string }[] }).actions).toEqual([
      { id: "a2", qualifier: "S", action: "Valve" },
    ]);
    const step = deletion(run({ type: "select", id: "s2" }), BODY);
    expect(step && !("error" in step) && ids(step.body)).not.toContain("s2");
    expect(deletion(INITIAL_STATE, BODY)).toBeNull();
  });

  it("copies from the selection and pastes below it, or says why not", () => {
    const text = clipText(run({ type: "select", id: "t1" }), BODY);
    expect(text).not.toBeNull();
    expect(clipText(INITIAL_STATE, BODY)).toBeNull();
    expect(pasting(INITIAL_STATE, BODY, "not a clip")).toEqual({
      error: "The clipboard holds no SFC steps or transitions.",
    });
    expect(pasting(INITIAL_STATE, BODY, text)).toEqual({ error: "Select where to paste first." });
    // A transition and its step pasted below the step Drain: two more elements, in that order.
    const pasted = pasting(run({ type: "select", id: "s2" }), BODY, text);
    expect("error" in pasted).toBe(false);
    if (!("error" in pasted))
      expect(chartOf(pasted.body).map((e) => e.type)).toEqual([
        "step",
        "transition",
        "step",
        "transition",
        "step",
        "transition",
        "jump",
      ]);
  });

  it("opens the action a selected association row names, when the POU has it", () => {
    expect(openedAction(run({ type: "selectAssociation", step: "s1", row: "a1" }), BODY)?.name).toBe("Pump");
    expect(openedAction(run({ type: "selectAssociation", step: "s1", row: "a2" }), BODY)).toBeUndefined();
    expect(openedAction(run({ type: "select", id: "s1" }), BODY)).toBeUndefined();
  });

  it("puts breakpoints on steps and transitions only", () => {
    expect(["s1", "t1", "j1", "gone"].map((id) => breakable(BODY, id))).toEqual([true, true, false, false]);
  });
});
