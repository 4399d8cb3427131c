// The LD editor's state machine as plain TypeScript (issue 19): what is selected and from which
// anchor, which overlay is open (operand or network editor, box picker, context menu, shortcut help,
// value prompt, IL view), the message and the "declare variable" offer, the zoom, the drag, and the
// network to scroll into view. LdEditor renders this state and dispatches the actions; the diagram
// body and its undo history stay with the caller. The pure questions the editor asks of a body
// (which operand Enter edits, an operand's text, what to copy, where to paste) live here too.
import type { LibraryEntry } from "../../generated/api";
import type { Clip } from "../clipboard";
import { locate, networksOf, type LdBody, type Place } from "../model";
import type { EditResult, OperandField } from "../ops";
import type { Selection } from "../view/types";
import { selectedNetwork } from "./commands";
import type { VariableDeclaration } from "./declare";
import type { ValueRequest } from "../../online/ValuePrompt";
import { zoomed, type ZoomStep } from "../../ui/zoom";

export type Editing =
  | { kind: "operand"; id: string; field: OperandField; x: number; y: number }
  | { kind: "network"; id: string; field: "label" | "comment"; x: number; y: number };

export interface LdEditorState {
  selection: Selection | null;
  /** Where Shift+click and Shift+arrow ranges start: the first element selected. */
  anchor: string | null;
  editing: Editing | null;
  picker: boolean;
  menu: { x: number; y: number } | null;
  message: string | null;
  offer: VariableDeclaration | null;
  /** A drag has travelled far enough: the slots are drop targets. */
  dropping: boolean;
  help: boolean;
  zoom: number;
  /** An element whose operand editor opens once the edit that created it has been laid out. */
  pendingEdit: string | null;
  valuePrompt: ValueRequest | null;
  /** The network shown as IL ("View as IL"), or null. */
  asIl: string | null;
  /**
   * The network to scroll into view: where the keyboard, an edit or a focus request moved the
   * selection. A click does not scroll (the diagram would move under the pointer between the two
   * clicks of a double-click).
   */
  reveal: string | null;
  /** The last focus request acted on (only a new one moves the selection). */
  focusSeen: number | null;
}

export const INITIAL_STATE: LdEditorState = {
  selection: null,
  anchor: null,
  editing: null,
  picker: false,
  menu: null,
  message: null,
  offer: null,
  dropping: false,
  help: false,
  zoom: 1,
  pendingEdit: null,
  valuePrompt: null,
  asIl: null,
  reveal: null,
  focusSeen: null,
};

export type LdEditorAction =
  /** `anchor` undefined: the first selected element (none for a place or network). */
  | { type: "select"; selection: Selection | null; anchor?: string | null }
  /** Select and scroll to the selection's network in `body`. */
  | { type: "reveal"; selection: Selection | null; body: LdBody; anchor?: string | null }
  /** An edit's outcome: its error as the message, or its selection (edited elements or network) revealed. */
  | { type: "edited"; result: EditResult; then?: "edit" }
  /** A focus request (a diagnostic was clicked): selects its element, else its network, once per `seq`. */
  | { type: "focus"; focus: { network?: string | null; element?: string | null; seq: number }; body: LdBody }
  | { type: "edit"; editing: Editing | null }
  | { type: "pendingEditDone" }
  | { type: "picker"; open: boolean }
  | { type: "menu"; at: { x: number; y: number } | null }
  | { type: "message"; text: string | null }
  | { type: "offer"; offer: VariableDeclaration | null }
  | { type: "dropping"; dropping: boolean }
  | { type: "help"; open: boolean | "toggle" }
  | { type: "zoom"; step: ZoomStep }
  /** Fit: the zoom the editor measured (ui/zoom.ts fitZoom). */
  | { type: "zoomTo"; zoom: number }
  | { type: "valuePrompt"; request: ValueRequest | null }
  | { type: "asIl"; network: string | null };

