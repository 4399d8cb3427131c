// @vitest-environment jsdom
import { afterEach, describe, expect, it, vi } from "vitest";
import type { Pou, Reference } from "../generated/api";
import { jsonResponse, stubFetch } from "../test/fetchStub";
import {
  changedParts,
  describeReference,
  globalReferences,
  isEmptyPou,
  renamedPath,
  renamedPous,
  renameMemberEverywhere,
  sessionUses,
} from "./refactor";
import { copyName } from "../iec/identifier";

const pou = (declarations: string, body: Pou["body"], language: Pou["language"] = "st"): Pou => ({
  name: "P",
  kind: "program",
  language,
  declarations,
  body,
});

describe("project operations' pure facts", () => {
  it("knows an empty POU: only empty VAR blocks and comments, no body or networks", () => {
    expect(isEmptyPou(pou("VAR\nEND_VAR", ""))).toBe(true);
    expect(isEmptyPou(pou("VAR_INPUT (* none yet *)\nEND_VAR", "  "))).toBe(true);
    expect(isEmptyPou(pou("VAR\n  x : BOOL;\nEND_VAR", ""))).toBe(false);
    expect(isEmptyPou(pou("VAR\nEND_VAR", "x := 1;"))).toBe(false);
    expect(isEmptyPou(pou("", { networks: [] }, "ld"))).toBe(true);
    expect(isEmptyPou(pou("", { networks: [{ id: "n1", elements: [] }] }, "ld"))).toBe(false);
  });

  it("renames the first part of a watch path only, in any case", () => {
    expect(renamedPath("MAIN.b.Q", "Main", "Plant")).toBe("Plant.b.Q");
    expect(renamedPath("Other.Main", "Main", "Plant")).toBe("Other.Main");
    expect(renamedPath("MainX.a", "Main", "Plant")).toBe("MainX.a");
    expect(renamedPath("arr[2].x", "Arr", "Table")).toBe("Table[2].x");
    expect(renamedPath("%IX0.0", "IX0", "Y")).toBe("%IX0.0");
  });

  it("names the next free copy", () => {
    expect(copyName(["P", "p_COPY"], "P")).toBe("P_copy2");
    expect(copyName([], "P")).toBe("P_copy");
  });

  it("says where a reference is in the tree's words", () => {
    expect(
      describeReference({ part: "network", pou: "Lad", network_number: 2, network_label: "Timer", text: "" }),
    ).toBe('Lad, network 2 "Timer"');
    expect(describeReference({ part: "declarations", pou: "Main", line: 3, text: "" })).toBe(
      "Main, declarations line 3",
    );
    expect(describeReference({ part: "task", task: "Fast", text: "Main" })).toBe("task Fast");
    expect(describeReference({ part: "panel", panel: "Operator", element: "run_lamp", text: "Go" })).toBe(
      "panel Operator, widget run_lamp",
    );
    expect(describeReference({ part: "watch", text: "Go" })).toBe("Watch list");
    expect(describeReference({ part: "trace", text: "Go" })).toBe("Trace");
    // issue 25: a function block's EXTENDS / IMPLEMENTS and the texts of its methods and properties
    expect(describeReference({ part: "extends", pou: "Square", text: "EXTENDS Base" })).toBe("Square");
    expect(describeReference({ part: "body", pou: "Square", member: "Area", line: 4, text: "" })).toBe(
      "Square.Area, body line 4",
    );
    expect(describeReference({ part: "return type", pou: "Square", member: "Form", text: "Shape" })).toBe(
      "Square.Form, type",
    );
  });
});

