import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { ldBody } from "./arbitraries";
import { parseClip, serializeClip } from "./clipboard";
import { bodyOf, c, motorMain, net, q } from "./fixtures";
import { layoutBody } from "./layout";
import { locate, networksOf, seriesAt, walk, type LdBody, type LdElement } from "./model";
import {
  addBranch,
  addNetwork,
  box,
  coil,
  compare,
  contact,
  cycleMode,
  deleteElements,
  deleteNetworks,
  duplicateNetwork,
  feedPinFromRail,
  insertAt,
  insertNear,
  jump,
  moveElements,
  moveNetwork,
  pasteElements,
  pasteNetworks,
  rangeIds,
  ret,
  setMode,
  setNetworkComment,
  setNetworkLabel,
  setOperand,
  toggleEn,
  wrapInParallel,
  type EditResult,
} from "./ops";
import { isOutput, ldProblems } from "./validate";

function ok(result: EditResult) {
  if (!result.ok) throw new Error(`edit refused: ${result.error}`);
  expect(ldProblems(result.body)).toEqual([]);
  return result;
}
const ids = (body: LdBody) => [...walk(body)].map((l) => l.element.id);
const rung = (body: LdBody, n = 0) => networksOf(body)[n]!.elements!;
/** A rung as a compact string: contacts by var, coils as (var), parallels as [a|b]. */
function show(series: LdElement[]): string {
  return series
    .map((e) => {
      if (e.type === "contact") return e.mode === "no" ? e.var : `${e.var}/${e.mode}`;
      if (e.type === "coil") return `(${e.var})`;
      if (e.type === "parallel") return `[${e.branches.map(show).join("|")}]`;
      if (e.type === "box") return `<${e.call}>`;
      if (e.type === "jump") return `>>${e.target}`;
      if (e.type === "compare") return `${e.left}${e.op}${e.right}`;
      return "RET";
    })
    .join(" ");
}

const seal = () => bodyOf(net("n1", c("a"), c("b"), q("m")));

describe("insert (issue 7: insert contact before/after, coil, compare, jump, return)", () => {
  it("inserts a contact before and after the selection with a fresh id", () => {
    const before = ok(insertNear(seal(), { element: "b", side: "before" }, contact("nc", "X")));
    expect(show(rung(before.body))).toBe("A X/nc B (M)");
    expect(before.select).toEqual(["contact1"]);
    const after = ok(insertNear(before.body, { element: "b", side: "after" }, contact("p", "Y")));
    expect(show(rung(after.body))).toBe("A X/nc B Y/p (M)");
    expect(after.select).toEqual(["contact2"]);
  });

  it("puts a contact asked for after a coil before the coils", () => {
    const r = ok(insertNear(seal(), { element: "m", side: "after" }, contact("no", "X")));
    expect(show(rung(r.body))).toBe("A B X (M)");
  });

  it("puts a coil asked for among the inputs at the end of the rung, before a jump", () => {
    const r = ok(
      insertNear(
        bodyOf(net("n1", c("a"), c("b"), { type: "jump", id: "j", target: "L" })),
        { element: "a", side: "after" },
        coil("set", "Q"),
      ),
    );
    expect(show(rung(r.body))).toBe("A B (Q) >>L");
    const inPin = ok(insertNear(motorMain, { element: "reset_count", side: "after" }, coil("normal", "Z")));
    expect(show(rung(inPin.body, 2))).toBe("Start/p <CTU> (Z)");
  });

  it("appends a coil, compare, box, jump and return to a network's rung", () => {
    let body: LdBody = bodyOf(net("n1"));
    body = ok(insertNear(body, { network: "n1" }, coil("normal", "Q"))).body;
    body = ok(insertNear(body, { network: "n1" }, compare("GE"))).body;
    body = ok(insertNear(body, { network: "n1" }, box("TON", "T1"))).body;
    body = ok(insertNear(body, { network: "n1" }, ret())).body;
    expect(show(rung(body))).toBe("GE <TON> (Q) RET");
    const again = insertNear(body, { network: "n1" }, jump("L"));
    expect(again).toEqual({ ok: false, error: "jump must be the last element of its branch" });
  });

  it("refuses a coil inside a box input and an element after a return", () => {
    const place = { series: { kind: "pin", box: "ctu", pin: "R" } as const, index: 1 };
    expect(insertAt(motorMain, place, coil())).toEqual({ ok: false, error: "a box input cannot hold a coil" });
    const body = bodyOf(net("n1", c("a"), { type: "return", id: "r" }));
    expect(insertAt(body, { series: { kind: "network", network: "n1" }, index: 2 }, coil()).ok).toBe(false);
  });

  it("names a missing anchor instead of throwing", () => {
    expect(insertNear(seal(), { element: "ghost", side: "after" }, contact())).toEqual({
      ok: false,
      error: "no element ghost",
    });
    expect(insertNear(seal(), { network: "ghost" }, contact())).toEqual({ ok: false, error: "no network ghost" });
  });
});

