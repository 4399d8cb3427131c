// The tests' coverage in the ST editor: the body lines no test executed, tinted (fed from outside by an
// effect, like the breakpoint marks: the Tests panel's last coverage run decides).
import { StateEffect, StateField, type Extension } from "@codemirror/state";
import { Decoration, EditorView, type DecorationSet } from "@codemirror/view";
import { linesIn } from "./breakpoints";

export const setCoverageLines = StateEffect.define<readonly number[]>();

const NEVER = Decoration.line({ class: "cm-coverage-never", attributes: { title: "no test executed this line" } });

const coverageField = StateField.define<DecorationSet>({
  create: () => Decoration.none,
  update(value, tr) {
    let next = value.map(tr.changes);
    for (const e of tr.effects) {
      if (e.is(setCoverageLines))
        next = Decoration.set(linesIn(tr.state.doc, e.value).map((l) => NEVER.range(tr.state.doc.line(l).from)));
    }
    return next;
  },
  provide: (f) => EditorView.decorations.from(f),
});

export const stCoverage: Extension = coverageField;
