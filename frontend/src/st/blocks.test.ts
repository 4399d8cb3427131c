// @vitest-environment jsdom
import { foldable } from "@codemirror/language";
import { EditorState } from "@codemirror/state";
import { EditorView } from "@codemirror/view";
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { foldAt, partnerAt, scanBlocks, stBlocks, type Span } from "./blocks";
import { stLanguage } from "./language";

const words = (text: string, spans: readonly Span[]) => spans.map((s) => text.slice(s.from, s.to));
const pairWords = (text: string) =>
  scanBlocks(text).pairs.map((p) => `${text.slice(p.open.from, p.open.to)}/${text.slice(p.close.from, p.close.to)}`);

const FB = `FUNCTION_BLOCK Counter
VAR_INPUT
    Enable : BOOL; (* END_VAR in a comment *)
END_VAR
VAR
    i : INT;
    s : STRING := 'END_IF';
END_VAR
IF Enable THEN
    FOR i := 1 TO 3 DO
        CASE i OF
            1: WHILE FALSE DO END_WHILE;
        END_CASE;
    END_FOR;
ELSIF NOT Enable THEN
    REPEAT i := i + 1; UNTIL i > 9 END_REPEAT;
END_IF;
(* a comment
   over two lines *)
END_FUNCTION_BLOCK`;

describe("END_* matching (issue 9: bracket/END_* matching)", () => {
  it("pairs every block keyword with its END_, ignoring comments and strings", () => {
    expect(pairWords(FB)).toEqual([
      "VAR_INPUT/END_VAR",
      "VAR/END_VAR",
      "WHILE/END_WHILE",
      "CASE/END_CASE",
      "FOR/END_FOR",
      "REPEAT/END_REPEAT",
      "IF/END_IF",
      "FUNCTION_BLOCK/END_FUNCTION_BLOCK",
    ]);
    expect(scanBlocks(FB).unmatched).toEqual([]);
    expect(words(FB, scanBlocks(FB).comments)).toEqual(["(* a comment\n   over two lines *)"]);
  });

  it("pairs TYPE/STRUCT, is case-insensitive and reports unclosed and stray keywords", () => {
    const types = "TYPE Point : STRUCT x : INT; END_STRUCT; END_TYPE";
    expect(pairWords(types)).toEqual(["STRUCT/END_STRUCT", "TYPE/END_TYPE"]);
    const broken = "if a then\n  while b do\n  end_if;\nEND_WHILE";
    expect(pairWords(broken)).toEqual(["if/end_if"]);
    expect(words(broken, scanBlocks(broken).unmatched)).toEqual(["while", "END_WHILE"]);
  });

  it("finds the partner of the keyword the cursor touches", () => {
    const text = "IF a THEN\n  b := 1;\nEND_IF;";
    const blocks = scanBlocks(text);
    for (const pos of [0, 1, 2])
      expect(partnerAt(blocks, pos)).toEqual({ at: { from: 0, to: 2 }, partner: { from: 20, to: 26 } });
    expect(partnerAt(blocks, 23)).toEqual({ at: { from: 20, to: 26 }, partner: { from: 0, to: 2 } });
    expect(partnerAt(blocks, 5)).toBeNull();
    expect(partnerAt(scanBlocks("END_IF"), 3)).toEqual({ at: { from: 0, to: 6 }, partner: null });
  });

  it("pairs any nesting of blocks, each closer with its own opener", () => {
    const block = fc.letrec<{ tree: string }>((tie) => ({
      tree: fc.oneof(
        { depthSize: "small" },
        fc.constant("x := 1;"),
        fc
          .tuple(
            fc.constantFrom(
              "IF c THEN|END_IF;",
              "WHILE c DO|END_WHILE;",
              "FOR i := 1 TO 2 DO|END_FOR;",
              "CASE i OF 1:|END_CASE;",
              "REPEAT|UNTIL c END_REPEAT;",
            ),
            fc.array(tie("tree"), { maxLength: 3 }),
          )
          .map(([frame, inner]) => frame.replace("|", `\n${inner.join("\n")}\n`)),
      ),
    })).tree;
    fc.assert(
      fc.property(fc.array(block, { maxLength: 4 }), (blocks) => {
        const text = blocks.join("\n");
        const result = scanBlocks(text);
        expect(result.unmatched).toEqual([]);
        const openers = (text.match(/\b(IF|WHILE|FOR|CASE|REPEAT)\b/g) ?? []).length;
        expect(result.pairs).toHaveLength(openers);
        for (const { open, close } of result.pairs) {
          expect(text.slice(close.from, close.to)).toBe(`END_${text.slice(open.from, open.to)}`);
          // Properly nested: the text between a pair has as many openers of its kind as closers.
          const inner = text.slice(open.to, close.from);
          const kind = text.slice(open.from, open.to);
          expect((inner.match(new RegExp(`\\bEND_${kind}\\b`, "g")) ?? []).length).toBe(
            (inner.match(new RegExp(`(?<!END_)\\b${kind}\\b`, "g")) ?? []).length,
          );
        }
      }),
    );
  });
});

describe("folding (issue 9: folding of blocks and comments)", () => {
  const state = EditorState.create({ doc: FB, extensions: [stLanguage, stBlocks] });
  const foldOfLine = (n: number) => {
    const line = state.doc.line(n);
    const range = foldable(state, line.from, line.to);
    return range ? state.doc.sliceString(range.from, range.to) : null;
  };

  it("folds a block to the line before its END_, and a comment after its first line", () => {
    expect(foldOfLine(9)).toBe(
      FB.split("\n")
        .slice(9, 16)
        .map((l) => `\n${l}`)
        .join(""),
    );
    expect(foldOfLine(10)).toBe("\n        CASE i OF\n            1: WHILE FALSE DO END_WHILE;\n        END_CASE;");
    expect(foldOfLine(2)).toBe("\n    Enable : BOOL; (* END_VAR in a comment *)");
    expect(foldOfLine(18)).toBe("\n   over two lines *)");
    // A block on one line, and a plain statement, do not fold.
    expect(foldOfLine(12)).toBeNull();
    expect(foldOfLine(16)).toBeNull();
  });

  it("gives nothing for a line with no block", () => {
    expect(foldAt(scanBlocks("x := 1;\ny := 2;"), state.doc, 0, 7)).toBeNull();
  });
});

describe("END_* highlight in the editor", () => {
  it("marks the keyword at the cursor and its partner, and a stray closer as not matching", () => {
    const view = new EditorView({
      parent: document.body,
      state: EditorState.create({
        doc: "WHILE a DO\n  b := 1;\nEND_WHILE;\nEND_IF;",
        selection: { anchor: 2 },
        extensions: [stLanguage, stBlocks],
      }),
    });
    const marked = (cls: string) => [...view.dom.querySelectorAll(cls)].map((e) => e.textContent);
    expect(marked(".cm-matchingBracket")).toEqual(["WHILE", "END_WHILE"]);
    view.dispatch({ selection: { anchor: view.state.doc.length - 2 } });
    expect(marked(".cm-matchingBracket")).toEqual([]);
    expect(marked(".cm-nonmatchingBracket")).toEqual(["END_IF"]);
    view.destroy();
  });
});
