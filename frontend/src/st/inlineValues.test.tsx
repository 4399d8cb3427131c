// @vitest-environment jsdom
import { EditorView } from "@codemirror/view";
import { act, fireEvent, render } from "@testing-library/react";
import { describe, expect, it, vi } from "vitest";
import type { LibraryEntry } from "../generated/api";
import { emptyMonitor } from "../online/monitor";
import type { Value } from "../online/protocol";
import {
  concretePath,
  describe as describeOccurrence,
  inlineMarks,
  variableOccurrences,
  type InlineMark,
  type Occurrence,
} from "./inlineValues";
import { structTypes, type Scope } from "./members";
import { StEditor } from "./StEditor";
import { symbol } from "../test/symbols";

const pin = (name: string, type: string) => ({ name, type });
const TON: LibraryEntry = {
  name: "TON",
  kind: "function_block",
  source: "standard",
  comment: null,
  extensible: false,
  inputs: [pin("IN", "BOOL"), pin("PT", "TIME")],
  in_outs: [],
  outputs: [pin("Q", "BOOL"), pin("ET", "TIME")],
  return_type: null,
};
const scope: Scope = {
  symbols: [
    symbol("Start", "BOOL"),
    symbol("Count", "INT"),
    symbol("T1", "TON"),
    symbol("p", "Point"),
    symbol("arr", "ARRAY[1..3] OF INT"),
    symbol("Alarm", "BOOL", "VAR_GLOBAL"),
  ],
  library: [TON],
  structs: structTypes("TYPE Point : STRUCT x : INT; END_STRUCT; END_TYPE"),
};

const BODY = `(* Start counts *)
T1(IN := Start, PT := T#1s);
IF T1.Q AND NOT Alarm THEN
    Count := Count + p.x; // Count
    arr[Count] := 'Start';
END_IF;`;

const at = (o: Occurrence) => `${o.text}@${o.from}-${o.to} ${o.path} ${o.type}`;

