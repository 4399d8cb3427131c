// IEC block keywords as pairs (IF/END_IF, VAR_INPUT/END_VAR, STRUCT/END_STRUCT, ...) and block
// comments, found from the highlighter's tokens. The editor highlights the partner of the keyword
// at the cursor (like bracket matching) and folds every block and comment spanning lines.
import { foldService } from "@codemirror/language";
import { StateField, type EditorState, type Extension } from "@codemirror/state";
import { Decoration, EditorView, type DecorationSet } from "@codemirror/view";
import { tokenize } from "./language";

/** Opening keyword -> the keyword that closes it (the blocks a project's ST texts hold; all are keywords). */
const CLOSER: Readonly<Record<string, string>> = {
  IF: "END_IF",
  CASE: "END_CASE",
  FOR: "END_FOR",
  WHILE: "END_WHILE",
  REPEAT: "END_REPEAT",
  PROGRAM: "END_PROGRAM",
  FUNCTION: "END_FUNCTION",
  FUNCTION_BLOCK: "END_FUNCTION_BLOCK",
  TYPE: "END_TYPE",
  STRUCT: "END_STRUCT",
  ...Object.fromEntries(
    ["VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_TEMP", "VAR_GLOBAL", "VAR_EXTERNAL"].map((k) => [
      k,
      "END_VAR",
    ]),
  ),
};
const CLOSERS = new Set(Object.values(CLOSER));

export interface Span {
  from: number;
  to: number;
}

export interface BlockPair {
  open: Span;
  close: Span;
}

export interface Blocks {
  /** Matched keyword pairs, in the order their closers appear. */
  pairs: BlockPair[];
  /** Openers never closed and closers with no opener. */
  unmatched: Span[];
  /** Block comments and pragmas that span lines. */
  comments: Span[];
}

/** The block structure of ST text: a stack of open keywords; a closer pops to its opener (skipped ones stay unmatched). */
export function scanBlocks(text: string): Blocks {
  const pairs: BlockPair[] = [];
  const unmatched: Span[] = [];
  const comments: Span[] = [];
  const stack: { word: string; span: Span }[] = [];
  let commentFrom: number | null = null;
  for (const token of tokenize(text)) {
    if (token.style === "comment" || token.style === "meta") {
      if (token.continues && commentFrom === null) commentFrom = token.from;
      else if (!token.continues && commentFrom !== null) {
        comments.push({ from: commentFrom, to: token.to });
        commentFrom = null;
      }
      continue;
    }
    if (token.style !== "keyword") continue;
    const word = token.text.toUpperCase();
    const span = { from: token.from, to: token.to };
    if (CLOSER[word]) stack.push({ word, span });
    else if (CLOSERS.has(word)) {
      const at = stack.map((s) => CLOSER[s.word]).lastIndexOf(word);
      if (at < 0) unmatched.push(span);
      else {
        for (const skipped of stack.splice(at + 1)) unmatched.push(skipped.span);
        pairs.push({ open: stack.pop()!.span, close: span });
      }
    }
  }
  unmatched.push(...stack.map((s) => s.span));
  return { pairs, unmatched: unmatched.sort((a, b) => a.from - b.from), comments };
}

/** The keyword at `pos` (the cursor touching it) and its partner; `partner` null when it has none. */
export function partnerAt(blocks: Blocks, pos: number): { at: Span; partner: Span | null } | null {
  const touches = (s: Span) => s.from <= pos && pos <= s.to;
  for (const { open, close } of blocks.pairs) {
    if (touches(open)) return { at: open, partner: close };
    if (touches(close)) return { at: close, partner: open };
  }
  const lone = blocks.unmatched.find(touches);
  return lone ? { at: lone, partner: null } : null;
}

/**
 * What folds at the line `[lineStart, lineEnd]`: a block opened on it and closed on a later line
 * folds to the end of the line before its closer (END_IF stays visible); a comment folds whole
 * but its first line.
 */
export function foldAt(blocks: Blocks, doc: EditorState["doc"], lineStart: number, lineEnd: number): Span | null {
  const comment = blocks.comments.find((c) => c.from >= lineStart && c.from <= lineEnd);
  if (comment && comment.to > lineEnd) return { from: lineEnd, to: comment.to };
  for (const { open, close } of blocks.pairs) {
    if (open.from < lineStart || open.from > lineEnd) continue;
    const to = doc.lineAt(close.from).from - 1;
    if (to > lineEnd) return { from: lineEnd, to };
  }
  return null;
}

const blocksField = StateField.define<Blocks>({
  create: (state) => scanBlocks(state.doc.toString()),
  update: (value, tr) => (tr.docChanged ? scanBlocks(tr.state.doc.toString()) : value),
});

const matched = Decoration.mark({ class: "cm-matchingBracket" });
const unmatchedMark = Decoration.mark({ class: "cm-nonmatchingBracket" });

const keywordMatching = EditorView.decorations.compute([blocksField, "selection"], (state): DecorationSet => {
  const found = partnerAt(state.field(blocksField), state.selection.main.head);
  if (!found) return Decoration.none;
  if (!found.partner) return Decoration.set([unmatchedMark.range(found.at.from, found.at.to)]);
  const marks = [found.at, found.partner].sort((a, b) => a.from - b.from);
  return Decoration.set(marks.map((s) => matched.range(s.from, s.to)));
});

/** END_* matching and folding of blocks and comments (add CodeMirror's foldGutter to show the markers). */
export const stBlocks: Extension = [
  blocksField,
  keywordMatching,
  foldService.of((state, lineStart, lineEnd) => foldAt(state.field(blocksField), state.doc, lineStart, lineEnd)),
];