describe("parallel branches (GR-14)", () => {
  it("wraps a run of contacts in a parallel with a new contact branch", () => {
    const r = ok(wrapInParallel(seal(), ["a", "b"]));
    expect(show(rung(r.body))).toBe("[A B|] (M)");
    expect(r.select).toEqual(["contact1"]);
    expect(locate(r.body, "contact1")?.series).toEqual({ kind: "branch", parallel: "par1", branch: 1 });
  });

  it("wraps a coil in a parallel coil", () => {
    expect(show(rung(ok(wrapInParallel(seal(), ["m"])).body))).toBe("A B [(M)|()]");
  });

  it("refuses a selection that is not one run of one branch", () => {
    expect(wrapInParallel(seal(), ["a", "m"])).toEqual({ ok: false, error: "select adjacent elements" });
    expect(wrapInParallel(motorMain, ["start", "seal"])).toEqual({ ok: false, error: "select elements of one branch" });
    expect(wrapInParallel(seal(), [])).toEqual({ ok: false, error: "nothing selected" });
  });

  it("adds a branch to a parallel", () => {
    const r = ok(addBranch(motorMain, "start_or_motor"));
    expect(show(rung(r.body))).toBe("[Start|Motor|] Stop/nc (Motor)");
    expect(addBranch(motorMain, "start").ok).toBe(false);
  });

  it("selects a range only inside one series", () => {
    expect(rangeIds(seal(), "m", "a")).toEqual(["a", "b", "m"]);
    expect(rangeIds(motorMain, "start", "stop")).toEqual(["stop"]);
  });
});

describe("delete", () => {
  it("dissolves a parallel left with one branch", () => {
    const r = ok(deleteElements(motorMain, ["seal"]));
    expect(show(rung(r.body))).toBe("Start Stop/nc (Motor)");
    expect(locate(r.body, "start_or_motor")).toBeUndefined();
    expect(r.select).toEqual(["start"]);
  });

  it("disconnects a box pin whose series became empty", () => {
    const r = ok(deleteElements(motorMain, ["reset_count"]));
    const ctu = locate(r.body, "ctu")!.element;
    expect(ctu.type === "box" && ctu.inputs).toEqual({ PV: "100" });
  });

  it("deletes a nested element with its parallel and selects the next element", () => {
    const r = ok(deleteElements(motorMain, ["start_or_motor"]));
    expect(show(rung(r.body))).toBe("Stop/nc (Motor)");
    expect(r.select).toEqual(["stop"]);
  });
});

describe("modes and operands (GR-15..GR-25)", () => {
  it("sets and cycles contact and coil modes", () => {
    expect(show(rung(ok(setMode(seal(), "a", "n")).body))).toBe("A/n B (M)");
    expect(setMode(seal(), "a", "set")).toEqual({ ok: false, error: "a contact has no mode set" });
    let body = seal();
    const seen = [];
    for (let i = 0; i < 6; i += 1) {
      body = ok(cycleMode(body, "m")).body;
      const m = locate(body, "m")!.element;
      seen.push(m.type === "coil" && m.mode);
    }
    expect(seen).toEqual(["negated", "set", "reset", "p", "n", "normal"]);
  });

  it("edits operand texts; an empty pin text disconnects the pin", () => {
    let body = ok(setOperand(motorMain, "ton", { kind: "input", pin: "PT" }, " T#2s ")).body;
    body = ok(setOperand(body, "ton", { kind: "output", pin: "ET" }, "Elapsed")).body;
    body = ok(setOperand(body, "ton", { kind: "instance" }, "")).body;
    const ton = locate(body, "ton")!.element;
    expect(ton.type === "box" && [ton.inputs, ton.outputs, ton.instance]).toEqual([
      { PT: "T#2s" },
      { ET: "Elapsed" },
      null,
    ]);
    body = ok(setOperand(body, "ton", { kind: "input", pin: "PT" }, "")).body;
    const bare = locate(body, "ton")!.element;
    expect(bare.type === "box" && bare.inputs).toEqual({});
    expect(setOperand(body, "start", { kind: "target" }, "L")).toEqual({
      ok: false,
      error: "a contact has no target operand",
    });
  });

  it("toggles EN/ENO and feeds a pin from the rail", () => {
    const on = ok(toggleEn(motorMain, "ton"));
    const ton = locate(on.body, "ton")!.element;
    expect(ton.type === "box" && ton.en).toBe(true);
    const fed = ok(feedPinFromRail(motorMain, "ton", "PT"));
    expect(seriesAt(fed.body, { kind: "pin", box: "ton", pin: "PT" })!.map((e) => e.id)).toEqual(fed.select);
  });
});

