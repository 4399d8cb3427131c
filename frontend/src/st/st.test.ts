// @vitest-environment jsdom
import { StringStream } from "@codemirror/language";
import { Text } from "@codemirror/state";
import { CompletionContext } from "@codemirror/autocomplete";
import { EditorState } from "@codemirror/state";
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import type { Diagnostic, LibraryEntry } from "../generated/api";
import { callTemplate, stCompletionSource, stCompletions } from "./completion";
import { stParser, type StState } from "./language";
import { lintDiagnostics } from "./lint";
import { linesIn } from "./breakpoints";
import { plainSymbol } from "../store/project";

/** [text, style] tokens of each line, carrying the parser state across lines as CodeMirror does. */
function tokens(text: string): [string, string | null][][] {
  const state: StState = stParser.startState!(2);
  return text.split("\n").map((line) => {
    const out: [string, string | null][] = [];
    const stream = new StringStream(line, 2, 2);
    while (!stream.eol()) {
      stream.start = stream.pos;
      const style = stParser.token(stream, state);
      out.push([stream.current(), style]);
    }
    return out;
  });
}
const styled = (text: string) =>
  tokens(text)
    .flat()
    .filter(([, s]) => s !== null);

const pin = (name: string, type: string) => ({ name, type });
const TON: LibraryEntry = {
  name: "TON",
  kind: "function_block",
  source: "standard",
  comment: "on delay",
  extensible: false,
  inputs: [pin("IN", "BOOL"), pin("PT", "TIME")],
  in_outs: [],
  outputs: [pin("Q", "BOOL"), pin("ET", "TIME")],
  return_type: null,
};
const LIMIT: LibraryEntry = {
  name: "LIMIT",
  kind: "function",
  source: "standard",
  comment: null,
  extensible: false,
  inputs: [pin("MN", "ANY_ELEMENTARY"), pin("IN", "ANY_ELEMENTARY"), pin("MX", "ANY_ELEMENTARY")],
  in_outs: [],
  outputs: [],
  return_type: "ANY_ELEMENTARY",
};
const symbol = plainSymbol;

describe("ST highlighting (issue 9: keywords, types, literals, comments, pragmas)", () => {
  it("classifies each kind of token", () => {
    expect(styled("IF Start AND NOT x THEN y := T#5s; END_IF // done")).toEqual([
      ["IF", "keyword"],
      ["Start", "variableName"],
      ["AND", "keyword"],
      ["NOT", "keyword"],
      ["x", "variableName"],
      ["THEN", "keyword"],
      ["y", "variableName"],
      [":=", "operator"],
      ["T#5s", "number"],
      [";", "punctuation"],
      ["END_IF", "keyword"],
      ["// done", "lineComment"],
    ]);
    expect(
      styled("v : INT := 16#FF; s : STRING := 'it$'s'; r : REAL := 1.5E3; b : BOOL := TRUE;").filter(
        ([, s]) => s !== "punctuation" && s !== "operator",
      ),
    ).toEqual([
      ["v", "variableName"],
      ["INT", "typeName"],
      ["16#FF", "number"],
      ["s", "variableName"],
      ["STRING", "typeName"],
      ["'it$'s'", "string"],
      ["r", "variableName"],
      ["REAL", "typeName"],
      ["1.5E3", "number"],
      ["b", "variableName"],
      ["BOOL", "typeName"],
      ["TRUE", "atom"],
    ]);
  });

  it("continues block comments and pragmas over lines", () => {
    expect(tokens("(* one\ntwo *) x\n{attribute 'a'\n} y /* c */")).toEqual([
      [["(* one", "comment"]],
      [
        ["two *)", "comment"],
        [" ", null],
        ["x", "variableName"],
      ],
      [["{attribute 'a'", "meta"]],
      [
        ["}", "meta"],
        [" ", null],
        ["y", "variableName"],
        [" ", null],
        ["/* c */", "comment"],
      ],
    ]);
  });

  it("always advances and covers every character of any line", () => {
    fc.assert(
      fc.property(fc.array(fc.string({ maxLength: 30 }), { maxLength: 6 }), (lines) => {
        const text = lines.map((l) => l.replace(/\n/g, " ")).join("\n");
        const result = tokens(text);
        expect(result.map((line) => line.map(([t]) => t).join(""))).toEqual(text.split("\n"));
        for (const line of result) for (const [t] of line) expect(t.length).toBeGreaterThan(0);
      }),
    );
  });
});

