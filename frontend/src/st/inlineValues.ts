// ST online mode (like CODESYS): every occurrence of a variable with a value (elementary type,
// reached through FB instances and struct fields) gets its simulation path; the editor shows the
// monitor's value after it as a widget, describes it on hover and opens the online commands on a
// right click. Occurrences come from the highlighter's tokens, so comments, strings, keywords,
// function names and formal parameter names (`IN :=`) are never taken for variables.
import { StateEffect, StateField, type Extension } from "@codemirror/state";
import { Decoration, EditorView, hoverTooltip, WidgetType, type DecorationSet } from "@codemirror/view";
import { operandPath } from "../online/ldBinding";
import { formatValue } from "../online/values";
import type { Value } from "../online/protocol";
import { tokenize } from "./language";
import { membersOf, typeOfChain, type Scope } from "./members";

export interface Occurrence {
  from: number;
  to: number;
  /** The access as written, e.g. `Timer.Q`. */
  text: string;
  /** Canonical simulation path (upper case), e.g. `MAIN.TIMER.Q` or `ALARM` (a global, as the server names it). */
  path: string;
  type: string;
}

/** A type whose variables have one value to show (not an FB, a struct, an array or a reference). */
const hasValue = (type: string, scope: Scope) =>
  membersOf(type, scope) === null && !/^\s*(ARRAY|REF_TO|POINTER)\b/i.test(type);

/** Every variable occurrence in `text` with a value, as paths of POU instance `instance`. */
export function variableOccurrences(text: string, scope: Scope, instance: string): Occurrence[] {
  const tokens = tokenize(text).filter((t) => t.style !== null);
  const out: Occurrence[] = [];
  let depth = 0;
  for (let i = 0; i < tokens.length; i++) {
    const t = tokens[i]!;
    if (t.text === "(") depth += 1;
    else if (t.text === ")") depth = Math.max(0, depth - 1);
    if (t.style !== "variableName") continue;
    const chain = [t.text];
    let end = i;
    while (tokens[end + 1]?.text === "." && tokens[end + 2]?.style === "variableName") {
      chain.push(tokens[end + 2]!.text);
      end += 2;
    }
    const next = tokens[end + 1]?.text;
    const formal = depth > 0 && chain.length === 1 && (next === ":=" || next === "=>");
    const type = formal ? null : typeOfChain(chain, scope);
    const path = type !== null && hasValue(type, scope) ? operandPath(chain.join("."), instance, scope.symbols) : null;
    if (path && type)
      out.push({ from: t.from, to: tokens[end]!.to, text: text.slice(t.from, tokens[end]!.to), path, type });
    i = end;
  }
  return out;
}

export interface InlineMark {
  /** Document offset the value is shown at (the end of the occurrence). */
  pos: number;
  text: string;
  /** BOOL values are coloured like LD power flow. */
  bool: boolean | null;
  forced: boolean;
}

/** The values to show: one per occurrence whose path has a value in the monitor. */
export function inlineMarks(
  occurrences: readonly Occurrence[],
  values: Readonly<Record<string, Value>>,
  forced: ReadonlySet<string>,
): InlineMark[] {
  return occurrences.flatMap((o) => {
    const value = values[o.path];
    if (value === undefined) return [];
    return [
      {
        pos: o.to,
        text: formatValue(value, o.type),
        bool: typeof value === "boolean" ? value : null,
        forced: forced.has(o.path),
      },
    ];
  });
}

/** What hover says about an occurrence: access, type, value and whether it is forced. */
export function describe(o: Occurrence, values: Readonly<Record<string, Value>>, forced: ReadonlySet<string>): string {
  return `${o.text} : ${o.type} = ${formatValue(values[o.path], o.type)}${forced.has(o.path) ? " (forced)" : ""}`;
}

class ValueWidget extends WidgetType {
  constructor(readonly mark: InlineMark) {
    super();
  }
  override eq(other: ValueWidget) {
    const [a, b] = [this.mark, other.mark];
    return a.text === b.text && a.bool === b.bool && a.forced === b.forced;
  }
  override toDOM() {
    const span = document.createElement("span");
    const { bool, forced, text } = this.mark;
    span.className = `cm-st-value${bool === null ? "" : bool ? " cm-st-value-true" : " cm-st-value-false"}${forced ? " cm-st-value-forced" : ""}`;
    span.textContent = forced ? `${text} F` : text;
    return span;
  }
}

export const setInlineMarks = StateEffect.define<readonly InlineMark[]>();

const inlineField = StateField.define<DecorationSet>({
  create: () => Decoration.none,
  update(value, tr) {
    let next = value.map(tr.changes);
    for (const e of tr.effects) {
      if (!e.is(setInlineMarks)) continue;
      const length = tr.state.doc.length;
      const marks = [...e.value].filter((m) => m.pos >= 0 && m.pos <= length).sort((a, b) => a.pos - b.pos);
      next = Decoration.set(marks.map((m) => Decoration.widget({ widget: new ValueWidget(m), side: 1 }).range(m.pos)));
    }
    return next;
  },
  provide: (f) => EditorView.decorations.from(f),
});

/** What the editor asks of the online view at a position (read at each event, so it follows the monitor). */
export interface StOnlineView {
  occurrences: readonly Occurrence[];
  describe(o: Occurrence): string;
  onMenu(o: Occurrence, x: number, y: number): void;
}

const occurrenceAt = (view: StOnlineView | undefined, pos: number) =>
  view?.occurrences.find((o) => o.from <= pos && pos <= o.to);

/** Values as small tags after their variable; BOOLs in the LD editor's power colours. */
const valueTheme = EditorView.baseTheme({
  ".cm-st-value": {
    marginLeft: "2px",
    padding: "0 3px",
    borderRadius: "3px",
    fontSize: "85%",
    background: "#e8eefc",
    color: "#1d3f8f",
    border: "1px solid #b9c8ee",
  },
  ".cm-st-value-true": { background: "#d9f5dc", color: "#14692a", borderColor: "#7fcf8f" },
  ".cm-st-value-false": { background: "#eef0f3", color: "#555d6b", borderColor: "#c9ced6" },
  ".cm-st-value-forced": { outline: "2px solid #d0312d" },
  ".cm-st-value-tooltip": { padding: "2px 6px", fontFamily: "ui-monospace, monospace" },
});

/** The inline value widgets (fed by setInlineMarks), hover and the right-click menu on variables. */
export function stInlineValues(online: () => StOnlineView | undefined): Extension {
  return [
    inlineField,
    valueTheme,
    hoverTooltip((_view, pos) => {
      const o = occurrenceAt(online(), pos);
      if (!o) return null;
      return {
        pos: o.from,
        end: o.to,
        above: true,
        create: () => {
          const dom = document.createElement("div");
          dom.className = "cm-st-value-tooltip";
          dom.textContent = online()!.describe(o);
          return { dom };
        },
      };
    }),
    EditorView.domEventHandlers({
      contextmenu(event, view) {
        const pos = view.posAtCoords({ x: event.clientX, y: event.clientY });
        const o = pos === null ? undefined : occurrenceAt(online(), pos);
        if (!o) return false;
        event.preventDefault();
        online()!.onMenu(o, event.clientX, event.clientY);
        return true;
      },
    }),
  ];
}
