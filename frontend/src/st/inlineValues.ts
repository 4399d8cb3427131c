// ST online mode (like CODESYS): every occurrence of a variable with a value (elementary type,
// reached through FB instances and struct fields, and array elements whose index is a variable or a
// number: `a[i]`, ON-12) gets its simulation path; the editor shows the monitor's value after it as
// a widget (forced and prepared values marked as everywhere else), describes it on hover, prepares a
// value on a double-click and opens the online commands on a right click. Occurrences come from the
// highlighter's tokens, so comments, strings, keywords, function names and formal parameter names
// (`IN :=`) are never taken for variables. An element with an expression index (`a[i + 1]`) shows none.
// A pointer or REF_TO shows its own value as the monitor sends it (`ADR(a[2])`, NULL; ON-11), a bit or part of
// an integer or bit string (`w.%X3`, `w.3`, `d.%B1`) the part's value, a path of its own (`MAIN.W.%X3`).
import { StateEffect, StateField, type Extension } from "@codemirror/state";
import { Decoration, EditorView, hoverTooltip, WidgetType, type DecorationSet } from "@codemirror/view";
import { operandPath } from "../online/monitor";
import { pathKey, type MonitorState } from "../online/monitor";
import type { Value } from "../online/protocol";
import { preparedText, shownOf, type Prepared, type ValueShown } from "../online/shown";
import { valueTagClass } from "../online/ValueTag";
import { formatValue } from "../online/values";
import { partBits } from "../iec/vocabulary";
import { tokenize } from "./language";
import { ARRAY_TYPE, membersOf, typeOfChain, type Scope } from "./members";

/** An array element `a[i, 2]`: each index (a variable's path or a number) and the array's lower bounds. */
export interface ElementAccess {
  indices: ({ path: string } | { value: number })[];
  lows: number[];
}

export interface Occurrence {
  from: number;
  to: number;
  /** The access as written, e.g. `Timer.Q` or `arr[i]`. */
  text: string;
  /**
   * Canonical simulation path (upper case), e.g. `MAIN.TIMER.Q` or `ALARM` (a global, as the server
   * names it); for an array element, the array's (the element is picked from its value).
   */
  path: string;
  type: string;
  /** Set for an array element: how to pick it. */
  element?: ElementAccess;
}

/** A type whose variables have one value to show (not an FB, a struct or an array); a pointer's is what it holds. */
const hasValue = (type: string, scope: Scope) => membersOf(type, scope) === null && !/^\s*ARRAY\b/i.test(type);

/** Part letters: their width in bits and type (ST's partial access, IEC 61131-3 ed. 3, 6.5.6). */
const PARTS: Readonly<Record<string, readonly [number, string]>> = {
  X: [1, "BOOL"],
  B: [8, "BYTE"],
  W: [16, "WORD"],
  D: [32, "DWORD"],
  L: [64, "LWORD"],
};

/**
 * The bit or part selected after a variable of type `type` from token `dot` on (`.%X3`, `.3`, `.%B1`): its path
 * suffix as the server names it (`.%X3`), its type and its last token; null when none is, or it lies outside.
 */
function partAfter(
  tokens: readonly Token[],
  dot: number,
  type: string,
): { suffix: string; type: string; last: number } | null {
  const bits = partBits(type);
  const first = tokens[dot + 1];
  if (bits === null || tokens[dot]?.text !== "." || !first) return null;
  const short = /^\d+$/.test(first.text) && first.style === "number";
  const named =
    first.text === "%" && tokens[dot + 2]?.from === first.to ? /^([XBWDL])(\d+)$/i.exec(tokens[dot + 2]!.text) : null;
  if (!short && !named) return null;
  const [letter, index] = named ? [named[1]!.toUpperCase(), Number(named[2])] : ["X", Number(first.text)];
  const [width, partType] = PARTS[letter]!;
  if ((index + 1) * width > bits) return null; // the checker reports it
  return { suffix: `.%${letter}${index}`, type: partType, last: named ? dot + 2 : dot + 1 };
}

/** An array type's lower bounds and element type, when its bounds are numbers. */
function arrayOf(type: string): { lows: number[]; element: string } | null {
  const match = ARRAY_TYPE.exec(type);
  if (!match) return null;
  const lows = match[1]!.split(",").map((d) => Number(d.split("..")[0]!.trim()));
  return lows.every(Number.isInteger) ? { lows, element: match[2]! } : null;
}

type Token = ReturnType<typeof tokenize>[number];

/**
 * The indices of `[...]` opening at token `open` when each is a variable (with a value) or an
 * integer, and the token of its `]`; null for an expression index.
 */