describe("ST autocomplete (issue 9: variables, standard functions with a formal call template)", () => {
  it("builds formal call templates for FB instances and functions", () => {
    expect(callTemplate("TON1", TON)).toBe("TON1(IN := , PT := , Q => , ET => );");
    expect(callTemplate("LIMIT", LIMIT)).toBe("LIMIT(MN := , IN := , MX := )");
  });

  it("offers variables (an FB instance inserts its call), functions and FB types", () => {
    const options = stCompletions([symbol("Start", "BOOL"), symbol("TON1", "ton")], [TON, LIMIT]);
    const own = options.filter((o) => o.type !== "keyword" && o.type !== "type");
    expect(own.map((o) => [o.label, o.type, o.detail, o.apply ?? null])).toEqual([
      ["Start", "variable", "BOOL", null],
      ["TON1", "variable", "ton", "TON1(IN := , PT := , Q => , ET => );"],
      [
        "LIMIT",
        "function",
        "(MN: ANY_ELEMENTARY, IN: ANY_ELEMENTARY, MX: ANY_ELEMENTARY) : ANY_ELEMENTARY",
        "LIMIT(MN := , IN := , MX := )",
      ],
      ["TON", "class", "function block", null],
    ]);
    // Then the backend's keywords and types (issue 22 item 3): none the checker would reject.
    const words = options.filter((o) => !own.includes(o)).map((o) => o.label);
    expect(words).toEqual(
      expect.arrayContaining(["IF", "END_IF", "VAR_INPUT", "WSTRING", "TOD", "LREAL", "LTIME", "CONTINUE"]),
    );
    expect(words.filter((w) => ["CHAR", "WCHAR"].includes(w))).toEqual([]);
    expect(options.slice(0, own.length)).toEqual(own); // the POU's own names first
  });

  it("completes the word before the cursor, and nothing after a space unless asked", () => {
    const source = stCompletionSource(() => ({
      options: stCompletions([symbol("Start", "BOOL")], [TON]),
      members: () => null,
    }));
    const at = (doc: string, explicit = false) =>
      source(new CompletionContext(EditorState.create({ doc }), doc.length, explicit));
    expect(at("x := St")?.from).toBe(5);
    expect(
      at("x := St")
        ?.options.filter((o) => o.type !== "keyword" && o.type !== "type")
        .map((o) => o.label),
    ).toEqual(["Start", "TON"]);
    expect(at("x := ")).toBeNull();
    // A keyword typed out in full is not offered (Enter then starts a new line); its prefix is.
    expect(at("IF x then")?.options.map((o) => o.label)).not.toContain("THEN");
    expect(at("IF x the")?.options.map((o) => o.label)).toContain("THEN");
    expect(at("x := ", true)?.from).toBe(5);
  });
});

describe("diagnostics as lint underlines (issue 9: live diagnostics)", () => {
  const doc = Text.of(["x := y;", "  z := 1 +;"]);
  const diag = (d: Partial<Diagnostic>): Diagnostic => ({ code: "ST-E", message: "bad", file: "Main/body", ...d });

  it("maps 1-based line/column with an exclusive end column to document offsets", () => {
    expect(
      lintDiagnostics(
        [
          diag({
            line: 1,
            column: 6,
            end_line: 1,
            end_column: 7,
            message: "unknown variable 'y'",
            code: "ST-UNKNOWN-VAR",
          }),
        ],
        "MAIN/body",
        doc,
      ),
    ).toEqual([{ from: 5, to: 6, severity: "error", message: "ST-UNKNOWN-VAR: unknown variable 'y'" }]);
    expect(lintDiagnostics([diag({ line: 2, column: 11, severity: "warning" })], "Main/body", doc)).toEqual([
      { from: 18, to: 19, severity: "warning", message: "ST-E: bad" },
    ]);
  });

  it("keeps only the editor's text, marks unlocated ones on line 1 and clamps stale positions", () => {
    expect(
      lintDiagnostics(
        [diag({ file: "Main/declarations", line: 1, column: 1 }), diag({ file: null })],
        "Main/body",
        doc,
      ),
    ).toEqual([]);
    expect(lintDiagnostics([diag({})], "Main/body", doc)).toEqual([
      { from: 0, to: 7, severity: "error", message: "ST-E: bad" },
    ]);
    expect(lintDiagnostics([diag({ line: 9, column: 40, end_line: 12, end_column: 3 })], "Main/body", doc)).toEqual([
      { from: 19, to: 19, severity: "error", message: "ST-E: bad" },
    ]);
  });
});

describe("breakpoint lines (issue 9: ST line gutter)", () => {
  it("keeps existing lines once, in order", () => {
    expect(linesIn(Text.of(["a", "b", "c"]), [3, 1, 3, 0, 4, 2.5, 2])).toEqual([1, 2, 3]);
  });
});
