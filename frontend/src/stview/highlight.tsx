// Highlighting of read-only ST (the "View as ST" tab, the printed document) with the ST editor's own
// language (st/language.ts): @lezer/highlight runs the same stream parser, so a word is coloured the
// same in the editor and in the views, and a block comment spanning lines stays a comment. Classes
// are st-comment, st-string, st-number, st-keyword, st-type, st-name (styles.css, print.css); other
// text (operators, punctuation, spaces) has none.
import { highlightCode, tagHighlighter, tags } from "@lezer/highlight";
import { stLanguage } from "../st/language";

/** The CSS class of each highlighting tag of the ST language (sub-tags, e.g. lineComment, follow their parent). */
export const ST_VIEW_CLASSES = tagHighlighter([
  { tag: [tags.comment, tags.meta], class: "st-comment" },
  { tag: tags.string, class: "st-string" },
  { tag: tags.number, class: "st-number" },
  { tag: [tags.keyword, tags.atom], class: "st-keyword" },
  { tag: tags.typeName, class: "st-type" },
  { tag: tags.variableName, class: "st-name" },
]);

export interface Token {
  text: string;
  /** The CSS class ("" for text the language does not mark). */
  className: string;
}

/** The tokens of every line of `text` ("\n"-separated), parsed as one text. */
export function highlightLines(text: string): Token[][] {
  const lines: Token[][] = [[]];
  highlightCode(
    text,
    stLanguage.parser.parse(text),
    ST_VIEW_CLASSES,
    (part, className) => lines[lines.length - 1]!.push({ text: part, className }),
    () => lines.push([]),
  );
  return lines;
}

/** One line's highlighted tokens as spans of their classes. */
export function Tokens({ tokens }: { tokens: readonly Token[] }) {
  return tokens.map((t, j) => (
    <span key={j} className={t.className || undefined}>
      {t.text}
    </span>
  ));
}
