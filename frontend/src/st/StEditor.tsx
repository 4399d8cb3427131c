// A CodeMirror 6 editor for ST text (a POU body or its declarations): IEC ST highlighting, bracket
// and END_* matching, folding, autocomplete (members after `x.`), backend diagnostics as lint
// underlines, and online the values of variables inline. The text is controlled: every edit goes
// to onChange, and a new `text` from outside (reload, draft restore) replaces the doc.
import { autocompletion, closeBrackets, closeBracketsKeymap, completionKeymap } from "@codemirror/autocomplete";
import { defaultKeymap, history, historyKeymap } from "@codemirror/commands";
import {
  bracketMatching,
  codeFolding,
  foldGutter,
  foldKeymap,
  indentOnInput,
  syntaxHighlighting,
} from "@codemirror/language";
import { lintGutter, setDiagnostics } from "@codemirror/lint";
import { Compartment, EditorState } from "@codemirror/state";
import { EditorView, highlightActiveLine, keymap, lineNumbers, type ViewUpdate } from "@codemirror/view";
import { useEffect, useLayoutEffect, useRef } from "react";
import type { Diagnostic } from "../generated/api";
import { stBlocks } from "./blocks";
import { setBreakpointLines, setHaltedLine, stDebugging } from "./breakpoints";
import { stCompletionSource, type StCompletions } from "./completion";
import { setCoverageLines, stCoverage } from "./coverage";
import { setInlineMarks, stInlineValues, type InlineMark, type StOnlineView } from "./inlineValues";
import { ilLanguage } from "./ilLanguage";
import { stHighlightStyle } from "./highlightStyle";
import { stLanguage, stTestLanguage } from "./language";
import { stKeys } from "./keys";
import { lintDiagnostics } from "./lint";

export interface StEditorProps {
  text: string;
  onChange(text: string): void;
  /** Which text the diagnostics must name in `file` (e.g. "Main/body"). */
  file: string;
  diagnostics: Diagnostic[];
  completions: StCompletions;
  /** A reason the text cannot be edited now (online), shown above the text, or null; "" makes the text read-only
   * without saying why again (a second editor of the same POU whose first one says it). */
  readOnly: string | null;
  label: string;
  /** Debugging (the body only): breakpoint lines, the halted line, a gutter click, and an edit that moved lines
   * (`move`: a line before the edit -> its line after it, null when its text was deleted). */
  debug?: {
    breakpoints: readonly number[];
    halted: number | null;
    onToggle(line: number): void;
    onLinesMoved?(move: (line: number) => number | null): void;
  };
  /** Online (the body only): values shown after their variables (none when hidden), hover and right-click. */
  online?: StOnlineView & { marks: readonly InlineMark[] };
  /** Lines the last test run with coverage never executed (tinted). */
  coverage?: readonly number[];
  /** A line to show and put the cursor on (a test failure or diagnostic was clicked); `seq` repeats a jump. */
  focusLine?: { line: number; seq: number } | null;
  /** The text's language: ST (default), an IL body (docs/il.md) or a test file (docs/testing.md). */
  language?: "st" | "il" | "test";
  /** The quick fix of an unknown variable (its mark's "Declare NAME", Shift+F2): opens the declare dialog. */
  onDeclare?(name: string): void;
}

const NO_MARKS: readonly InlineMark[] = [];

/** Where line `line` went in an edit: the line its start is on now, or null when all of its text was deleted. */
function lineAfter(u: ViewUpdate, line: number): number | null {
  const before = u.startState.doc;
  if (line < 1 || line > before.lines) return line;
  const { from, to, length } = before.line(line);
  const start = u.changes.mapPos(from, 1);
  if (length > 0 && u.changes.mapPos(to, -1) <= start && u.changes.touchesRange(from, to)) return null;
  return u.state.doc.lineAt(start).number;
}
const NO_LINES: readonly number[] = [];

