// @vitest-environment jsdom
// FBD model operations (issue 9 "FBD editor"): nodes, wires, pins, order, arrange, undo, clipboard.
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { historyOf, record, redo, undo } from "../store/history";
import { serializeClip as serializeLdClip } from "../ld/clipboard";
import { arrange } from "./arrange";
import { clipOf, parseClip, pasteClip, PASTE_OFFSET, serializeClip } from "./clipboard";
import { arithmetic, bodyOf, lookup, SYMBOLS, wire } from "./fixtures";
import type { LibraryEntry } from "../generated/api";
import { plainSymbol } from "../store/project";
import {
  instanceMethodEntries,
  methodEntry,
  nodePins,
  nodesOf,
  wiresOf,
  type Block,
  type FbdBody,
  type FbdNetwork,
} from "./model";
import * as ops from "./ops";
import { moveInOrder } from "./order";

const ok = (result: ops.EditResult): FbdBody => {
  if (!result.ok) throw new Error(result.error);
  return result.body;
};
const net = (body: FbdBody, id = "n1"): FbdNetwork => body.networks!.find((n) => n.id === id)!;
const node = (body: FbdBody, id: string) => body.networks!.flatMap((n) => n.nodes ?? []).find((n) => n.id === id);

describe("nodes and networks", () => {
  it("adds networks and nodes with fresh readable ids", () => {
    let body = ok(ops.addNetwork({ networks: [] }));
    expect(body.networks!.map((n) => n.id)).toEqual(["n1"]);
    const added = ops.addNode(body, "n1", { type: "block", call: "ADD" }, { x: 10, y: 20 });
    body = ok(added);
    expect(added.ok && added.select).toEqual(["blk1"]);
    body = ok(ops.addNode(body, "n1", { type: "input", expr: "var1" }, { x: 0, y: 0 }));
    expect(nodesOf(net(body))).toEqual([
      { type: "block", id: "blk1", pos: { x: 10, y: 20 }, call: "ADD" },
      { type: "input", id: "in1", pos: { x: 0, y: 0 }, expr: "var1" },
    ]);
    expect(ops.addNode(body, "nope", { type: "return" }, { x: 0, y: 0 })).toEqual({
      ok: false,
      error: "There is no network nope.",
    });
  });

  it("deleting a node removes its wires and its place in the order list", () => {
    const body = bodyOf({ ...arithmetic(), order: ["add", "sub"] });
    const after = ok(ops.deleteNodes(body, ["add"]));
    expect(nodesOf(net(after)).map((n) => n.id)).toEqual(["a", "b", "c", "sub", "r"]);
    expect(wiresOf(net(after))).toEqual([wire("c", "OUT", "sub", "IN2"), wire("sub", "OUT", "r", "IN")]);
    expect(net(after).order).toEqual(["sub"]);
    expect(net(body).nodes).toHaveLength(6); // the old body is untouched (undo keeps it)
  });

  it("sets texts, output modes, EN/ENO and network label/comment", () => {
    let body = bodyOf(arithmetic());
    body = ok(ops.setNodeText(body, "a", " var2 "));
    body = ok(ops.setOutputMode(body, "r", "set"));
    body = ok(ops.setNetworkText(body, "n1", "label", " Start "));
    expect(node(body, "a")).toMatchObject({ expr: "var2" });
    expect(node(body, "r")).toMatchObject({ mode: "set" });
    expect(net(body).label).toBe("Start");
    expect(ops.setOutputMode(body, "add", "set")).toEqual({ ok: false, error: "Only output nodes have a mode." });
    const withEn = ok(
      ops.addNode(ok(ops.toggleEn(body, "add")), "n1", { type: "input", expr: "flag" }, { x: 0, y: 0 }),
    );
    const wired = ok(
      ops.connect(withEn, "n1", { from: { node: "in1", pin: "OUT" }, to: { node: "add", pin: "EN" } }, lookup, SYMBOLS),
    );
    expect(wiresOf(net(wired))).toHaveLength(6);
    const off = ok(ops.toggleEn(wired, "add"));
    expect((node(off, "add") as Block).en).toBe(false);
    expect(wiresOf(net(off))).toHaveLength(5); // the wire into EN went with it
  });
});