function select(state: LdEditorState, selection: Selection | null, anchor?: string | null): LdEditorState {
  const first = selection?.kind === "elements" ? selection.ids[0]! : null;
  return { ...state, selection, anchor: anchor !== undefined ? anchor : first };
}

function reveal(state: LdEditorState, selection: Selection | null, body: LdBody, anchor?: string | null) {
  return { ...select(state, selection, anchor), reveal: selectedNetwork({ body, selection }) ?? null };
}

export function ldEditorReducer(state: LdEditorState, action: LdEditorAction): LdEditorState {
  switch (action.type) {
    case "select":
      return select(state, action.selection, action.anchor);
    case "reveal":
      return reveal(state, action.selection, action.body, action.anchor);
    case "edited": {
      const { result } = action;
      if (!result.ok) return { ...state, message: result.error };
      const next = { ...state, message: null, pendingEdit: action.then === "edit" ? (result.select[0] ?? null) : null };
      const [first] = result.select;
      if (first === undefined) return select(next, null);
      if (networksOf(result.body).some((n) => n.id === first))
        return reveal(next, { kind: "network", id: first }, result.body);
      return reveal(next, { kind: "elements", ids: result.select }, result.body);
    }
    case "focus": {
      const { focus, body } = action;
      if (focus.seq === state.focusSeen) return state;
      const seen = { ...state, focusSeen: focus.seq };
      if (focus.element && locate(body, focus.element))
        return reveal(seen, { kind: "elements", ids: [focus.element] }, body);
      if (focus.network && networksOf(body).some((n) => n.id === focus.network))
        return reveal(seen, { kind: "network", id: focus.network }, body);
      return seen;
    }
    case "edit":
      return { ...state, editing: action.editing };
    case "pendingEditDone":
      return { ...state, pendingEdit: null };
    case "picker":
      return { ...state, picker: action.open };
    case "menu":
      return { ...state, menu: action.at };
    case "message":
      return { ...state, message: action.text };
    case "offer":
      return { ...state, offer: action.offer };
    case "dropping":
      return { ...state, dropping: action.dropping };
    case "help":
      return { ...state, help: action.open === "toggle" ? !state.help : action.open };
    case "zoom":
      return { ...state, zoom: zoomed(state.zoom, action.step) };
    case "zoomTo":
      return { ...state, zoom: action.zoom };
    case "valuePrompt":
      return { ...state, valuePrompt: action.request };
    case "asIl":
      return { ...state, asIl: action.network };
  }
}

/** The selection with what an undo removed dropped, rather than left dangling. */
export function liveSelection(body: LdBody, selection: Selection | null): Selection | null {
  if (!selection) return null;
  if (selection.kind === "elements") {
    const ids = selection.ids.filter((id) => locate(body, id));
    return ids.length ? { kind: "elements", ids } : null;
  }
  if (selection.kind === "network") return networksOf(body).some((n) => n.id === selection.id) ? selection : null;
  return selection;
}

/** The operand Enter edits: the variable, a compare's left side, a box's instance or first free input, a jump's target. */
export function mainField(
  body: LdBody,
  id: string,
  library: (call: string) => LibraryEntry | undefined,
): OperandField | undefined {
  const e = locate(body, id)?.element;
  switch (e?.type) {
    case "contact":
    case "coil":
      return { kind: "var" };
    case "compare":
      return { kind: "left" };
    case "jump":
      return { kind: "target" };
    case "box": {
      const entry = library(e.call);
      if (!entry || entry.kind === "function_block") return { kind: "instance" };
      const pin = entry.inputs.find((p) => p.type.toUpperCase() !== "BOOL") ?? entry.inputs[0];
      return pin ? { kind: "input", pin: pin.name } : undefined;
    }
    default:
      return undefined;
  }
}

