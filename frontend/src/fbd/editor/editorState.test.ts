// @vitest-environment jsdom
// The FBD editor's transitions without React (issue 19): selection in a network's canvas and of a
// whole network, an edit's outcome, halt and focus requests, overlays, the networks near the viewport,
// and the pure questions (where new things go, what Delete and Copy take, what F9 toggles, the type a
// new variable is offered with, the variable behind a pin).
import { describe, expect, it } from "vitest";
import { arithmetic, bodyOf, lookup, SYMBOLS, wire } from "../fixtures";
import { networksOf, nodesOf, wiresOf, type Block, type FbdBody, type FbdNetwork } from "../model";
import type { EditResult } from "../ops";
import {
  breakpointTarget,
  clipOfSelection,
  declareOffer,
  deletion,
  fbdEditorReducer as reduce,
  guessType,
  INITIAL_STATE,
  pinOperand,
  revealPending,
  selectedNetworkIndex,
  targetNetwork,
  type FbdEditorAction,
  type FbdEditorState,
} from "./editorState";

/** n1: var1 + var2 - var3 -> result; n2: a TON instance t1 fed by input `start`, its Q to output `done`. */
const timer = (): FbdNetwork => ({
  id: "n2",
  nodes: [
    { type: "input", id: "s", expr: "start", pos: { x: 0, y: 0 } },
    { type: "block", id: "ton", call: "TON", instance: "t1", pos: { x: 200, y: 0 } },
    { type: "output", id: "d", var: "done", mode: "set", pos: { x: 400, y: 0 } },
  ],
  wires: [wire("s", "OUT", "ton", "IN"), wire("ton", "Q", "d", "IN")],
});
const BODY: FbdBody = bodyOf(arithmetic(), timer());

const run = (...actions: FbdEditorAction[]): FbdEditorState => actions.reduce(reduce, INITIAL_STATE);
const nodes = (network: string, ...ids: string[]): FbdEditorAction => ({
  type: "selectChanges",
  network,
  nodes: ids.map((id) => ({ id, selected: true })),
  edges: [],
});

describe("FBD editor state: selection", () => {
  it("gathers a canvas's selection changes into one selection of that network", () => {
    const s = run(nodes("n1", "a"), nodes("n1", "add"), {
      type: "selectChanges",
      network: "n1",
      nodes: [{ id: "a", selected: false }],
      edges: [{ id: "a.OUT->add.IN1", selected: true }],
    });
    expect(s.selection).toEqual({ network: "n1", nodes: ["add"], edges: ["a.OUT->add.IN1"] });
  });

  it("keeps the selection when another network's canvas lets go, and drops it when its own does", () => {
    const selected = run(nodes("n1", "a"));
    const otherLetsGo = reduce(selected, { type: "selectChanges", network: "n2", nodes: [], edges: [] });
    expect(otherLetsGo.selection).toEqual({ network: "n1", nodes: ["a"], edges: [] });
    const ownLetsGo = reduce(selected, {
      type: "selectChanges",
      network: "n1",
      nodes: [{ id: "a", selected: false }],
      edges: [],
    });
    expect(ownLetsGo.selection).toBeNull();
  });

  it("selects a whole network or nodes, never both", () => {
    const network = run(nodes("n1", "a"), { type: "selectNetwork", network: "n2" });
    expect([network.selection, network.networkSelected]).toEqual([null, "n2"]);
    const back = reduce(network, nodes("n1", "b"));
    expect([back.selection?.nodes, back.networkSelected]).toEqual([["b"], null]);
  });

  it("clears the selection and closes the menu on Escape", () => {
    const menu = { x: 1, y: 2, groups: [] };
    const s = run(nodes("n1", "a"), { type: "menu", menu }, { type: "clear" });
    expect([s.selection, s.networkSelected, s.menu]).toEqual([null, null, null]);
  });
});

describe("FBD editor state: an edit's outcome", () => {
  const ok = (select: string[]): EditResult => ({ ok: true, body: BODY, select });

  it("shows a failed edit's error and keeps the selection", () => {
    const s = run(nodes("n1", "a"), { type: "edited", result: { ok: false, error: "No." } });
    expect(s.message).toBe("No.");
    expect(s.selection?.nodes).toEqual(["a"]);
  });

  it("selects the new nodes in their network, or the new network, and clears the message", () => {
    const added = run({ type: "message", text: "old" }, { type: "edited", result: ok(["ton", "d"]) });
    expect([added.selection, added.message]).toEqual([{ network: "n2", nodes: ["ton", "d"], edges: [] }, null]);
    const network = run(nodes("n1", "a"), { type: "edited", result: ok(["n2"]) });
    expect([network.selection, network.networkSelected]).toEqual([null, "n2"]);
  });

  it("keeps the selection when the edit selects nothing", () => {
    expect(run(nodes("n1", "a"), { type: "edited", result: ok([]) }).selection?.nodes).toEqual(["a"]);
  });
});

