// The SFC editor's state machine as plain TypeScript (issue 19, as ld/editor/editorState.ts): the
// selected element and association row, which editor or overlay is open (a field of the properties
// panel, the new association form, the context menu, the shortcut help, the value prompt), the message,
// the zoom and the focus request last acted on. SfcEditor renders this state and dispatches the actions;
// the body and its undo history stay with the caller. The pure questions the editor asks of a body
// (what Enter edits, what Delete removes, what Copy takes, what Ctrl+Enter opens, what F9 toggles) live
// here too.
import type { SfcAction } from "../generated/api";
import type { MenuItem } from "../ui/MenuList";
import type { ValueRequest } from "../online/ValuePrompt";
import { zoomedTo, type ZoomStep } from "../ui/zoom";
import { kindOf, locate, type SfcBody, type SfcStep } from "./model";
import * as ops from "./ops";

/** The properties panel's field taking the keys: a step's name, a transition's condition, a jump's target. */
export type Editing = { kind: "name" | "condition" | "target"; id: string } | null;

export interface SfcEditorState {
  selected: string | null;
  /** The selected action association row of the selected step. */
  association: string | null;
  editing: Editing;
  /** The new association form is open. */
  associating: boolean;
  menu: { x: number; y: number; groups: MenuItem[][] } | null;
  valuePrompt: ValueRequest | null;
  message: string | null;
  help: boolean;
  zoom: number;
  /** The last focus request acted on (only a new one moves the selection). */
  focusSeen: number | null;
}

export const INITIAL_STATE: SfcEditorState = {
  selected: null,
  association: null,
  editing: null,
  associating: false,
  menu: null,
  valuePrompt: null,
  message: null,
  help: false,
  zoom: 1,
  focusSeen: null,
};

/** The zoom levels of the keys and buttons (CODESYS's list, trimmed to 50-200 %). */
export const ZOOM_LEVELS = [0.5, 0.67, 0.8, 1, 1.25, 1.5, 2];

export type SfcEditorAction =
  /** A click or the arrows: the element, no association row. */
  | { type: "select"; id: string | null }
  | { type: "selectAssociation"; step: string; row: string | null }
  /** An edit's outcome: its error as the message, or its selection (when it names one). */
  | { type: "edited"; result: ops.EditResult }
  | { type: "focus"; focus: { element?: string | null; seq: number } }
  | { type: "edit"; editing: Editing }
  | { type: "associating"; open: boolean }
  | { type: "menu"; menu: SfcEditorState["menu"] }
  | { type: "valuePrompt"; request: ValueRequest | null }
  | { type: "message"; text: string | null }
  | { type: "help"; open: boolean | "toggle" }
  | { type: "zoom"; step: ZoomStep }
  /** Fit: the zoom the editor measured (ui/zoom.ts fitZoom). */
  | { type: "zoomTo"; zoom: number };

export function sfcEditorReducer(state: SfcEditorState, action: SfcEditorAction): SfcEditorState {
  switch (action.type) {
    case "select":
      return { ...state, selected: action.id, association: null };
    case "selectAssociation":
      return { ...state, selected: action.step, association: action.row };
    case "edited": {
      const { result } = action;
      if ("error" in result) return { ...state, message: result.error };
      return { ...state, message: null, selected: result.select !== undefined ? result.select : state.selected };
    }
    case "focus": {
      const { focus } = action;
      if (focus.seq === state.focusSeen) return state;
      const seen = { ...state, focusSeen: focus.seq };
      return focus.element ? { ...seen, selected: focus.element } : seen;
    }
    case "edit":
      return { ...state, editing: action.editing };
    case "associating":
      return { ...state, associating: action.open };
    case "menu":
      return { ...state, menu: action.menu };
    case "valuePrompt":
      return { ...state, valuePrompt: action.request };
    case "message":
      return { ...state, message: action.text };
    case "help":
      return { ...state, help: action.open === "toggle" ? !state.help : action.open };
    case "zoom":
      return { ...state, zoom: zoomedTo(ZOOM_LEVELS, state.zoom, action.step) };
    case "zoomTo":
      return { ...state, zoom: action.zoom };
  }
}

/** What Enter, F2 and a double-click edit: a step's name, a transition's condition, a jump's target. */
export function editingOf(body: SfcBody, id: string | null): Editing {
  const element = id ? locate(body, id)?.element : undefined;
  const kind = element ? kindOf(element) : null;
  if (kind === "step") return { kind: "name", id: id! };
  if (kind === "transition") return { kind: "condition", id: id! };
  if (kind === "jump") return { kind: "target", id: id! };
  return null;
}

/** What Delete does: the selected association row, else the selected element with its partner; null: nothing. */
export function deletion(state: SfcEditorState, body: SfcBody): ops.EditResult | null {
  const { selected, association } = state;
  if (!selected) return null;
  const place = locate(body, selected);
  if (association && place) return ops.removeAssociation(body, place.element.id, association);
  return ops.remove(body, selected);
}

/** What Copy takes: the fragment from the selected element (null: nothing selected, or nothing to copy there). */
export function clipText(state: SfcEditorState, body: SfcBody): string | null {
  const fragment = state.selected ? ops.copyFragment(body, state.selected) : null;
  return fragment ? ops.serializeFragment(fragment) : null;
}

/** What Paste does with clip text: paste it below the selection, or the message saying why it cannot. */
export function pasting(state: SfcEditorState, body: SfcBody, text: string | null): ops.EditResult {
  const fragment = text ? ops.parseFragment(text) : null;
  if (!fragment) return { error: "The clipboard holds no SFC steps or transitions." };
  if (!state.selected) return { error: "Select where to paste first." };
  return ops.pasteFragment(body, state.selected, fragment);
}

/** The action Ctrl+Enter opens: the one the selected association row names, when the POU has it. */
export function openedAction(state: SfcEditorState, body: SfcBody): SfcAction | undefined {
  const element = state.selected ? locate(body, state.selected)?.element : undefined;
  const row =
    element && kindOf(element) === "step"
      ? (element as SfcStep).actions?.find((a) => a.id === state.association)
      : undefined;
  return row ? body.actions?.find((a) => a.name.toUpperCase() === row.action.toUpperCase()) : undefined;
}

/** Whether an element can hold a breakpoint (steps and transitions; not divergences or jumps). */
export function breakable(body: SfcBody, id: string | null): boolean {
  const element = id ? locate(body, id)?.element : undefined;
  const kind = element ? kindOf(element) : null;
  return kind === "step" || kind === "transition";
}