function plainIndices(
  tokens: readonly Token[],
  open: number,
  scope: Scope,
  instance: string,
  hidden: ReadonlySet<string>,
): { indices: ElementAccess["indices"]; close: number } | null {
  const indices: ElementAccess["indices"] = [];
  for (let i = open + 1; ; i += 2) {
    const t = tokens[i];
    if (!t) return null;
    if (t.style === "variableName") {
      const type = hidden.has(t.text.toUpperCase()) ? null : typeOfChain([t.text], scope);
      const path = type !== null && hasValue(type, scope) ? operandPath(t.text, instance, scope.symbols) : null;
      if (!path) return null;
      indices.push({ path });
    } else if (/^[+-]?\d+$/.test(t.text)) indices.push({ value: Number(t.text) });
    else return null;
    const next = tokens[i + 1]?.text;
    if (next === "]") return { indices, close: i + 1 };
    if (next !== ",") return null;
  }
}

/** `THIS^.` or `SUPER^.` opening at token `i` (an FB's or method's own instance, ST-OO): the token after it, else i. */
function pastSelf(tokens: readonly Token[], i: number): number {
  const self = /^(THIS|SUPER)$/i.test(tokens[i]!.text) && tokens[i + 1]?.text === "^" && tokens[i + 2]?.text === ".";
  return self && tokens[i + 3]?.style === "variableName" ? i + 3 : i;
}

const NONE: ReadonlySet<string> = new Set();

/**
 * Every variable occurrence in `text` with a value, as paths of POU instance `instance`; a bare name in `hidden`
 * (upper case: a method's own variable, methodScope.ts) is not the instance's, `THIS^.x` and `SUPER^.x` are.
 */
export function variableOccurrences(
  text: string,
  scope: Scope,
  instance: string,
  hidden: ReadonlySet<string> = NONE,
): Occurrence[] {
  const tokens = tokenize(text).filter((t) => t.style !== null);
  const out: Occurrence[] = [];
  let depth = 0;
  for (let i = 0; i < tokens.length; i++) {
    const t = tokens[i]!;
    if (t.text === "(") depth += 1;
    else if (t.text === ")") depth = Math.max(0, depth - 1);
    if (t.style !== "variableName" || tokens[i - 1]?.text === ".") continue; // a member (`rp^.x`, `a[i].x`)
    const start = pastSelf(tokens, i);
    const chain = [tokens[start]!.text];
    let end = start;
    while (tokens[end + 1]?.text === "." && tokens[end + 2]?.style === "variableName") {
      chain.push(tokens[end + 2]!.text);
      end += 2;
    }
    const next = tokens[end + 1]?.text;
    if (start === i && hidden.has(t.text.toUpperCase())) {
      i = end; // the member's own (`own.x` too): not the instance's
      continue;
    }
    const formal = depth > 0 && chain.length === 1 && (next === ":=" || next === "=>");
    const type = formal ? null : typeOfChain(chain, scope);
    const path = type !== null ? operandPath(chain.join("."), instance, scope.symbols) : null;
    const part = path && type ? partAfter(tokens, end + 1, type) : null;
    if (path && part) {
      const to = tokens[part.last]!.to;
      out.push({ from: t.from, to, text: text.slice(t.from, to), path: `${path}${part.suffix}`, type: part.type });
      i = part.last;
      continue;
    }
    if (path && type && hasValue(type, scope))
      out.push({ from: t.from, to: tokens[end]!.to, text: text.slice(t.from, tokens[end]!.to), path, type });
    const array = path && type && next === "[" ? arrayOf(type) : null;
    const index = array ? plainIndices(tokens, end + 1, scope, instance, hidden) : null;
    if (path && array && index && index.indices.length === array.lows.length && tokens[index.close + 1]?.text !== ".") {
      const to = tokens[index.close]!.to;
      const element = { indices: index.indices, lows: array.lows };
      out.push({ from: t.from, to, text: text.slice(t.from, to), path, type: array.element, element });
    }
    i = end;
  }
  return out;
}

export interface InlineMark {
  /** Document offset the value is shown at (the end of the occurrence). */
  pos: number;
  shown: ValueShown;
  /** IL: the accumulator after the line that ends at `pos` (shown as "CR value"). */
  accumulator?: boolean;
}

/** The numbers an element's indices stand for now; null while one is unknown. */
function indexValues(element: ElementAccess, values: MonitorState["values"]): number[] | null {
  const numbers = element.indices.map((i) => ("value" in i ? i.value : values[i.path]));
  return numbers.every((n): n is number => typeof n === "number") ? numbers : null;
}

/** The path of the variable an occurrence names now (`MAIN.ARR[3]` for `arr[i]`); null while an index is unknown. */
export function concretePath(o: Occurrence, values: MonitorState["values"]): string | null {
  if (!o.element) return o.path;
  const numbers = indexValues(o.element, values);
  return numbers ? `${o.path}[${numbers.join(", ")}]` : null;
}