describe("the parts a rename marks unsaved (issue 22 item 1)", () => {
  it("names the globals, types, tasks and test files a rename changed, once each; POUs are named elsewhere", () => {
    expect(
      changedParts([
        { part: "globals", line: 2, text: "Go : BOOL;" },
        { part: "declarations", pou: "Main", line: 1, text: "x" },
        { part: "task", task: "Fast", text: "Go" },
        { part: "task", task: "Slow", text: "Go" },
        { part: "types", line: 3, text: "T" },
        { part: "test", file: "tests/t.st", line: 1, text: "Go" },
        { part: "panel", panel: "Operator", element: "lamp", text: "Go" },
      ]),
    ).toEqual(["part:globals", "part:tasks", "part:types", "tests/t.st", "panel Operator"]);
  });
});

describe("what uses a global variable (issue 22 item 1: its delete lists them)", () => {
  afterEach(() => vi.unstubAllGlobals());

  it("is every place the server finds but the global's own declaration, asked of the working copy", async () => {
    const project = { name: "p", globals: "VAR_GLOBAL\n    Go : BOOL;\n    Run : BOOL := Go;\nEND_VAR" };
    const found: Reference[] = [
      { part: "globals", line: 2, text: "Go : BOOL;" },
      { part: "globals", line: 3, text: "Run : BOOL := Go;" },
      { part: "network", pou: "Lad", network_number: 1, element: "c1", text: "Go" },
      { part: "panel", panel: "Operator", element: "start", text: "Go" },
    ];
    const { sent } = stubFetch(() => jsonResponse({ references: found }));
    expect(await globalReferences(project, "go")).toEqual(found.slice(1));
    expect(sent.map((r) => [r.method, r.path])).toEqual([["POST", "/api/refactor/references"]]);
    expect(JSON.parse(sent[0]!.body)).toEqual({ project, name: "go" });
  });

  it("includes the watch list rows and traced variables that start with it, not those of a longer name", () => {
    expect(sessionUses("Go", ["go", "Main.Go", "GoFast", "Go.x"], ["GO", "Level"], "go")).toEqual([
      { part: "watch", text: "go" },
      { part: "watch", text: "Go.x" },
      { part: "trace", text: "GO" },
      { part: "trigger", text: "go" },
    ]);
    expect(sessionUses("Go", [], [], "")).toEqual([]);
    expect(describeReference({ part: "trigger", text: "Go" })).toBe("Trace trigger");
  });
});

describe("a method renamed with its calls (issue 25 item 5)", () => {
  afterEach(() => vi.unstubAllGlobals());

  it("asks the server's member rename for the working copy and lists the declaration by its function block", async () => {
    const project = { name: "p" };
    const answer = { project, changes: [{ part: "method", pou: "Counter", member: "Old", text: "METHOD Old" }] };
    const { sent } = stubFetch(() => jsonResponse(answer));
    expect(await renameMemberEverywhere(project, "Counter", "Old", "Bump")).toEqual(answer);
    expect(sent.map((r) => [r.method, r.path])).toEqual([["POST", "/api/refactor/rename-member"]]);
    expect(JSON.parse(sent[0]!.body)).toEqual({ project, pou: "Counter", old_name: "Old", new_name: "Bump" });
    expect(describeReference({ part: "method", pou: "Counter", member: "Old", text: "METHOD Old" })).toBe("Counter");
  });

  it("moves the breakpoints of the method and its overrides (engine POUs F.M), or of a renamed POU", () => {
    const changes: Reference[] = [
      { part: "method", pou: "Counter", member: "Old", text: "METHOD Old" },
      { part: "body", pou: "Counter", member: "Twice", line: 1, text: "Old();" },
      { part: "method", pou: "Fast", member: "old", text: "METHOD old" },
      { part: "method", pou: "Tank", member: "Old", text: "PROPERTY Old" },
    ];
    expect(renamedPous("Old", "Bump", false, changes)).toEqual([
      ["Counter.Old", "Counter.Bump"],
      ["Fast.old", "Fast.Bump"],
    ]);
    expect(renamedPous("Main", "Plant", true, [])).toEqual([["Main", "Plant"]]);
    expect(renamedPous("Speed", "Velocity", false, [{ part: "globals", line: 2, text: "Speed : INT;" }])).toEqual([]);
  });
});