describe("move (drag an element to another place)", () => {
  it("moves a contact to a later place in the same series", () => {
    const body = bodyOf(net("n1", c("a"), c("b"), c("d"), q("m")));
    const r = ok(moveElements(body, ["a"], { series: { kind: "network", network: "n1" }, index: 3 }));
    expect(show(rung(r.body))).toBe("B D A (M)");
  });

  it("moves a contact out of a parallel into another network, dissolving the parallel", () => {
    const r = ok(moveElements(motorMain, ["seal"], { series: { kind: "network", network: "lamp" }, index: 0 }));
    expect(show(rung(r.body, 0))).toBe("Start Stop/nc (Motor)");
    expect(show(rung(r.body, 3))).toBe("Motor MotorRunning <Blinker> (Lamp)");
  });

  it("refuses to move a parallel into itself or a contact behind a coil", () => {
    const inside = { series: { kind: "branch", parallel: "start_or_motor", branch: 0 } as const, index: 0 };
    expect(moveElements(motorMain, ["start_or_motor"], inside)).toEqual({
      ok: false,
      error: "cannot move an element into itself",
    });
    expect(moveElements(seal(), ["a"], { series: { kind: "network", network: "n1" }, index: 3 }).ok).toBe(false);
  });
});

describe("networks", () => {
  it("adds, moves, duplicates and deletes networks", () => {
    let body = ok(addNetwork(motorMain, 1)).body;
    expect(networksOf(body).map((n) => n.id)).toEqual(["seal_in", "n1", "run_timer", "count_starts", "lamp"]);
    body = ok(moveNetwork(body, "n1", 4)).body;
    expect(networksOf(body).map((n) => n.id)).toEqual(["seal_in", "run_timer", "count_starts", "lamp", "n1"]);
    const dup = ok(duplicateNetwork(body, "seal_in"));
    const copy = networksOf(dup.body)[1]!;
    expect(dup.select).toEqual(["n2"]);
    expect(show(copy.elements!)).toBe("[Start|Motor] Stop/nc (Motor)");
    expect(ids({ networks: [copy] })).toEqual(["par1", "contact1", "contact2", "contact3", "coil1"]);
    const del = ok(deleteNetworks(dup.body, ["n2", "lamp"]));
    expect(networksOf(del.body).map((n) => n.id)).toEqual(["seal_in", "run_timer", "count_starts", "n1"]);
    expect(del.select).toEqual(["run_timer"]);
  });

  it("keeps labels unique identifiers or numbers (GR-03)", () => {
    let body = ok(setNetworkLabel(motorMain, "seal_in", "Start1")).body;
    expect(setNetworkLabel(body, "lamp", "start1")).toEqual({ ok: false, error: "label start1 is used twice" });
    expect(setNetworkLabel(body, "lamp", "1x")).toEqual({
      ok: false,
      error: 'label "1x" is not an identifier or number',
    });
    body = ok(setNetworkLabel(body, "lamp", "20")).body;
    const dup = ok(duplicateNetwork(body, "seal_in"));
    expect(networksOf(dup.body)[1]!.label).toBeNull();
    body = ok(setNetworkLabel(body, "seal_in", "  ")).body;
    expect(networksOf(body)[0]!.label).toBeNull();
    expect(networksOf(ok(setNetworkComment(body, "lamp", "")).body)[3]!.comment).toBeNull();
  });
});