describe("wires", () => {
  it("connects compatible pins and refuses the rest with the reason", () => {
    const body = ok(ops.deleteNodes(bodyOf(arithmetic()), ["r"]));
    const withOut = ok(ops.addNode(body, "n1", { type: "output", var: "flag" }, { x: 0, y: 0 }));
    expect(
      ops.connect(
        withOut,
        "n1",
        { from: { node: "sub", pin: "OUT" }, to: { node: "out1", pin: "IN" } },
        lookup,
        SYMBOLS,
      ),
    ).toEqual({
      ok: false,
      error: "An INT output (sub.OUT) cannot feed a BOOL input (out1.IN).",
    });
    const result = ops.connect(
      body,
      "n1",
      { from: { node: "sub", pin: "OUT" }, to: { node: "add", pin: "IN1" } },
      lookup,
      SYMBOLS,
    );
    expect(result.ok).toBe(false);
    const withResult = ok(ops.addNode(body, "n1", { type: "output", var: "big" }, { x: 0, y: 0 }));
    const connected = ok(
      ops.connect(
        withResult,
        "n1",
        { from: { node: "sub", pin: "OUT" }, to: { node: "out1", pin: "IN" } },
        lookup,
        SYMBOLS,
      ),
    );
    expect(wiresOf(net(connected)).at(-1)).toEqual(wire("sub", "OUT", "out1", "IN")); // INT widens to DINT
    const cut = ok(ops.disconnect(connected, "n1", [wire("sub", "OUT", "out1", "IN")]));
    expect(wiresOf(net(cut))).toEqual(wiresOf(net(withResult)));
  });
});

