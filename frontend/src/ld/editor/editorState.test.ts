// The LD editor's transitions without React (issue 19): selection and anchor, an edit's outcome,
// focus requests, overlays, zoom steps, and the pure questions (what Copy takes, where Paste goes).
import { describe, expect, it } from "vitest";
import type { LdBody } from "../model";
import type { EditResult } from "../ops";
import {
  clipOf,
  INITIAL_STATE,
  ldEditorReducer as reduce,
  liveSelection,
  mainField,
  operandText,
  pastePlace,
  valueOperand,
  type LdEditorState,
} from "./editorState";

/** Two networks: n1 holds contact c1 (Start), contact c2 (Stop) and coil q1 (Motor) in series; n2 is empty. */
const BODY: LdBody = {
  networks: [
    {
      id: "n1",
      elements: [
        { type: "contact", id: "c1", var: "Start" },
        { type: "contact", id: "c2", var: "Stop", mode: "nc" },
        { type: "coil", id: "q1", var: "Motor" },
      ],
    },
    { id: "n2", elements: [] },
  ],
};

const ok = (select: string[], body: LdBody = BODY): EditResult => ({ ok: true, body, select });
const run = (...actions: Parameters<typeof reduce>[1][]): LdEditorState => actions.reduce(reduce, INITIAL_STATE);

describe("LD editor state: selection", () => {
  it("anchors a range at the first selected element, or where it is told", () => {
    expect(run({ type: "select", selection: { kind: "elements", ids: ["c2", "q1"] } }).anchor).toBe("c2");
    expect(run({ type: "select", selection: { kind: "elements", ids: ["q1"] }, anchor: "c1" }).anchor).toBe("c1");
    expect(run({ type: "select", selection: { kind: "network", id: "n1" } }).anchor).toBeNull();
  });

  it("scrolls to the selection's network only when revealing (a click does not scroll)", () => {
    const clicked = run({ type: "select", selection: { kind: "elements", ids: ["q1"] } });
    expect(clicked.reveal).toBeNull();
    const keyed = run({ type: "reveal", selection: { kind: "elements", ids: ["q1"] }, body: BODY });
    expect(keyed.reveal).toBe("n1");
  });

  it("drops what an undo removed from the selection", () => {
    expect(liveSelection(BODY, { kind: "elements", ids: ["gone", "c2"] })).toEqual({ kind: "elements", ids: ["c2"] });
    expect(liveSelection(BODY, { kind: "elements", ids: ["gone"] })).toBeNull();
    expect(liveSelection(BODY, { kind: "network", id: "n9" })).toBeNull();
    expect(liveSelection(BODY, { kind: "network", id: "n2" })).toEqual({ kind: "network", id: "n2" });
  });
});

describe("LD editor state: an edit's outcome", () => {
  it("shows a failed edit's error and keeps the selection", () => {
    const before = run({ type: "select", selection: { kind: "elements", ids: ["c1"] } });
    const after = reduce(before, { type: "edited", result: { ok: false, error: "Select a coil first." } });
    expect(after.message).toBe("Select a coil first.");
    expect(after.selection).toEqual({ kind: "elements", ids: ["c1"] });
  });

  it("selects and reveals the new elements, clears the message, and opens the operand editor when asked", () => {
    const state = run({ type: "message", text: "old" }, { type: "edited", result: ok(["q1"]), then: "edit" });
    expect(state).toMatchObject({
      message: null,
      selection: { kind: "elements", ids: ["q1"] },
      anchor: "q1",
      reveal: "n1",
      pendingEdit: "q1",
    });
    expect(reduce(state, { type: "pendingEditDone" }).pendingEdit).toBeNull();
  });

  it("selects a network an edit names, and nothing when the edit selects nothing", () => {
    expect(run({ type: "edited", result: ok(["n2"]) })).toMatchObject({
      selection: { kind: "network", id: "n2" },
      reveal: "n2",
      pendingEdit: null,
    });
    const cleared = run(
      { type: "select", selection: { kind: "elements", ids: ["c1"] } },
      { type: "edited", result: ok([]) },
    );
    expect(cleared.selection).toBeNull();
  });
});