/** The value an occurrence has now (an array element picked from its array's value); undefined when unknown. */
function valueOf(o: Occurrence, values: MonitorState["values"]): Value | undefined {
  const value = values[o.path];
  const element = o.element;
  if (!element) return value;
  const numbers = indexValues(element, values);
  if (!numbers) return undefined;
  let item: Value | undefined = value;
  numbers.forEach((n, d) => {
    item = Array.isArray(item) ? (item[n - element.lows[d]!] as Value | undefined) : undefined;
  });
  return item === null || typeof item === "object" ? undefined : item;
}

/** What an occurrence shows now: its value, forced, prepared; null when unknown. */
export function shownOccurrence(o: Occurrence, monitor: MonitorState, prepared: Prepared = {}): ValueShown | null {
  const value = valueOf(o, monitor.values);
  if (value === undefined) return null;
  const path = pathKey(concretePath(o, monitor.values) ?? o.path);
  const type = o.element ? o.type : (monitor.types[o.path] ?? o.type);
  return { ...shownOf(value, type), forced: monitor.forced.has(path), prepared: preparedText(prepared[path], type) };
}

/** The values to show: one per occurrence whose value the monitor has. */
export function inlineMarks(
  occurrences: readonly Occurrence[],
  monitor: MonitorState,
  prepared: Prepared = {},
): InlineMark[] {
  return occurrences.flatMap((o) => {
    const shown = shownOccurrence(o, monitor, prepared);
    return shown ? [{ pos: o.to, shown }] : [];
  });
}

/** What hover says about an occurrence: access, type, value, and whether it is forced or has a prepared value. */
export function describe(o: Occurrence, monitor: MonitorState, prepared: Prepared = {}): string {
  const shown = shownOccurrence(o, monitor, prepared);
  const forced = shown?.forced ? " (forced)" : "";
  const ready = shown && shown.prepared !== null ? `, prepared ${shown.prepared}` : "";
  return `${o.text} : ${o.type} = ${shown?.text ?? formatValue(undefined)}${forced}${ready}`;
}

class ValueWidget extends WidgetType {
  constructor(readonly mark: InlineMark) {
    super();
  }
  override eq(other: ValueWidget) {
    const [a, b] = [this.mark.shown, other.mark.shown];
    return (
      a.text === b.text &&
      a.bool === b.bool &&
      a.forced === b.forced &&
      a.prepared === b.prepared &&
      this.mark.accumulator === other.mark.accumulator
    );
  }
  override toDOM() {
    const { shown } = this.mark;
    const span = document.createElement("span");
    span.className = `cm-st-value ${valueTagClass(shown)}${this.mark.accumulator ? " cm-il-accumulator" : ""}`;
    if (this.mark.accumulator) span.title = "The accumulator (current result) after this line";
    if (!this.mark.accumulator) span.dataset.pos = String(this.mark.pos); // no variable's menu on the CR
    span.textContent = shown.text;
    if (shown.forced) {
      const mark = document.createElement("span");
      mark.className = "forced-mark";
      mark.textContent = "F";
      span.append(mark);
    }
    if (shown.prepared === null) return span;
    const wrap = document.createElement("span");
    const prepared = document.createElement("span");
    prepared.className = "prepared-tag";
    prepared.textContent = `<${shown.prepared}>`;
    wrap.append(span, prepared);
    return wrap;
  }
  /** Double-clicks and right-clicks on a value reach the editor's handlers (prepare, the menu). */
  override ignoreEvent() {
    return false;
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
  /** A double-click on an occurrence or its value: prepare a value for it (CODESYS). */
  onPrepare(o: Occurrence): void;
}

const occurrenceAt = (view: StOnlineView | undefined, pos: number) =>
  view?.occurrences.find((o) => o.from <= pos && pos <= o.to);

/** Values as small tags after their variable, in the classes of every other view (styles.css, value-tag). */
const valueTheme = EditorView.baseTheme({
  ".cm-st-value": { marginLeft: "2px", fontSize: "85%" },
  ".cm-il-accumulator": { marginLeft: "1.5em" },
  ".cm-il-accumulator::before": { content: '"CR "', opacity: 0.7 },
  ".cm-st-value-tooltip": { padding: "2px 6px", fontFamily: "ui-monospace, monospace" },
});

/** The occurrence of a mouse event: the one whose value widget was hit, else the one under the pointer. */
function occurrenceOfEvent(event: MouseEvent, view: EditorView, online: StOnlineView | undefined) {
  const widget = (event.target as HTMLElement).closest?.(".cm-st-value") as HTMLElement | null;
  const pos = widget?.dataset.pos
    ? Number(widget.dataset.pos)
    : view.posAtCoords({ x: event.clientX, y: event.clientY });
  return pos === null ? undefined : occurrenceAt(online, pos);
}

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
        const o = occurrenceOfEvent(event, view, online());
        if (!o) return false;
        event.preventDefault();
        online()!.onMenu(o, event.clientX, event.clientY);
        return true;
      },
      dblclick(event, view) {
        const o = occurrenceOfEvent(event, view, online());
        if (!o) return false;
        event.preventDefault();
        online()!.onPrepare(o);
        return true;
      },
    }),
  ];
}