describe("pins", () => {
  it("adds inputs to extensible blocks only, numbering on from the last", () => {
    let body = bodyOf(arithmetic());
    body = ok(ops.addInput(body, "add", lookup));
    body = ok(ops.addInput(body, "add", lookup));
    const pins = nodePins(node(body, "add")!, net(body), lookup, SYMBOLS);
    expect(pins.inputs.map((p) => `${p.name}:${p.type}`)).toEqual([
      "IN1:ANY_NUM",
      "IN2:ANY_NUM",
      "IN3:ANY_NUM",
      "IN4:ANY_NUM",
    ]);
    expect(ops.addInput(body, "sub", lookup)).toEqual({ ok: false, error: "SUB takes a fixed number of inputs." });
    const mux = ok(ops.addNode(body, "n1", { type: "block", call: "MUX" }, { x: 0, y: 0 }));
    expect(
      nodePins(node(ok(ops.addInput(mux, "blk1", lookup)), "blk1")!, net(mux), lookup, SYMBOLS).inputs.map(
        (p) => p.name,
      ),
    ).toEqual(["K", "IN0", "IN1", "IN2"]);
  });

  it("draws a method block inst.M with the method's inputs, its result as OUT and its VAR_OUTPUTs", () => {
    const pin = (name: string, type: string) => ({ name, type });
    const divider: LibraryEntry = {
      name: "Divider",
      kind: "function_block",
      source: "user",
      inputs: [],
      outputs: [],
      in_outs: [],
      extensible: false,
      return_type: null,
      comment: null,
      methods: [
        {
          name: "DivMod",
          kind: "function",
          source: "user",
          inputs: [pin("a", "INT"), pin("b", "INT")],
          outputs: [pin("q", "INT"), pin("r", "INT")],
          in_outs: [],
          extensible: false,
          return_type: "BOOL",
          comment: null,
        },
      ],
    };
    const withDivider = (call: string) => (call.toUpperCase() === "DIVIDER" ? divider : lookup(call));
    const symbols = [...SYMBOLS, plainSymbol("d", "Divider")];
    const body = ok(ops.addNode(bodyOf(arithmetic()), "n1", { type: "block", call: "d.DivMod" }, { x: 0, y: 0 }));
    const added = nodesOf(net(body)).find((n) => (n as Block).call === "d.DivMod")!;
    const pins = nodePins(added, net(body), withDivider, symbols);
    expect(pins.inputs.map((p) => `${p.name}:${p.type}`)).toEqual(["a:INT", "b:INT"]);
    expect(pins.outputs.map((p) => `${p.name}:${p.type}`)).toEqual(["OUT:BOOL", "q:INT", "r:INT"]);
    expect(methodEntry("d.Nope", withDivider, symbols)).toBeUndefined();
    expect(methodEntry("var1.DivMod", withDivider, symbols)).toBeUndefined(); // an INT has no methods
    // the block picker offers the method of each instance by its call, with the method's pins
    const offered = instanceMethodEntries([...symbols, plainSymbol("d2", "divider")], withDivider);
    expect(offered.map((e) => [e.name, e.kind, e.inputs.map((p) => p.name), e.return_type])).toEqual([
      ["d.DivMod", "function", ["a", "b"], "BOOL"],
      ["d2.DivMod", "function", ["a", "b"], "BOOL"],
    ]);
  });

  it("toggles negation bubbles and exclusive edge markers; no edges on outputs", () => {
    let body = bodyOf(arithmetic());
    body = ok(ops.togglePinFlag(body, "add", "IN1", "negated", "in"));
    body = ok(ops.togglePinFlag(body, "add", "IN1", "rising", "in"));
    expect((node(body, "add") as Block).pins).toEqual({ IN1: { negated: true, edge: "rising" } });
    body = ok(ops.togglePinFlag(body, "add", "IN1", "falling", "in"));
    expect((node(body, "add") as Block).pins).toEqual({ IN1: { negated: true, edge: "falling" } });
    body = ok(
      ops.togglePinFlag(ok(ops.togglePinFlag(body, "add", "IN1", "falling", "in")), "add", "IN1", "negated", "in"),
    );
    expect((node(body, "add") as Block).pins).toEqual({ IN1: { negated: false } });
    expect(ops.togglePinFlag(body, "add", "OUT", "rising", "out")).toEqual({
      ok: false,
      error: "Edge detection applies to inputs only.",
    });
    expect(ops.togglePinFlag(body, "a", "OUT", "negated", "out").ok).toBe(false);
  });
});

describe("execution order", () => {
  // The backend's order for the arithmetic network plus an independent MOVE-like output.
  const body = (): FbdBody =>
    bodyOf({
      ...arithmetic(),
      nodes: [...(arithmetic().nodes ?? []), { type: "output", id: "r2", var: "big" }],
      wires: [...(arithmetic().wires ?? []), wire("c", "OUT", "r2", "IN")],
    });
  const order = ["a", "b", "add", "c", "sub", "r", "r2"];

  it("moves an independent node earlier and stores the order list", () => {
    const moved = moveInOrder(body(), "n1", order, "r2", -1);
    expect(moved.ok && net(moved.body).order).toEqual(["add", "sub", "r2", "r"]);
  });

  it("refuses when data flow forbids it", () => {
    expect(moveInOrder(body(), "n1", order, "sub", -1)).toEqual({
      ok: false,
      error: "add feeds sub: data flow makes add run first.",
    });
    expect(moveInOrder(body(), "n1", order, "add", -1)).toEqual({ ok: false, error: "add already runs first." });
    expect(moveInOrder(body(), "n1", order, "a", 1).ok).toBe(false);
  });
});

