// @vitest-environment jsdom
import { describe, expect, it } from "vitest";
import type { ClientMessage } from "../online/protocol";
import type { Project } from "../generated/api";
import { goneBecause, movedLine, renamedPou } from "./follow";
import { createDebugStore } from "../debug/store";

const project: Project = {
  name: "p",
  pous: [
    { name: "Main", kind: "program", language: "st", declarations: "", body: "a := 1;\nb := 2;\nc := 3;" },
    {
      name: "Lad",
      kind: "program",
      language: "ld",
      declarations: "",
      body: {
        networks: [
          { id: "n1", elements: [{ type: "coil", id: "q1", var: "x" }] },
          { id: "n2", elements: [] },
        ],
      },
    },
  ],
} as Project;

describe("breakpoints follow what they are on (issue 22)", () => {
  it("take a renamed POU's new name, case-insensitively, and leave others", () => {
    expect(renamedPou({ pou: "MAIN", line: 2 }, "Main", "Plant")).toEqual({ pou: "Plant", line: 2 });
    expect(renamedPou({ pou: "Lad", network: "n1" }, "Main", "Plant")).toEqual({ pou: "Lad", network: "n1" });
  });

  it("move an ST line breakpoint of that POU's own text only", () => {
    const down = (line: number) => (line === 2 ? null : line + 1);
    expect(movedLine({ pou: "Main", line: 3 }, "main", down)).toEqual({ pou: "Main", line: 4 });
    expect(movedLine({ pou: "Main", line: 2 }, "Main", down)).toBeNull();
    expect(movedLine({ pou: "Main", body: "actions/A", line: 3 }, "Main", down)).toEqual({
      pou: "Main",
      body: "actions/A",
      line: 3,
    });
    expect(movedLine({ pou: "Lad", network: "n1" }, "Lad", down)).toEqual({ pou: "Lad", network: "n1" });
  });

  it("say why a breakpoint points at nothing, naming the network as the user last saw it", () => {
    expect(goneBecause({ pou: "Main", line: 3 }, project)).toBeNull();
    expect(goneBecause({ pou: "Lad", element: "q1" }, project)).toBeNull();
    expect(goneBecause({ pou: "Main", line: 4 }, project)).toBe(
      "The breakpoint at Main, line 4 was removed: Main has no line 4 any more.",
    );
    expect(goneBecause({ pou: "Gone", line: 1 }, project)).toBe(
      "The breakpoint at Gone, line 1 was removed: there is no POU Gone any more.",
    );
    const lad = project.pous![1]!;
    const without = {
      ...project,
      pous: [project.pous![0]!, { ...lad, body: { networks: [{ id: "n1", elements: [] }] } }],
    };
    expect(goneBecause({ pou: "Lad", network: "n2" }, without as Project, project)).toBe(
      "The breakpoint at Lad, network 2 was removed: its network was deleted.",
    );
    expect(goneBecause({ pou: "Lad", element: "q1" }, without as Project)).toBe(
      "The breakpoint at Lad, element q1 was removed: its element was deleted.",
    );
    expect(goneBecause({ pou: "Lad", element: "q1" }, without as Project, project)).toBe(
      "The breakpoint at Lad, element q1 (coil x) was removed: its element was deleted.",
    );
  });

  it("the store moves them, keeps each one's enabled state, drops the gone ones with a notice and tells the simulation", () => {
    const sent: ClientMessage[] = [];
    const store = createDebugStore((m) => (sent.push(m), true));
    const s = () => store.getState();
    s().toggle({ pou: "Main", line: 2 });
    s().toggle({ pou: "Main", line: 3 });
    s().toggle({ pou: "Lad", network: "n1" });
    s().setEnabled({ pou: "Main", line: 3 }, false);
    sent.length = 0;
    s().follow(
      (bp) => movedLine(bp, "Main", (line) => (line === 2 ? null : line + 5)),
      () => "line 2 was deleted.",
    );
    expect(s().breakpoints).toEqual([
      { pou: "Main", line: 8 },
      { pou: "Lad", network: "n1" },
    ]);
    expect(s().disabled).toEqual(["MAIN|line:8"]);
    expect(s().notice).toBe("line 2 was deleted.");
    // the enabled one that was dropped is cleared; the disabled one that moved was never in the simulation
    expect(sent).toEqual([{ type: "breakpoint_clear", pou: "Main", line: 2 }]);
    sent.length = 0;
    s().follow(
      (bp) => renamedPou(bp, "Lad", "Ladder"),
      () => "",
    );
    expect(s().breakpoints).toEqual([
      { pou: "Main", line: 8 },
      { pou: "Ladder", network: "n1" },
    ]);
    expect(sent).toEqual([
      { type: "breakpoint_clear", pou: "Lad", network: "n1" },
      { type: "breakpoint_set", pou: "Ladder", network: "n1" },
    ]);
  });
});