describe("variable occurrences (issue 9: ST online values inline)", () => {
  it("shows an instance's property with {attribute 'monitoring'}, not one without (issue 25)", () => {
    const tank: LibraryEntry = { ...TON, name: "Tank", source: "user", inputs: [], outputs: [] };
    const level = { name: "Level", type: "INT", kind: "PROPERTY", monitored: true };
    const hidden = { name: "Hidden", type: "INT", kind: "PROPERTY" };
    const withTank: Scope = {
      ...scope,
      symbols: [symbol("t", "Tank"), symbol("x", "INT")],
      library: [tank],
      extras: new Map([["TANK", [level, hidden]]]),
    };
    expect(variableOccurrences("x := t.Level + t.Hidden;", withTank, "MAIN").map(at)).toEqual([
      "x@0-1 MAIN.X INT",
      "t.Level@5-12 MAIN.T.LEVEL INT",
    ]);
  });

  it("shows a monitored property named bare or through THIS^ in its function block's own code (issue 25)", () => {
    const self = {
      name: "THIS^",
      kind: "THIS^",
      methodsOf: null,
      members: [
        { name: "amount", type: "INT", kind: "VAR" },
        { name: "Level", type: "INT", kind: "PROPERTY", monitored: true },
        { name: "Hidden", type: "INT", kind: "PROPERTY" },
      ],
    };
    const own: Scope = { ...scope, symbols: [symbol("amount", "INT")], qualifiers: new Map([["THIS^", self]]) };
    expect(variableOccurrences("amount := Level + THIS^.Level + Hidden;", own, "MAIN.T").map(at)).toEqual([
      "amount@0-6 MAIN.T.AMOUNT INT",
      "Level@10-15 MAIN.T.LEVEL INT",
      "THIS^.Level@18-29 MAIN.T.LEVEL INT",
    ]);
  });

  it("shows a variable named like an SFC word (OSCAT's step) outside an SFC body", () => {
    const named: Scope = { ...scope, symbols: [symbol("step", "INT"), symbol("Action", "BOOL")] };
    const text = "Step := step + 1;\nIF Action THEN step := 0; END_IF;";
    expect(variableOccurrences(text, named, "MAIN").map(at)).toEqual([
      "Step@0-4 MAIN.STEP INT",
      "step@8-12 MAIN.STEP INT",
      "Action@21-27 MAIN.ACTION BOOL",
      "step@33-37 MAIN.STEP INT",
    ]);
  });

  it("finds each variable with a value, as a path of the instance; skips FBs, whole arrays, formal names, comments and strings", () => {
    const found = variableOccurrences(BODY, scope, "MAIN");
    const offset = (needle: string, nth = 0) =>
      BODY.split(needle)
        .slice(0, nth + 1)
        .join(needle).length;
    expect(found.map(at)).toEqual([
      `Start@${offset("Start", 1)}-${offset("Start", 1) + 5} MAIN.START BOOL`,
      `T1.Q@${offset("T1.Q")}-${offset("T1.Q") + 4} MAIN.T1.Q BOOL`,
      `Alarm@${offset("Alarm")}-${offset("Alarm") + 5} ALARM BOOL`,
      `Count@${offset("Count", 0)}-${offset("Count", 0) + 5} MAIN.COUNT INT`,
      `Count@${offset("Count", 1)}-${offset("Count", 1) + 5} MAIN.COUNT INT`,
      `p.x@${offset("p.x")}-${offset("p.x") + 3} MAIN.P.X INT`,
      // the third "Count" is in a comment; the fourth is an array index: the element has a value (ON-12), so has Count
      `arr[Count]@${offset("arr")}-${offset("arr") + 10} MAIN.ARR INT`,
      `Count@${offset("Count", 3)}-${offset("Count", 3) + 5} MAIN.COUNT INT`,
    ]);
  });

  it("names paths of the chosen FB instance", () => {
    expect(variableOccurrences("Count := Count + 1;", scope, "MAIN.COUNTER1").map((o) => o.path)).toEqual([
      "MAIN.COUNTER1.COUNT",
      "MAIN.COUNTER1.COUNT",
    ]);
  });
});

const monitorOf = (values: Record<string, Value>, forced: string[] = []) => ({
  ...emptyMonitor,
  values,
  forced: new Set(forced),
});

describe("inline value marks", () => {
  const occurrences = variableOccurrences("IF Start THEN Count := Count + 1; END_IF; x := T1.ET;", scope, "MAIN");
  const text = (marks: InlineMark[]) => marks.map((m) => [m.pos, m.shown.text, m.shown.bool, m.shown.forced]);

  it("puts each value after its occurrence, BOOLs as TRUE/FALSE with their state, forced ones marked", () => {
    const monitor = monitorOf({ "MAIN.START": true, "MAIN.COUNT": 42 }, ["MAIN.COUNT"]);
    expect(text(inlineMarks(occurrences, monitor))).toEqual([
      [8, "TRUE", true, false],
      [19, "42", null, true],
      [28, "42", null, true],
    ]);
    expect(inlineMarks(occurrences, monitor, { "MAIN.START": false })[0]!.shown.prepared).toBe("FALSE");
  });

  it("shows nothing for paths the monitor has not sent yet", () => {
    expect(inlineMarks(occurrences, monitorOf({}))).toEqual([]);
  });

  it("describes an occurrence with type, value and force on hover", () => {
    expect(describeOccurrence(occurrences[3]!, monitorOf({ "MAIN.T1.ET": 250 }, ["MAIN.T1.ET"]))).toBe(
      "T1.ET : TIME = T#250ms (forced)",
    );
    expect(describeOccurrence(occurrences[0]!, monitorOf({}), { "MAIN.START": true })).toBe("Start : BOOL = …");
    expect(describeOccurrence(occurrences[0]!, monitorOf({ "MAIN.START": false }), { "MAIN.START": true })).toBe(
      "Start : BOOL = FALSE, prepared TRUE",
    );
  });
});

