// The colours of ST and IL text in the editor, taken from the theme's variables (theme.css), so the text
// stays readable in the light and the dark theme. The tags are those CodeMirror's default style colours.
import { HighlightStyle } from "@codemirror/language";
import { tags as t } from "@lezer/highlight";

export const stHighlightStyle = HighlightStyle.define([
  { tag: t.keyword, color: "var(--syntax-keyword)" },
  { tag: [t.atom, t.bool, t.labelName], color: "var(--syntax-atom)" },
  { tag: [t.literal, t.number], color: "var(--syntax-number)" },
  { tag: [t.string, t.regexp, t.escape, t.special(t.string)], color: "var(--syntax-string)" },
  { tag: [t.typeName, t.namespace, t.className], color: "var(--syntax-type)" },
  { tag: [t.definition(t.variableName), t.definition(t.propertyName), t.macroName], color: "var(--syntax-definition)" },
  { tag: t.comment, color: "var(--syntax-comment)" },
  { tag: t.meta, color: "var(--muted)" },
  { tag: t.invalid, color: "var(--down)" },
  { tag: t.strong, fontWeight: "bold" },
  { tag: t.emphasis, fontStyle: "italic" },
]);
