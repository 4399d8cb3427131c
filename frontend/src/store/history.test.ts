import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { canRedo, canUndo, historyOf, HISTORY_LIMIT, record, redo, undo } from "./history";

describe("history", () => {
  it("undoes and redoes in order and drops the redo steps on a new edit", () => {
    let h = historyOf("a");
    h = record(h, "b");
    h = record(h, "c");
    expect([canUndo(h), canRedo(h)]).toEqual([true, false]);
    h = undo(h);
    expect(h.present).toBe("b");
    h = undo(h);
    expect(h.present).toBe("a");
    expect(canUndo(h)).toBe(false);
    expect(undo(h)).toBe(h);
    h = redo(h);
    expect(h.present).toBe("b");
    h = record(h, "x");
    expect([h.present, canRedo(h)]).toEqual(["x", false]);
    expect(redo(h)).toBe(h);
  });

  it("ignores a step that changes nothing", () => {
    const h = historyOf({ v: 1 });
    expect(record(h, h.present)).toBe(h);
  });

  it(`keeps the last ${HISTORY_LIMIT} steps (at least 100, issue 7)`, () => {
    let h = historyOf(0);
    for (let i = 1; i <= 250; i += 1) h = record(h, i);
    let undone = 0;
    while (canUndo(h)) {
      h = undo(h);
      undone += 1;
    }
    expect(undone).toBe(HISTORY_LIMIT);
    expect(HISTORY_LIMIT).toBeGreaterThanOrEqual(100);
    expect(h.present).toBe(250 - HISTORY_LIMIT);
  });

  it("undoing everything returns the first state, redoing everything the last", () => {
    fc.assert(
      fc.property(fc.array(fc.integer(), { minLength: 1, maxLength: 150 }), (values) => {
        let h = historyOf<number | string>("start");
        for (const v of values) h = record(h, v);
        const last = h.present;
        while (canUndo(h)) h = undo(h);
        expect(h.present).toBe("start");
        while (canRedo(h)) h = redo(h);
        expect(h.present).toBe(last);
      }),
    );
  });
});