export function operandText(body: LdBody, id: string, field: OperandField): string {
  const e = locate(body, id)?.element;
  if (!e) return "";
  if (field.kind === "var" && (e.type === "contact" || e.type === "coil")) return e.var;
  if (field.kind === "left" && e.type === "compare") return e.left;
  if (field.kind === "right" && e.type === "compare") return e.right;
  if (field.kind === "target" && e.type === "jump") return e.target;
  if (e.type === "box") {
    if (field.kind === "instance") return e.instance ?? "";
    if (field.kind === "input") {
      const value = e.inputs?.[field.pin];
      return typeof value === "string" ? value : "";
    }
    if (field.kind === "output") return e.outputs?.[field.pin] ?? "";
  }
  return "";
}

/** The variable an element is about, for online commands and dragging to the watch list. */
export function variableOf(body: LdBody, id: string): string | null {
  const e = locate(body, id)?.element;
  const text =
    e?.type === "contact" || e?.type === "coil"
      ? e.var
      : e?.type === "compare"
        ? e.left
        : e?.type === "box"
          ? (e.instance ?? "")
          : "";
  return text.trim() || null;
}

/**
 * The variable a double-click online prepares a value for, with its type when the diagram knows it:
 * a contact's or coil's (a BOOL), a compare's left side, or at a box pin's value (`pin`: its key,
 * `in:PT`) the FB instance's pin or the pin's variable (the pin's declared type).
 */
export function valueOperand(
  body: LdBody,
  id: string,
  pin: string | null,
  library: (call: string) => LibraryEntry | undefined,
): { operand: string; type?: string } | null {
  const e = locate(body, id)?.element;
  if (e?.type !== "box" || !pin) {
    const operand = variableOf(body, id);
    return operand ? { operand, type: e?.type === "contact" || e?.type === "coil" ? "BOOL" : undefined } : null;
  }
  const [side, name] = pin.split(":") as ["in" | "out", string];
  const entry = library(e.call);
  const declared = entry
    ? [...entry.inputs, ...entry.in_outs, ...entry.outputs].find((p) => p.name.toUpperCase() === name)
    : undefined;
  if (entry?.kind === "function_block" && e.instance?.trim() && declared)
    return { operand: `${e.instance.trim()}.${name}`, type: declared.type };
  const pins = side === "in" ? (e.inputs ?? {}) : (e.outputs ?? {});
  const operand = Object.entries(pins).find(([n]) => n.toUpperCase() === name)?.[1];
  return typeof operand === "string" && operand.trim() ? { operand: operand.trim(), type: declared?.type } : null;
}

/** What Copy takes: the selected network, or the selected elements; null for nothing or a place. */
export function clipOf(body: LdBody, selection: Selection | null): Clip | null {
  if (selection?.kind === "network") {
    const network = networksOf(body).find((n) => n.id === selection.id);
    return network ? { kind: "networks", networks: [network] } : null;
  }
  if (selection?.kind === "elements") {
    const elements = selection.ids.map((id) => locate(body, id)?.element).filter((e) => e !== undefined);
    return elements.length ? { kind: "elements", elements } : null;
  }
  return null;
}

/** Where pasted elements go: the selected wire, after the last selected element, or at a selected network's start. */
export function pastePlace(body: LdBody, selection: Selection | null): Place | undefined {
  if (selection?.kind === "place") return selection.place;
  if (selection?.kind === "elements") {
    const at = locate(body, selection.ids[selection.ids.length - 1]!);
    return at ? { series: at.series, index: at.index + 1 } : undefined;
  }
  if (selection?.kind === "network") return { series: { kind: "network", network: selection.id }, index: 0 };
  return undefined;
}

export const fieldLabel = (field: OperandField) =>
  field.kind === "input" || field.kind === "output"
    ? `Pin ${field.pin}`
    : { var: "Variable", left: "Left operand", right: "Right operand", instance: "Instance", target: "Jump target" }[
        field.kind
      ];
