import { describe, expect, it } from "vitest";
import type { CallFrame } from "../generated/monitor";
import { callView } from "./callValues";

const call: CallFrame = {
  kind: "method",
  at: { pou: "MOTOR.START", instance: "MAIN.M", line: 2 },
  variables: [
    { name: "N", kind: "input", type: { name: "INT" }, value: 7 },
    { name: "T", kind: "var", type: { name: "TIME" }, value: 1500 },
    { name: "ARR", kind: "var", type: { name: "ARRAY" }, value: [1, 2, 3] },
    { name: "OK", kind: "output", type: { name: "BOOL" }, value: true },
    { name: "LOST", kind: "temp", type: { name: "INT" }, reason: "not held in the call's frame" },
    { name: "START", kind: "result", type: { name: "INT" }, value: 0 },
  ],
};

describe("a halted call's own variables inline", () => {
  it("shows each bare occurrence's value as every online value is shown, and no member, call or formal", () => {
    const text = "Start := n + inst.n + Other(n := t);\nok := arr[1] > 0 AND lost > 0;";
    const view = callView(text, call);
    const shown = view.marks.map((m) => [text.slice(0, m.pos).split(/\W/).pop(), m.shown.text, m.shown.bool]);
    expect(shown).toEqual([
      ["Start", "0", null],
      ["n", "7", null],
      ["t", "T#1s500ms", null],
      ["ok", "TRUE", true],
    ]);
    // hover: the value and what the variable is; an unreadable one says why it shows none
    const occurrence = (name: string) => view.occurrences.find((o) => o.text === name)!;
    expect(view.describe(occurrence("t"))).toBe("t : TIME = T#1s500ms (this call's variable)");
    expect(view.describe(occurrence("lost"))).toBe("lost : INT: no value (not held in the call's frame)");
    expect(view.occurrences.map((o) => o.text)).toEqual(["Start", "n", "t", "ok", "lost"]); // no `arr`: no value
  });
});
