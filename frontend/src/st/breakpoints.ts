// The ST editor's debugging marks: a gutter of breakpoint dots (a click toggles the line) and the
// line where a halted scan stands. Both are fed from outside by effects, so the editor shows
// whatever the debug store and the monitor say.
import { RangeSet, StateEffect, StateField, type Extension, type Text } from "@codemirror/state";
import { Decoration, EditorView, GutterMarker, gutter, type DecorationSet } from "@codemirror/view";

export const setBreakpointLines = StateEffect.define<readonly number[]>();
export const setHaltedLine = StateEffect.define<number | null>();

const breakpointLines = StateField.define<readonly number[]>({
  create: () => [],
  update: (value, tr) => tr.effects.reduce((v, e) => (e.is(setBreakpointLines) ? e.value : v), value),
});

class BreakpointDot extends GutterMarker {
  override toDOM() {
    const dot = document.createElement("span");
    dot.className = "cm-breakpoint";
    dot.textContent = "●";
    dot.style.color = "#d0312d";
    return dot;
  }
}
const DOT = new BreakpointDot();

/** 1-based line numbers that exist in `doc`, sorted and without repeats (RangeSet needs order). */
export function linesIn(doc: Text, lines: readonly number[]): number[] {
  return [...new Set(lines)].filter((l) => Number.isInteger(l) && l >= 1 && l <= doc.lines).sort((a, b) => a - b);
}

const haltedLine = StateField.define<DecorationSet>({
  create: () => Decoration.none,
  update(value, tr) {
    let next = value.map(tr.changes);
    for (const e of tr.effects) {
      if (!e.is(setHaltedLine)) continue;
      const [line] = e.value == null ? [] : linesIn(tr.state.doc, [e.value]);
      next = line
        ? Decoration.set([
            Decoration.line({ class: "cm-halted-line", attributes: { style: "background: #fff3b0" } }).range(
              tr.state.doc.line(line).from,
            ),
          ])
        : Decoration.none;
    }
    return next;
  },
  provide: (f) => EditorView.decorations.from(f),
});

/** The gutter and the halted-line highlight; `onToggle` gets the 1-based line clicked. */
export function stDebugging(onToggle: (line: number) => void): Extension {
  return [
    breakpointLines,
    haltedLine,
    gutter({
      class: "cm-breakpoint-gutter",
      markers: (view) =>
        RangeSet.of(
          linesIn(view.state.doc, view.state.field(breakpointLines)).map((l) => DOT.range(view.state.doc.line(l).from)),
        ),
      initialSpacer: () => DOT,
      domEventHandlers: {
        mousedown(view, block) {
          onToggle(view.state.doc.lineAt(block.from).number);
          return true;
        },
      },
    }),
  ];
}