describe("copy and paste (clipboard JSON)", () => {
  it("round-trips elements and networks through clipboard text and renames clashing ids", () => {
    const text = serializeClip({ kind: "elements", elements: [locate(motorMain, "start_or_motor")!.element] });
    const clip = parseClip(text);
    expect(clip?.kind).toBe("elements");
    if (clip?.kind !== "elements") return;
    const r = ok(pasteElements(motorMain, { series: { kind: "network", network: "lamp" }, index: 0 }, clip.elements));
    expect(show(rung(r.body, 3))).toBe("[Start|Motor] MotorRunning <Blinker> (Lamp)");
    expect(r.select).toEqual(["par1"]);
    const other = ok(
      pasteElements(bodyOf(net("x")), { series: { kind: "network", network: "x" }, index: 0 }, clip.elements),
    );
    expect(ids(other.body)).toEqual(["start_or_motor", "start", "seal"]);
  });

  it("pastes networks after a position", () => {
    const clip = parseClip(serializeClip({ kind: "networks", networks: networksOf(motorMain).slice(0, 2) }));
    if (clip?.kind !== "networks") throw new Error("not a network clip");
    const r = ok(pasteNetworks(motorMain, 4, clip.networks));
    expect(networksOf(r.body)).toHaveLength(6);
    expect(r.select).toEqual(["n1", "n2"]);
  });

  it("ignores foreign or damaged clipboard text", () => {
    expect(parseClip("Motor")).toBeNull();
    expect(
      parseClip('{"format":"ladderlab/ld-clip","kind":"elements","elements":[{"id":"x","type":"lamp"}]}'),
    ).toBeNull();
    expect(parseClip('{"format":"other","kind":"elements","elements":[]}')).toBeNull();
  });
});

// ---- properties: random valid bodies, random edits ----

const anyId = (body: LdBody, pick: number) => {
  const all = ids(body);
  return all.length ? all[pick % all.length]! : "none";
};
/** An element of one type when there is one, else any (so type-specific edits mostly apply). */
const anyOf = (body: LdBody, type: LdElement["type"], pick: number) => {
  const all = [...walk(body)].filter((l) => l.element.type === type).map((l) => l.element.id);
  return all.length ? all[pick % all.length]! : anyId(body, pick);
};
const anySlot = (body: LdBody, pick: number) => {
  const slots = layoutBody(body).networks.flatMap((n) => n.slots);
  return slots.length
    ? slots[pick % slots.length]!.place
    : { series: { kind: "network" as const, network: "none" }, index: 0 };
};
const anyNetwork = (body: LdBody, pick: number) => {
  const ns = networksOf(body);
  return ns.length ? ns[pick % ns.length]!.id : "none";
};
const specs = [contact("nc", "X"), coil("set", "Y"), compare("EQ"), box("TON", "T9"), jump("L1"), ret()];
const subtree = (e: LdElement) => ids({ networks: [{ id: "_", elements: [e] }] });

type Step = { op: number; a: number; b: number; c: number };
const OPS: ((body: LdBody, s: Step) => EditResult)[] = [
  (body, s) =>
    insertNear(body, { element: anyId(body, s.a), side: s.b % 2 ? "after" : "before" }, specs[s.c % specs.length]!),
  (body, s) => insertNear(body, { network: anyNetwork(body, s.a) }, specs[s.c % specs.length]!),
  (body, s) => insertAt(body, anySlot(body, s.a), specs[s.c % specs.length]!),
  (body, s) => wrapInParallel(body, rangeIds(body, anyId(body, s.a), anyId(body, s.b))),
  (body, s) => addBranch(body, anyOf(body, "parallel", s.a)),
  (body, s) => deleteElements(body, rangeIds(body, anyId(body, s.a), anyId(body, s.b))),
  (body, s) => cycleMode(body, anyId(body, s.a)),
  (body, s) => setOperand(body, anyId(body, s.a), { kind: "var" }, "Z"),
  (body, s) => toggleEn(body, anyOf(body, "box", s.a)),
  (body, s) => feedPinFromRail(body, anyOf(body, "box", s.a), "PT"),
  (body, s) => moveElements(body, rangeIds(body, anyId(body, s.a), anyId(body, s.b)), anySlot(body, s.c)),
  (body, s) =>
    pasteElements(
      body,
      anySlot(body, s.c),
      rangeIds(body, anyId(body, s.a), anyId(body, s.b)).map((id) => locate(body, id)!.element),
    ),
  (body, s) => addNetwork(body, s.a % 5),
  (body, s) => deleteNetworks(body, [anyNetwork(body, s.a)]),
  (body, s) => moveNetwork(body, anyNetwork(body, s.a), s.b % 5),
  (body, s) => duplicateNetwork(body, anyNetwork(body, s.a)),
  (body, s) => pasteNetworks(body, s.b % 5, networksOf(body).slice(s.a % 3)),
  (body, s) => setNetworkLabel(body, anyNetwork(body, s.a), ["L1", "L2", "7", "bad label", null][s.b % 5]!),
];
const step = fc.record({ op: fc.nat(OPS.length - 1), a: fc.nat(), b: fc.nat(), c: fc.nat() });