describe("array elements inline (ON-12: a[i] shows its value, a[i + 1] none)", () => {
  const text = "x := arr[Count] + arr[2] + arr[Count + 1] + grid[Count, 0];";
  const withGrid: Scope = { ...scope, symbols: [...scope.symbols, symbol("grid", "ARRAY [1..2, 0..1] OF REAL")] };
  const found = variableOccurrences(text, withGrid, "MAIN");

  it("names an element whose indices are variables or numbers; an expression index is left alone", () => {
    expect(found.filter((o) => o.element).map((o) => [o.text, o.path, o.type])).toEqual([
      ["arr[Count]", "MAIN.ARR", "INT"],
      ["arr[2]", "MAIN.ARR", "INT"],
      ["grid[Count, 0]", "MAIN.GRID", "REAL"],
    ]);
  });

  it("picks the element the index names now from the array's value", () => {
    const monitor = monitorOf({
      "MAIN.ARR": [10, 20, 30],
      "MAIN.COUNT": 3,
      "MAIN.GRID": [
        [0.5, 1],
        [2, Math.fround(2.2)],
      ],
    });
    const shown = inlineMarks(found, monitor).map((m) => [text.slice(0, m.pos).split(" ").at(-1), m.shown.text]);
    expect(shown).toEqual([
      ["arr[Count]", "30"],
      ["arr[Count", "3"], // the index variable's own value
      ["arr[2]", "20"],
      ["arr[Count", "3"], // in arr[Count + 1] only Count has a value
      ["grid[Count", "3"],
    ]); // grid[3, 0] is outside the array: no value
    expect(
      concretePath(
        found.find((o) => o.text === "arr[Count]")!,
        monitor.values,
      ),
    ).toBe("MAIN.ARR[3]");
    const grid = found.find((o) => o.text === "grid[Count, 0]")!;
    const later = monitorOf({ ...monitor.values, "MAIN.COUNT": 2 }, ["MAIN.GRID[2, 1]"]);
    expect(inlineMarks([grid], later).map((m) => m.shown.text)).toEqual(["2.0"]); // a REAL, as the engine writes it;
    expect(inlineMarks([grid], monitorOf({ ...later.values, "MAIN.COUNT": 2 })).length).toBe(1);
  });

  it("marks an element forced when its own path is", () => {
    const monitor = monitorOf({ "MAIN.ARR": [10, 20, 30], "MAIN.COUNT": 1 }, ["MAIN.ARR[1]"]);
    const element = found.find((o) => o.text === "arr[Count]")!;
    expect(inlineMarks([element], monitor)[0]!.shown).toMatchObject({ text: "10", forced: true });
  });
});

