// @vitest-environment jsdom
import { syntaxHighlighting } from "@codemirror/language";
import { EditorState } from "@codemirror/state";
import { EditorView } from "@codemirror/view";
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { stLanguage } from "../st/language";
import { highlightLines, ST_VIEW_CLASSES, type Token } from "./highlight";

const marked = (tokens: readonly Token[]) => tokens.filter((t) => t.className).map((t) => [t.className, t.text]);

/** Adjacent text of one class joined, so two renderings compare by what is coloured how. */
function runs(parts: readonly [string, string][]): [string, string][] {
  const out: [string, string][] = [];
  for (const [className, text] of parts) {
    const last = out[out.length - 1];
    if (last && last[0] === className) last[1] += text;
    else if (text) out.push([className, text]);
  }
  return out;
}

/** What the ST editor (CodeMirror with the ST language) renders: per line, each text node's class. */
function editorRuns(doc: string): [string, string][][] {
  const parent = document.createElement("div");
  document.body.append(parent);
  const view = new EditorView({
    state: EditorState.create({ doc, extensions: [stLanguage, syntaxHighlighting(ST_VIEW_CLASSES)] }),
    parent,
  });
  const lines = [...view.contentDOM.querySelectorAll(".cm-line")].map((line) => {
    const parts: [string, string][] = [];
    const walker = document.createTreeWalker(line, NodeFilter.SHOW_TEXT);
    for (let node = walker.nextNode(); node; node = walker.nextNode()) {
      const span = node.parentElement === line ? null : node.parentElement;
      parts.push([span?.className ?? "", node.textContent ?? ""]);
    }
    return runs(parts);
  });
  view.destroy();
  parent.remove();
  return lines;
}

const SAMPLE = [
  "FUNCTION_BLOCK Motor (* the motor rung,",
  "   as a block comment over two lines *)",
  "VAR_INPUT Start, Stop : BOOL; END_VAR",
  "VAR RunTimer : TON; n : INT := 16#FF; r : REAL := 2.5e3; s : STRING := 'it$'s'; END_VAR",
  "{attribute 'hide'}",
  "Motor := (Start OR Motor) AND NOT Stop; // seal-in",
  "RunTimer(IN := Motor, PT := T#5s);",
  "IF RunTimer.Q THEN n := n + 1; ELSE n := 0; END_IF;",
  "END_FUNCTION_BLOCK",
].join("\n");

describe("ST highlighting of the read-only views (issue 19: one ST tokenizer)", () => {
  it("marks keywords and names of the motor rung", () => {
    expect(marked(highlightLines("Motor := (Start OR Motor) AND NOT Stop;")[0]!)).toEqual([
      ["st-name", "Motor"],
      ["st-name", "Start"],
      ["st-keyword", "OR"],
      ["st-name", "Motor"],
      ["st-keyword", "AND"],
      ["st-keyword", "NOT"],
      ["st-name", "Stop"],
    ]);
  });

  it("marks comments (also over lines), typed literals, numbers, strings, types and pragmas", () => {
    const lines = highlightLines(SAMPLE).map(marked);
    expect(lines[0]).toEqual([
      ["st-keyword", "FUNCTION_BLOCK"],
      ["st-name", "Motor"],
      ["st-comment", "(* the motor rung,"],
    ]);
    expect(lines[1]).toEqual([["st-comment", "   as a block comment over two lines *)"]]);
    expect(lines[3]).toEqual([
      ["st-keyword", "VAR"],
      ["st-name", "RunTimer"],
      ["st-type", "TON"],
      ["st-name", "n"],
      ["st-type", "INT"],
      ["st-number", "16#FF"],
      ["st-name", "r"],
      ["st-type", "REAL"],
      ["st-number", "2.5e3"],
      ["st-name", "s"],
      ["st-type", "STRING"],
      ["st-string", "'it$'s'"],
      ["st-keyword", "END_VAR"],
    ]);
    expect(lines[4]).toEqual([["st-comment", "{attribute 'hide'}"]]);
    expect(lines[5]!.at(-1)).toEqual(["st-comment", "// seal-in"]);
    expect(lines[6]).toContainEqual(["st-number", "T#5s"]);
    expect(lines[7]!.slice(0, 3)).toEqual([
      ["st-keyword", "IF"],
      ["st-name", "RunTimer"],
      ["st-name", "Q"],
    ]);
  });

  it("colours the sample exactly as the ST editor does", () => {
    const editor = editorRuns(SAMPLE);
    expect(editor[0]).toContainEqual(["st-keyword", "FUNCTION_BLOCK"]); // the editor did colour
    const view = highlightLines(SAMPLE).map((line) => runs(line.map((t) => [t.className, t.text])));
    expect(view).toEqual(editor);
  });

  it("gives back every line of the text it was given (property)", () => {
    fc.assert(
      fc.property(
        fc.string({
          unit: fc.constantFrom(
            "a",
            "Z",
            "_",
            "1",
            "#",
            "'",
            '"',
            "(",
            "*",
            ")",
            "/",
            " ",
            ":",
            "=",
            ";",
            "$",
            ".",
            "\n",
            "{",
            "}",
          ),
        }),
        (text) => {
          expect(highlightLines(text).map((line) => line.map((t) => t.text).join(""))).toEqual(text.split("\n"));
        },
      ),
    );
  });
});