describe("FBD editor state: halt and focus", () => {
  const reveal = (
    state: FbdEditorState,
    halt: { key: string | null; place: { network?: string; element?: string } | null },
    focus: { network?: string; element?: string; seq: number } | null,
  ) => reduce(state, { type: "reveal", halt, focus, body: BODY });

  it("selects a clicked diagnostic's node and scrolls to its network, once per request", () => {
    const s = reveal(INITIAL_STATE, { key: null, place: null }, { element: "ton", seq: 1 });
    expect([s.selection, s.revealed.network]).toEqual([{ network: "n2", nodes: ["ton"], edges: [] }, "n2"]);
    expect(revealPending(s, null, 1)).toBe(false);
    expect(revealPending(s, null, 2)).toBe(true);
  });

  it("selects a halted network; a new halt wins over an old focus request", () => {
    const focused = reveal(INITIAL_STATE, { key: null, place: null }, { element: "a", seq: 1 });
    const halted = reveal(focused, { key: "n2:", place: { network: "n2" } }, { element: "a", seq: 1 });
    expect([halted.networkSelected, halted.revealed.network]).toEqual(["n2", "n2"]);
  });

  it("records a request for a place that is gone without selecting anything", () => {
    const s = reveal(INITIAL_STATE, { key: null, place: null }, { element: "gone", seq: 3 });
    expect([s.selection, s.revealed]).toEqual([null, { halt: null, focus: 3, network: null }]);
  });
});

describe("FBD editor state: overlays and the viewport", () => {
  it("toggles the shortcut help", () => {
    expect(run({ type: "help", open: "toggle" }).help).toBe(true);
    expect(run({ type: "help", open: "toggle" }, { type: "help", open: "toggle" }).help).toBe(false);
  });

  it("tracks the networks near the viewport, unchanged when nothing changes", () => {
    const s = run({ type: "near", network: "n1", near: true }, { type: "near", network: "n2", near: true });
    expect([...s.near].sort()).toEqual(["n1", "n2"]);
    expect(reduce(s, { type: "near", network: "n1", near: true })).toBe(s);
    expect([...reduce(s, { type: "near", network: "n1", near: false }).near]).toEqual(["n2"]);
  });
});

describe("FBD editor state: questions", () => {
  it("puts new things into the selected network, else the last one", () => {
    expect(targetNetwork(INITIAL_STATE, BODY)).toBe("n2");
    expect(targetNetwork(run(nodes("n1", "a")), BODY)).toBe("n1");
    expect(targetNetwork(run({ type: "selectNetwork", network: "n1" }), BODY)).toBe("n1");
    expect(targetNetwork(INITIAL_STATE, bodyOf())).toBeNull();
    expect(selectedNetworkIndex(run(nodes("n2", "s")), BODY)).toBe(1);
    expect(selectedNetworkIndex(INITIAL_STATE, BODY)).toBe(-1);
  });

  it("deletes the selected nodes and the selected wires, else the selected network", () => {
    const cut = deletion(
      run({ type: "selectChanges", network: "n1", nodes: [], edges: [{ id: "add.OUT->sub.IN1", selected: true }] }),
      BODY,
    );
    expect(cut?.ok && wiresOf(networksOf(cut.body)[0]!).map((w) => `${w.from.node}->${w.to.node}`)).toEqual([
      "a->add",
      "b->add",
      "c->sub",
      "sub->r",
    ]);
    const gone = deletion(run(nodes("n2", "ton")), BODY);
    expect(gone?.ok && nodesOf(networksOf(gone.body)[1]!).map((n) => n.id)).toEqual(["s", "d"]);
    const network = deletion(run({ type: "selectNetwork", network: "n1" }), BODY);
    expect(network?.ok && networksOf(network.body).map((n) => n.id)).toEqual(["n2"]);
    expect(deletion(INITIAL_STATE, BODY)).toBeNull();
  });

  it("copies the selected nodes with the wires between them only", () => {
    const clip = clipOfSelection(run(nodes("n1", "a", "add")), BODY);
    expect(clip?.nodes.map((n) => n.id)).toEqual(["a", "add"]);
    expect(clip?.wires).toEqual([wire("a", "OUT", "add", "IN1")]);
    expect(clipOfSelection(run({ type: "selectNetwork", network: "n1" }), BODY)).toBeNull();
  });

  it("toggles a breakpoint on the one selected node, else on the network", () => {
    expect(breakpointTarget(run(nodes("n1", "add")))).toEqual({ element: "add" });
    expect(breakpointTarget(run(nodes("n1", "a", "b")))).toEqual({ network: "n1" });
    expect(breakpointTarget(run({ type: "selectNetwork", network: "n2" }))).toEqual({ network: "n2" });
    expect(breakpointTarget(INITIAL_STATE)).toBeNull();
  });

  it("offers a new variable with the type of where it is used", () => {
    // An input feeding ADD's ANY_NUM pin: INT, the family's usual member; a set output: BOOL; an instance: its FB.
    expect(guessType(BODY, "a", lookup, SYMBOLS)).toBe("INT");
    expect(guessType(BODY, "d", lookup, SYMBOLS)).toBe("BOOL");
    expect(guessType(BODY, "ton", lookup, SYMBOLS)).toBe("TON");
    // An input feeding TON's IN: BOOL.
    expect(declareOffer(BODY, "s", "start", new Set(["VAR1"]), lookup, SYMBOLS)).toEqual({
      name: "start",
      type: "BOOL",
    });
    expect(declareOffer(BODY, "a", "var1", new Set(["VAR1"]), lookup, SYMBOLS)).toBeNull();
    expect(declareOffer(BODY, "a", "42", new Set(), lookup, SYMBOLS)).toBeNull();
  });

  it("names the variable behind a pin: the instance's pin, or the input wired to a function's pin", () => {
    const [, network2] = networksOf(BODY);
    const ton = nodesOf(network2!).find((n) => n.id === "ton")!;
    expect(pinOperand(BODY, ton as Block, "in", "PT", lookup)).toBe("t1.PT");
    const add = nodesOf(networksOf(BODY)[0]!).find((n) => n.id === "add")!;
    expect(pinOperand(BODY, add as Block, "in", "IN2", lookup)).toBe("var2");
    expect(pinOperand(BODY, add as Block, "out", "OUT", lookup)).toBeNull();
  });
});