describe("pointers and parts inline (ON-11, issue 25)", () => {
  const withParts: Scope = {
    ...scope,
    symbols: [
      ...scope.symbols,
      symbol("w", "WORD"),
      symbol("k", "INT"),
      symbol("r", "REAL"),
      symbol("x", "INT"),
      symbol("a", "ARRAY [1..3] OF INT"),
      symbol("ptr", "POINTER TO INT"),
      symbol("rp", "REF_TO Point"),
    ],
  };
  const shown = (text: string, values: Record<string, Value>) =>
    inlineMarks(variableOccurrences(text, withParts, "MAIN"), monitorOf(values)).map((m) => [
      text.slice(0, m.pos),
      m.shown.text,
    ]);

  it("shows a pointer's own value as the monitor sends it: the ADR() it holds, or NULL", () => {
    const text = "ptr := ADR(a[2]);\nx := ptr^ + rp^.x;";
    expect(variableOccurrences(text, withParts, "MAIN").map((o) => [o.text, o.path, o.type])).toEqual([
      ["ptr", "MAIN.PTR", "POINTER TO INT"],
      ["a[2]", "MAIN.A", "INT"], // the element pointed to (ON-12)
      ["x", "MAIN.X", "INT"],
      ["ptr", "MAIN.PTR", "POINTER TO INT"],
      ["rp", "MAIN.RP", "REF_TO Point"], // rp^.x's x is a member of what rp points to, not the variable x
    ]);
    expect(shown("ptr := ADR(a[2]);", { "MAIN.PTR": "ADR(a[2])" })).toEqual([["ptr", "ADR(a[2])"]]);
    expect(shown("ptr := ADR(a[2]);", { "MAIN.PTR": "NULL" })).toEqual([["ptr", "NULL"]]);
  });

  it("names a bit or part of an integer or bit string as a path of its own, with the part's type", () => {
    const text = "x := w.%X3; k.%B1 := 16#7F; IF w.15 AND k.%X15 THEN w.%W0 := 0; END_IF; y := r.1; z := w.%B2;";
    expect(variableOccurrences(text, withParts, "MAIN").map((o) => [o.text, o.path, o.type])).toEqual([
      ["x", "MAIN.X", "INT"],
      ["w.%X3", "MAIN.W.%X3", "BOOL"],
      ["k.%B1", "MAIN.K.%B1", "BYTE"],
      ["w.15", "MAIN.W.%X15", "BOOL"], // the short form names bit 15
      ["k.%X15", "MAIN.K.%X15", "BOOL"],
      ["w.%W0", "MAIN.W.%W0", "WORD"],
      ["r", "MAIN.R", "REAL"], // a REAL has no parts: r alone
      ["w", "MAIN.W", "WORD"], // %B2 lies outside a WORD: the checker says so, w alone shows its value
    ]);
    expect(shown("IF w.%X3 THEN k.%B1 := 1; END_IF;", { "MAIN.W.%X3": true, "MAIN.K.%B1": 255 })).toEqual([
      ["IF w.%X3", "TRUE"],
      ["IF w.%X3 THEN k.%B1", "255"],
    ]);
  });
});

describe("StEditor online (issue 9: values inline, right-click commands)", () => {
  it("shows the marks as widgets after the variables and opens the menu on a variable", () => {
    const text = "Count := Count + 1;";
    const occurrences = variableOccurrences(text, scope, "MAIN");
    const onMenu = vi.fn();
    const onPrepare = vi.fn();
    const online = (values: Record<string, number>) => ({
      occurrences,
      marks: inlineMarks(occurrences, monitorOf(values)),
      describe: () => "",
      onMenu,
      onPrepare,
    });
    const props = {
      text,
      onChange: vi.fn(),
      file: "Main/body",
      diagnostics: [],
      completions: { options: [], members: () => null },
      readOnly: "Online",
      label: "Main body",
    };
    const { container, rerender } = render(<StEditor {...props} online={online({ "MAIN.COUNT": 7 })} />);
    const shown = () => [...container.querySelectorAll(".cm-st-value")].map((e) => e.textContent);
    expect(shown()).toEqual(["7", "7"]);
    expect(container.querySelector(".cm-line")!.textContent).toBe("Count7 := Count7 + 1;");
    rerender(<StEditor {...props} online={online({ "MAIN.COUNT": 8 })} />);
    expect(shown()).toEqual(["8", "8"]);
    const view = EditorView.findFromDOM(container.querySelector(".cm-editor") as HTMLElement)!;
    view.posAtCoords = () => 11;
    act(() => void fireEvent.contextMenu(view.contentDOM, { clientX: 30, clientY: 5 }));
    expect(onMenu).toHaveBeenCalledWith(occurrences[1], 30, 5);
    act(() => void fireEvent.dblClick(container.querySelectorAll(".cm-st-value")[0]!));
    expect(onPrepare).toHaveBeenCalledWith(occurrences[0]); // a double-click on a value prepares one
    rerender(<StEditor {...props} />);
    expect(shown()).toEqual([]);
  });
});