export function StEditor({
  text,
  onChange,
  file,
  diagnostics,
  completions,
  readOnly,
  label,
  debug,
  online,
  coverage = NO_LINES,
  focusLine,
  language = "st",
  onDeclare,
}: StEditorProps) {
  const host = useRef<HTMLDivElement>(null);
  const view = useRef<EditorView | null>(null);
  // What the editor's callbacks read: the props of the last render (kept after rendering, not during it).
  const latest = useRef({ onChange, completions, debug, online, onDeclare });
  useLayoutEffect(() => {
    latest.current = { onChange, completions, debug, online, onDeclare };
  });
  const editable = useRef(new Compartment());
  /** The props the view is created with; later ones arrive through the effects below. */
  const initial = useRef({ text, debugging: debug !== undefined, readOnly, label, language });

  useEffect(() => {
    const { text, debugging, readOnly, label, language } = initial.current;
    const v = new EditorView({
      parent: host.current!,
      state: EditorState.create({
        doc: text,
        extensions: [
          lineNumbers(),
          history(),
          highlightActiveLine(),
          indentOnInput(),
          bracketMatching(),
          closeBrackets(),
          language === "il" ? ilLanguage : [language === "test" ? stTestLanguage : stLanguage, stBlocks],
          codeFolding(),
          foldGutter(),
          syntaxHighlighting(stHighlightStyle),
          autocompletion({ override: [stCompletionSource(() => latest.current.completions)] }),
          lintGutter(),
          debugging ? stDebugging((line) => latest.current.debug?.onToggle(line)) : [],
          stInlineValues(() => latest.current.online),
          stCoverage,
          keymap.of([
            ...stKeys(debugging ? (line) => latest.current.debug?.onToggle(line) : null),
            ...closeBracketsKeymap,
            ...defaultKeymap,
            ...historyKeymap,
            ...foldKeymap,
            ...completionKeymap,
          ]),
          editable.current.of(EditorState.readOnly.of(readOnly !== null)),
          EditorView.contentAttributes.of({ "aria-label": label }),
          EditorView.theme({
            "&": { height: "100%" },
            ".cm-scroller": { overflow: "auto", fontFamily: "ui-monospace, monospace" },
            // the line numbers in the app's colours (CodeMirror's own gutter is light grey, also in the dark theme)
            ".cm-gutters": {
              backgroundColor: "var(--panel)",
              color: "var(--muted)",
              borderRight: "1px solid var(--border-soft)",
            },
            ".cm-activeLineGutter": { backgroundColor: "var(--surface-2)", color: "var(--text)" },
          }),
          EditorView.updateListener.of((u) => {
            if (!u.docChanged) return;
            const debugging = latest.current.debug;
            if (debugging?.breakpoints.length && debugging.onLinesMoved)
              debugging.onLinesMoved((line) => lineAfter(u, line));
            latest.current.onChange(u.state.doc.toString());
          }),
        ],
      }),
    });
    view.current = v;
    return () => {
      v.destroy();
      view.current = null;
    };
  }, []);

  useEffect(() => {
    const v = view.current;
    if (v && v.state.doc.toString() !== text)
      v.dispatch({ changes: { from: 0, to: v.state.doc.length, insert: text } });
  }, [text]);

  const breakpoints = debug?.breakpoints;
  const halted = debug?.halted ?? null;
  const debugging = debug !== undefined;
  useEffect(() => {
    if (breakpoints) view.current?.dispatch({ effects: [setBreakpointLines.of(breakpoints)] });
  }, [breakpoints]);
  useEffect(() => {
    const v = view.current;
    if (!v || !debugging) return;
    const line = halted !== null && halted >= 1 && halted <= v.state.doc.lines ? v.state.doc.line(halted) : null;
    v.dispatch({
      effects: [setHaltedLine.of(halted), ...(line ? [EditorView.scrollIntoView(line.from, { y: "center" })] : [])],
    });
  }, [halted, debugging]);

  const marks = online?.marks ?? NO_MARKS;
  useEffect(() => {
    view.current?.dispatch({ effects: setInlineMarks.of(marks) });
  }, [marks]);

  useEffect(() => {
    view.current?.dispatch({ effects: setCoverageLines.of(coverage) });
  }, [coverage]);

  const declaring = onDeclare !== undefined;
  const focusSeq = focusLine?.seq;
  useEffect(() => {
    const v = view.current;
    if (!v || !focusLine || focusLine.line < 1 || focusLine.line > v.state.doc.lines) return;
    const at = v.state.doc.line(focusLine.line).from;
    v.dispatch({ selection: { anchor: at }, effects: EditorView.scrollIntoView(at, { y: "center" }) });
    v.focus();
    // Only a new request moves the cursor (seq), not a re-render with the same one.
    // eslint-disable-next-line react-hooks/exhaustive-deps
  }, [focusSeq]);

  useEffect(() => {
    view.current?.dispatch({ effects: editable.current.reconfigure(EditorState.readOnly.of(readOnly !== null)) });
  }, [readOnly]);

  useEffect(() => {
    const v = view.current;
    const declare = declaring ? (name: string) => latest.current.onDeclare?.(name) : undefined;
    if (v) v.dispatch(setDiagnostics(v.state, lintDiagnostics(diagnostics, file, v.state.doc, declare)));
  }, [diagnostics, file, declaring]);

  return (
    <div className="st-editor" style={{ display: "flex", flexDirection: "column", height: "100%", minHeight: 0 }}>
      {readOnly ? <p className="st-editor-readonly">{readOnly}</p> : null}
      <div ref={host} className="st-editor-host" style={{ flex: "1 1 auto", minHeight: 0, overflow: "hidden" }} />
    </div>
  );
}
