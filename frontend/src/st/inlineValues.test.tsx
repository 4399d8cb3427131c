import { EditorView } from "@codemirror/view";
import { act, fireEvent, render } from "@testing-library/react";
import { describe, expect, it, vi } from "vitest";
import type { LibraryEntry, SymbolInfo } from "../generated/api";
import { describe as describeOccurrence, inlineMarks, variableOccurrences, type Occurrence } from "./inlineValues";
import { structTypes, type Scope } from "./members";
import { StEditor } from "./StEditor";

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
const symbol = (name: string, type: string, var_class = "VAR"): SymbolInfo => ({
  name,
  type,
  var_class,
  initial: null,
  address: null,
  comment: null,
  retain: false,
  constant: false,
});
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
  it("finds each variable with a value, as a path of the instance; skips FBs, arrays, formal names, comments and strings", () => {
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
      // the third "Count" is in a comment; the fourth is an array index
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

describe("inline value marks", () => {
  const occurrences = variableOccurrences("IF Start THEN Count := Count + 1; END_IF; x := T1.ET;", scope, "MAIN");

  it("puts each value after its occurrence, BOOLs as TRUE/FALSE with their state, forced ones marked", () => {
    const values = { "MAIN.START": true, "MAIN.COUNT": 42 };
    expect(inlineMarks(occurrences, values, new Set(["MAIN.COUNT"]))).toEqual([
      { pos: 8, text: "TRUE", bool: true, forced: false },
      { pos: 19, text: "42", bool: null, forced: true },
      { pos: 28, text: "42", bool: null, forced: true },
    ]);
  });

  it("shows nothing for paths the monitor has not sent yet", () => {
    expect(inlineMarks(occurrences, {}, new Set())).toEqual([]);
  });

  it("describes an occurrence with type, value and force on hover", () => {
    expect(describeOccurrence(occurrences[3]!, { "MAIN.T1.ET": 250 }, new Set(["MAIN.T1.ET"]))).toBe(
      "T1.ET : TIME = T#250ms (forced)",
    );
    expect(describeOccurrence(occurrences[0]!, {}, new Set())).toBe("Start : BOOL = …");
  });
});

describe("StEditor online (issue 9: values inline, right-click commands)", () => {
  it("shows the marks as widgets after the variables and opens the menu on a variable", () => {
    const text = "Count := Count + 1;";
    const occurrences = variableOccurrences(text, scope, "MAIN");
    const onMenu = vi.fn();
    const online = (values: Record<string, number>) => ({
      occurrences,
      marks: inlineMarks(occurrences, values, new Set<string>()),
      describe: () => "",
      onMenu,
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
    rerender(<StEditor {...props} />);
    expect(shown()).toEqual([]);
  });
});