describe("LD editor state: focus requests", () => {
  it("selects the element, else the network, once per request", () => {
    const element = run({ type: "focus", focus: { element: "c2", network: "n1", seq: 1 }, body: BODY });
    expect(element).toMatchObject({ selection: { kind: "elements", ids: ["c2"] }, reveal: "n1", focusSeen: 1 });
    const network = run({ type: "focus", focus: { element: "gone", network: "n2", seq: 1 }, body: BODY });
    expect(network.selection).toEqual({ kind: "network", id: "n2" });
    // The same request again (a later render) does not move a selection the user changed since.
    const moved = reduce(element, { type: "select", selection: { kind: "elements", ids: ["q1"] } });
    expect(reduce(moved, { type: "focus", focus: { element: "c2", seq: 1 }, body: BODY }).selection).toEqual({
      kind: "elements",
      ids: ["q1"],
    });
  });
});

describe("LD editor state: overlays and zoom", () => {
  it("opens and closes the overlays", () => {
    const open = run(
      { type: "picker", open: true },
      { type: "menu", at: { x: 3, y: 4 } },
      { type: "help", open: "toggle" },
      { type: "asIl", network: "n1" },
      { type: "offer", offer: { name: "Lamp", type: "BOOL" } },
      { type: "valuePrompt", request: { operand: "Speed", action: "write" } },
    );
    expect(open).toMatchObject({
      picker: true,
      menu: { x: 3, y: 4 },
      help: true,
      asIl: "n1",
      offer: { name: "Lamp", type: "BOOL" },
      valuePrompt: { operand: "Speed", action: "write" },
    });
    expect(reduce(open, { type: "help", open: "toggle" }).help).toBe(false);
  });

  it("zooms by the keys' steps and to a fitted zoom", () => {
    const fitted = run({ type: "zoom", step: "in" }, { type: "zoomTo", zoom: 0.73 });
    expect(fitted.zoom).toBe(0.73);
    expect(reduce(fitted, { type: "zoom", step: "in" }).zoom).toBe(0.8);
    expect(reduce(fitted, { type: "zoom", step: "reset" }).zoom).toBe(1);
  });
});

describe("LD editor: pure questions of the body", () => {
  it("copies the selected network or elements, nothing for a wire", () => {
    expect(clipOf(BODY, { kind: "network", id: "n2" })).toEqual({
      kind: "networks",
      networks: [BODY.networks![1]],
    });
    expect(clipOf(BODY, { kind: "elements", ids: ["c2", "gone"] })).toEqual({
      kind: "elements",
      elements: [{ type: "contact", id: "c2", var: "Stop", mode: "nc" }],
    });
    expect(clipOf(BODY, null)).toBeNull();
  });

  it("pastes after the last selected element, at a network's start, or on the selected wire", () => {
    const series = { kind: "network", network: "n1" };
    expect(pastePlace(BODY, { kind: "elements", ids: ["c1", "c2"] })).toMatchObject({ series, index: 2 });
    expect(pastePlace(BODY, { kind: "network", id: "n2" })).toEqual({
      series: { kind: "network", network: "n2" },
      index: 0,
    });
    expect(pastePlace(BODY, null)).toBeUndefined();
  });

  it("edits a contact's variable with Enter and reads it back; prepares a contact's value as a BOOL", () => {
    expect(mainField(BODY, "c2", () => undefined)).toEqual({ kind: "var" });
    expect(operandText(BODY, "c2", { kind: "var" })).toBe("Stop");
    expect(valueOperand(BODY, "q1", null, () => undefined)).toEqual({ operand: "Motor", type: "BOOL" });
  });
});