describe("properties", () => {
  it("generated bodies are valid and lay out", () => {
    fc.assert(
      fc.property(ldBody, (body) => {
        expect(ldProblems(body)).toEqual([]);
        expect(layoutBody(body).networks).toHaveLength(networksOf(body).length);
      }),
    );
  });

  it("every edit sequence keeps the model valid and selects existing things", () => {
    fc.assert(
      fc.property(ldBody, fc.array(step, { maxLength: 12 }), (start, steps) => {
        let body = start;
        for (const s of steps) {
          const result = OPS[s.op]!(body, s);
          if (!result.ok) continue;
          expect(ldProblems(result.body)).toEqual([]);
          const known = new Set([...ids(result.body), ...networksOf(result.body).map((n) => n.id)]);
          for (const id of result.select) expect(known.has(id)).toBe(true);
          body = result.body;
        }
      }),
      { numRuns: 150 },
    );
  });

  it("a contact goes right before or after any input element", () => {
    fc.assert(
      fc.property(ldBody, fc.nat(), fc.boolean(), (body, pick, after) => {
        const inputs = [...walk(body)].filter((l) => !isOutput(l.element));
        fc.pre(inputs.length > 0);
        const target = inputs[pick % inputs.length]!;
        const r = ok(insertNear(body, { element: target.element.id, side: after ? "after" : "before" }, contact()));
        const added = locate(r.body, r.select[0]!)!;
        expect(added.series).toEqual(target.series);
        expect(added.index).toBe(target.index + (after ? 1 : 0));
        expect(ids(r.body)).toHaveLength(ids(body).length + 1);
      }),
    );
  });

  it("a coil can always be inserted, and lands among the trailing outputs of a rung or branch", () => {
    fc.assert(
      fc.property(ldBody, fc.nat(), (body, pick) => {
        fc.pre(anyId(body, pick) !== "none");
        const r = ok(insertNear(body, { element: anyId(body, pick), side: "after" }, coil()));
        const added = locate(r.body, r.select[0]!)!;
        expect(added.series.kind).not.toBe("pin");
        const series = seriesAt(r.body, added.series)!;
        expect(series.slice(added.index).every(isOutput)).toBe(true);
      }),
    );
  });

  it("any single element can be wrapped in a parallel and deleted again", () => {
    fc.assert(
      fc.property(ldBody, fc.nat(), (body, pick) => {
        const id = anyId(body, pick);
        fc.pre(id !== "none");
        const wrapped = ok(wrapInParallel(body, [id]));
        expect(ids(wrapped.body)).toHaveLength(ids(body).length + 2);
        const where = locate(wrapped.body, id)!;
        expect(where.series.kind).toBe("branch");
        const back = ok(deleteElements(wrapped.body, wrapped.select));
        expect(show(networksOf(back.body).flatMap((n) => n.elements!))).toBe(
          show(networksOf(body).flatMap((n) => n.elements!)),
        );
      }),
    );
  });

  it("deleting removes exactly the element, its contents and dissolved parallels", () => {
    fc.assert(
      fc.property(ldBody, fc.nat(), (body, pick) => {
        const id = anyId(body, pick);
        fc.pre(id !== "none");
        const r = deleteElements(body, [id]);
        fc.pre(r.ok);
        if (!r.ok) return;
        const gone = new Set(subtree(locate(body, id)!.element));
        const kept = new Set(ids(r.body));
        for (const l of walk(body)) {
          if (gone.has(l.element.id)) expect(kept.has(l.element.id)).toBe(false);
          else if (l.element.type !== "parallel") expect(kept.has(l.element.id)).toBe(true);
        }
      }),
    );
  });

  it("moving keeps every non-parallel element exactly once", () => {
    fc.assert(
      fc.property(ldBody, fc.nat(), fc.nat(), (body, a, slot) => {
        const id = anyId(body, a);
        fc.pre(id !== "none");
        const r = moveElements(body, [id], anySlot(body, slot));
        if (!r.ok) return;
        const leaves = (b: LdBody) =>
          [...walk(b)]
            .filter((l) => l.element.type !== "parallel")
            .map((l) => l.element.id)
            .sort();
        expect(leaves(r.body)).toEqual(leaves(body));
      }),
    );
  });
});
