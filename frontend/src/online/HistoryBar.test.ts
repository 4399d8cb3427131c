import { describe, expect, it } from "vitest";
import { findPlaceholder, markClass, markOffset, shownScan, stepScan, steppingKey, steppingText } from "./HistoryBar";
import { applyMessage, emptyMonitor, haltedAt } from "./monitor";

describe("scan history in the monitor state (issue 23)", () => {
  it("takes the history range of every values message, and null when a message has none", () => {
    const viewing = applyMessage(emptyMonitor, {
      type: "values",
      scan: 3,
      time_ms: 30,
      changed: { "MAIN.COUNT": 3 },
      forced: [],
      power: {},
      history: { first: 1, last: 10, viewing: 3, bytes: 100, budget_bytes: 1000 },
    });
    expect(viewing.history).toEqual({ first: 1, last: 10, viewing: 3, bytes: 100, budget_bytes: 1000 });
    expect(viewing.scan).toBe(3);
    const none = applyMessage(viewing, { type: "values", scan: 11, time_ms: 110, changed: {}, forced: [], power: {} });
    expect(none.history).toBeNull();
  });

  it("shows the scan viewed, else the live one, and steps within the range only", () => {
    expect(shownScan({ last: 10, viewing: null })).toBe(10);
    expect(shownScan({ last: 10, viewing: 4 })).toBe(4);
    expect(stepScan({ first: 1, last: 10 }, 4, -1)).toBe(3);
    expect(stepScan({ first: 1, last: 10 }, 1, -1)).toBeNull();
    expect(stepScan({ first: 1, last: 10 }, 10, 1)).toBeNull();
    expect(stepScan({ first: 1, last: 10 }, 9, 1)).toBe(10);
  });

  it("places a mark along the slider by its scan", () => {
    expect(markOffset(1, 1, 11)).toBe(0);
    expect(markOffset(6, 1, 11)).toBe(50);
    expect(markOffset(11, 1, 11)).toBe(100);
    expect(markOffset(3, 3, 3)).toBe(0);
  });

  it("colours a mark by the most telling thing in its scan: an error, a breakpoint hit, a trace trigger, an input", () => {
    expect(markClass(["error", "trigger", "write"])).toBe("history-mark error");
    expect(markClass(["breakpoint", "trigger"])).toBe("history-mark breakpoint");
    expect(markClass(["trigger", "write"])).toBe("history-mark trigger");
    expect(markClass(["force", "write"])).toBe("history-mark");
  });

  it("suggests the first watched variable in the find field, a generic hint when nothing is watched", () => {
    expect(findPlaceholder("changed", "Main.Motor")).toBe("Main.Motor");
    expect(findPlaceholder("true", "Main.Motor")).toBe("a condition, e.g. on Main.Motor");
    expect(findPlaceholder("changed", undefined)).toBe("a variable, e.g. Main.Motor");
  });
});

describe("stepping through a past scan (issue 23)", () => {
  const at = { pou: "MAIN", network: "2" };
  const live = { pou: "MAIN", line: 7 };
  const history = { first: 1, last: 9, viewing: 4 };

  it("marks the step's point while one runs, the live halt otherwise", () => {
    expect(haltedAt({ state: "halted", at: live, history: { ...history, stepping: { at } } })).toBe(at);
    expect(haltedAt({ state: "halted", at: live, history: { ...history, stepping: { at: null } } })).toBeNull();
    expect(haltedAt({ state: "halted", at: live, history })).toBe(live);
    expect(haltedAt({ state: "running", at: live, history: null })).toBeNull();
  });

  it("says where the step stands", () => {
    expect(steppingText(4, null, null)).toBe(
      "Step through scan 4: network by network (LD, FBD), line by line (ST, IL)",
    );
    expect(steppingText(4, { at }, "MAIN, network 2")).toBe("Scan 4, halted before MAIN, network 2");
    expect(steppingText(4, { at: null }, null)).toBe("Scan 4 ran to its end");
  });

  it("steps forth with → (into the scan first) and back with ← while stepping", () => {
    expect(steppingKey("ArrowRight", false, false)).toBe("statement");
    expect(steppingKey("ArrowRight", true, false)).toBe("statement");
    expect(steppingKey("ArrowRight", true, true)).toBeNull(); // the scan ran to its end
    expect(steppingKey("ArrowLeft", true, true)).toBe("back");
    expect(steppingKey("ArrowLeft", false, false)).toBeNull(); // not stepping: the slider's ← steps one scan
    expect(steppingKey("Enter", true, false)).toBeNull();
  });
});