describe("auto-arrange", () => {
  it("lays the arithmetic network out left to right and pins the order", () => {
    const result = ops.arrangeNetwork(bodyOf(arithmetic()), "n1", () => 60, ["a", "b", "add", "c", "sub", "r"]);
    const laid = net(ok(result));
    const x = Object.fromEntries(nodesOf(laid).map((n) => [n.id, n.pos!.x]));
    expect(x.a).toBeLessThan(x.add!);
    expect(x.add).toBeLessThan(x.sub!);
    expect(x.c).toBeLessThan(x.sub!);
    expect(x.sub).toBeLessThan(x.r!);
    expect(laid.order).toEqual(["add", "sub", "r"]);
  });

  it("every wire of an acyclic network runs left to right, and no two nodes of a column overlap", () => {
    const dag = fc
      .integer({ min: 1, max: 12 })
      .chain((n) => fc.tuple(fc.constant(n), fc.array(fc.tuple(fc.nat(n - 1), fc.nat(n - 1)), { maxLength: 25 })));
    fc.assert(
      fc.property(dag, ([n, edges]) => {
        const network: FbdNetwork = {
          id: "n",
          nodes: Array.from({ length: n }, (_, i) => ({ type: "block" as const, id: `b${i}`, call: "ADD" })),
          wires: edges.filter(([a, b]) => a < b).map(([a, b], i) => wire(`b${a}`, "OUT", `b${b}`, `IN${i}`)),
        };
        const pos = arrange(network, () => 50);
        for (const w of wiresOf(network)) expect(pos.get(w.from.node)!.x).toBeLessThan(pos.get(w.to.node)!.x);
        const all = [...pos.values()];
        for (const p of all)
          for (const q of all) if (p !== q && p.x === q.x) expect(Math.abs(p.y - q.y)).toBeGreaterThanOrEqual(50);
      }),
    );
  });
});

describe("undo, redo and the clipboard", () => {
  it("undo and redo step through edits of the body", () => {
    let h = historyOf(bodyOf(arithmetic()));
    h = record(h, ok(ops.deleteNodes(h.present, ["r"])));
    h = record(h, ok(ops.addInput(h.present, "add", lookup)));
    expect(node(undo(undo(h)).present, "r")).toBeDefined();
    expect(redo(undo(h)).present).toBe(h.present);
  });

  it("copies nodes with their inner wires and pastes them with fresh ids, offset", () => {
    const body = bodyOf(arithmetic());
    const text = serializeClip(clipOf(net(body), ["a", "b", "add"]));
    const clip = parseClip(text)!;
    expect(clip.wires).toEqual([wire("a", "OUT", "add", "IN1"), wire("b", "OUT", "add", "IN2")]);
    const pasted = pasteClip(body, "n1", clip);
    expect(pasted.ok && pasted.select).toEqual(["in1", "in2", "blk1"]);
    const after = net(ok(pasted));
    expect(wiresOf(after).slice(-2)).toEqual([wire("in1", "OUT", "blk1", "IN1"), wire("in2", "OUT", "blk1", "IN2")]);
    expect(nodesOf(after).find((n) => n.id === "blk1")!.pos).toEqual({ x: 200 + PASTE_OFFSET, y: PASTE_OFFSET });
    // Another POU without those ids keeps them.
    const other = pasteClip(bodyOf({ id: "n1" }), "n1", clip);
    expect(other.ok && other.select).toEqual(["a", "b", "add"]);
  });

  it("ignores texts that are not FBD clips (an LD clip, JSON, prose)", () => {
    expect(parseClip(serializeLdClip({ kind: "elements", elements: [] }))).toBeNull();
    expect(parseClip('{"format":"ladderlab/fbd-clip","nodes":[{"id":1}],"wires":[]}')).toBeNull();
    expect(parseClip("hello")).toBeNull();
  });
});

describe("comment boxes (issue 28)", () => {
  it("adds a comment node and edits its text, line breaks kept", () => {
    const body: FbdBody = { networks: [{ id: "n1", nodes: [], wires: [] }] };
    const added = ops.addNode(body, "n1", { type: "comment", text: "why" }, { x: 10, y: 20 });
    if (!added.ok) throw new Error(added.error);
    expect(added.body.networks![0]!.nodes).toEqual([
      { type: "comment", id: "note1", pos: { x: 10, y: 20 }, text: "why" },
    ]);
    const edited = ops.setNodeText(added.body, "note1", "first line\n  second line  ");
    if (!edited.ok) throw new Error(edited.error);
    expect(edited.body.networks![0]!.nodes![0]).toMatchObject({ text: "first line\n  second line" });
  });
});
