// The SFC editor: the chart drawn from its structure (layout.ts, so every chart it draws is well formed),
// the toolbar and keys of the keymap's "sfc" scope (insert a step and a transition below, alternative and
// simultaneous branches, jump, associate an action with its qualifier, delete, copy/paste through the system
// clipboard, undo/redo, zoom and fit), arrow-key navigation across the chart, and a properties panel for the
// selection (step name, action associations with the qualifier picker and time, entry and exit actions, time
// limits; a transition's condition and priority; a jump's target). The actions and named transitions are listed
// below; "Open" shows one in its own editor (the caller's). The undo history is the caller's (one per POU).
// Its state machine is sfc/editorState.ts; the root's keys and clipboard are ui/useEditorRoot.ts.
import { useCallback, useEffect, useMemo, useReducer, useRef, useState, type MouseEvent, type ReactNode } from "react";
import type { Diagnostic } from "../generated/api";
import type { SfcAction, SfcNamedTransition } from "../generated/api";
import { MenuList, type MenuItem } from "../ui/MenuList";
import type { LdOnlineActions } from "../online/operandCommands";
import { OperandValuePrompt } from "../online/ValuePrompt";
import { canRedo, canUndo, record, redo, undo, type History } from "../store/history";
import { onlineOperandItems } from "../online/operandCommands";
import { keysOf, type CommandOf } from "../keys/keymap";
import { ShortcutHelp } from "../keys/ShortcutHelp";
import type { LastClip } from "../ui/systemClipboard";
import { useEditorRoot, type KeyHandlers } from "../ui/useEditorRoot";
import { fitZoom } from "../ui/zoom";
import {
  breakable,
  clipText,
  deletion,
  editingOf,
  INITIAL_STATE,
  openedAction,
  pasting,
  sfcEditorReducer,
  ZOOM_LEVELS,
  type Editing,
} from "./editorState";
import { layoutChart, neighbour, type Direction } from "./layout";
import {
  QUALIFIERS,
  QUALIFIER_TEXT,
  TIMED,
  chartOf,
  kindOf,
  locate,
  steps,
  type Qualifier,
  type SfcBody,
  type SfcStep,
  type SfcTransition,
} from "./model";
import * as ops from "./ops";
import { SfcDiagram, type SfcMarks, type SfcOnlineView } from "./SfcDiagram";
import "./sfc.css";
import { OverflowBar, helpItem, toolItem, type BarItem } from "../ui/OverflowBar";
import { COMMAND_ICONS } from "../ui/icons";

/** How long a tool stays in the toolbar as it narrows (the chart tools default to 2): higher stays longer. */
const TOOL_PRIORITY: Partial<Record<string, number>> = {
  "insert-step": 3,
  copy: 0,
  paste: 0,
  "zoom-in": 1,
  "zoom-out": 1,
  "zoom-fit": 1,
};

export type SfcPart = { kind: "action" | "transition"; name: string };

export interface SfcEditorProps {
  history: History<SfcBody>;
  onHistoryChange(history: History<SfcBody>): void;
  /** Variables an association may name besides the actions (the POU's BOOLs). */
  variables?: readonly string[];
  diagnostics?: readonly Diagnostic[];
  online?: SfcOnlineView;
  /** Editing is off (online); the reason is shown. */
  readOnly?: string | null;
  readOnlyActions?: ReactNode;
  /** Shows an action or named transition in its editor. */
  onOpen?(part: SfcPart): void;
  /** Breakpoints on steps and transitions (the caller's debug store). */
  debugging?: { marks: SfcMarks; toggle(element: string): void };
  /** Online: write, force and release a step's flag `<step>.X` (operands relative to the shown instance). */
  onlineActions?: LdOnlineActions;
  /** Extra controls in the toolbar (online: step to the next transition). */
  toolbarExtra?: ReactNode;
  focus?: { element?: string | null; seq: number } | null;
}

type Command = CommandOf<"sfc">;

const ARROWS: Record<string, Direction> = { ArrowUp: "up", ArrowDown: "down", ArrowLeft: "left", ArrowRight: "right" };
/** Room kept around a fitted chart for the scroll area's edges. */
const FIT_MARGIN = 8;
/** The last fragment copied in this tab (the browser may keep its clipboard closed to the toolbar's Paste). */
const lastClip: LastClip = { text: null };

export function SfcEditor(props: SfcEditorProps) {
  const { history, onHistoryChange, readOnly } = props;
  const body = history.present;
  const elements = chartOf(body);
  const [state, dispatch] = useReducer(sfcEditorReducer, INITIAL_STATE);
  const { selected, association, message, zoom, help, editing, associating, menu, valuePrompt } = state;
  const root = useRef<HTMLDivElement>(null);
  const scroll = useRef<HTMLDivElement>(null);
  const layout = useMemo(() => layoutChart(elements), [elements]);
  const place = selected ? locate(body, selected) : undefined;
  const setMessage = (text: string | null) => dispatch({ type: "message", text });
  const select = (id: string | null) => dispatch({ type: "select", id });

  // A diagnostic clicked elsewhere selects its element here (while rendering, as the request arrives).
  if (props.focus && props.focus.seq !== state.focusSeen) dispatch({ type: "focus", focus: props.focus });

  const apply = useCallback(
    (result: ops.EditResult) => {
      const ok = !("error" in result);
      if (ok) onHistoryChange(record(history, result.body));
      dispatch({ type: "edited", result });
      return ok;
    },
    [history, onHistoryChange],
  );
  const editable = !readOnly;
  const need = (fn: (id: string) => ops.EditResult) => () => {
    if (!editable) return false;
    if (!selected && elements.length) {
      setMessage("Select an element of the chart first.");
      return true;
    }
    return apply(fn(selected ?? "")) || true;
  };

  /** Zoom so the whole chart fits the scroll area (ui/zoom.ts). */
  const fit = () => {
    const view = scroll.current;
    if (!view) return false;
    const room = { width: view.clientWidth - FIT_MARGIN, height: view.clientHeight - FIT_MARGIN };
    dispatch({ type: "zoomTo", zoom: fitZoom(layout, room) });
    return true;
  };

  const handlers: KeyHandlers<"sfc"> = {
    "insert-step": () => editable && apply(ops.insertBelow(body, selected)),
    alternative: need((id) => ops.addAlternative(body, id)),
    parallel: need((id) => ops.addParallel(body, id)),
    jump: need((id) => ops.addJump(body, id)),
    associate: () => {
      if (!editable || !place || kindOf(place.element) !== "step") return false;
      dispatch({ type: "associating", open: true });
      return true;
    },
    edit: () => {
      const next = editable ? editingOf(body, selected) : null;
      if (next) dispatch({ type: "edit", editing: next });
      return next !== null;
    },
    open: () => {
      const action = openedAction(state, body);
      if (!action || !props.onOpen) return false;
      props.onOpen({ kind: "action", name: action.name });
      return true;
    },
    delete: () => {
      const result = editable ? deletion(state, body) : null;
      if (!result) return false;
      const removesElement = !association || !place;
      return apply(result) && (removesElement && select(null), true);
    },
    "delete-branch": () => (editable && selected ? apply(ops.removeBranch(body, selected)) : false),
    undo: () => editable && canUndo(history) && (onHistoryChange(undo(history)), true),
    redo: () => editable && canRedo(history) && (onHistoryChange(redo(history)), true),
    "zoom-in": () => (dispatch({ type: "zoom", step: "in" }), true),
    "zoom-out": () => (dispatch({ type: "zoom", step: "out" }), true),
    "zoom-reset": () => (dispatch({ type: "zoom", step: "reset" }), true),
    "zoom-fit": fit,
    "move-selection": () => false, // the arrows are handled with their direction (keyHandlers)
    "clear-selection": () => (select(null), true),
    "toggle-breakpoint": () => {
      if (!props.debugging || !breakable(body, selected)) return false;
      props.debugging.toggle(selected!);
      return true;
    },
  };
  const keyHandlers = (event: { key: string }): KeyHandlers<"sfc"> => ({
    ...handlers,
    "move-selection": () => (select(neighbour(layout, selected, ARROWS[event.key]!)), true),
  });

  const editor = useEditorRoot({
    root,
    scope: "sfc",
    handlers: keyHandlers,
    clipboard: {
      take: (cut) => {
        const text = clipText(state, body);
        if (text !== null && cut && editable) apply(ops.remove(body, selected!));
        return text;
      },
      paste: (text) => apply(pasting(state, body, text)),
      isClip: (text) => ops.parseFragment(text) !== null,
      locked: !editable,
    },
    last: lastClip,
    onZoom: (step) => dispatch({ type: "zoom", step }),
  });

  /** The context menu of a step or transition: its breakpoint; online, a step's flag X (write, force, watch). */
  const openMenu = (id: string, event: MouseEvent) => {
    const element = locate(body, id)?.element;
    if (!element || !breakable(body, id)) return;
    event.preventDefault();
    select(id);
    const groups: MenuItem[][] = [];
    const { onlineActions, debugging } = props;
    if (kindOf(element) === "step" && onlineActions) {
      const operand = `${(element as SfcStep).name}.X`;
      groups.push(
        onlineOperandItems(operand, onlineActions, (action) =>
          dispatch({ type: "valuePrompt", request: { operand, action } }),
        ),
      );
    }
    if (debugging)
      groups.push([
        {
          id: "breakpoint",
          label: debugging.marks.breakpoints.has(id) ? "Remove breakpoint" : "Set breakpoint",
          keys: keysOf("sfc", "toggle-breakpoint") || undefined,
          run: () => debugging.toggle(id),
        },
      ]);
    if (!groups.length) return;
    const box = root.current?.getBoundingClientRect();
    dispatch({
      type: "menu",
      menu: { x: event.clientX - (box?.left ?? 0), y: event.clientY - (box?.top ?? 0), groups },
    });
  };

  const toolbar: { label: string; command: Command; enabled: boolean }[] = [
    { label: "Step + transition", command: "insert-step", enabled: editable },
    { label: "Alternative branch", command: "alternative", enabled: editable && !!place },
    { label: "Simultaneous branch", command: "parallel", enabled: editable && !!place },
    { label: "Jump", command: "jump", enabled: editable && !!place },
    {
      label: "Associate action",
      command: "associate",
      enabled: editable && !!place && kindOf(place.element) === "step",
    },
    { label: "Delete", command: "delete", enabled: editable && !!place },
    { label: "Copy", command: "copy", enabled: !!place },
    { label: "Paste", command: "paste", enabled: editable && !!place },
    { label: "Undo", command: "undo", enabled: editable && canUndo(history) },
    { label: "Redo", command: "redo", enabled: editable && canRedo(history) },
    { label: "Zoom in", command: "zoom-in", enabled: zoom < ZOOM_LEVELS[ZOOM_LEVELS.length - 1]! },
    { label: "Zoom out", command: "zoom-out", enabled: zoom > ZOOM_LEVELS[0]! },
    { label: "Zoom to fit", command: "zoom-fit", enabled: elements.length > 0 },
  ];

  // One row (ui/OverflowBar.tsx): as it narrows, zoom and clipboard go into More first, the chart tools last.
  const toolbarItems: BarItem[] = [
    // eslint-disable-next-line react-hooks/refs -- toolItem keeps `run` for the click and the More entry, never calls it
    ...toolbar.map(({ label, command, enabled }, i) =>
      toolItem(
        {
          id: command,
          icon: COMMAND_ICONS[command === "parallel" ? "sfc-parallel" : command]!,
          label,
          keys: keysOf("sfc", command) || undefined,
          disabled: !enabled,
          run: () => {
            if (command === "copy" || command === "cut") editor.copy(command === "cut");
            else if (command === "paste") editor.paste();
            // eslint-disable-next-line react-hooks/refs -- runs on a click or a More entry, not during render
            else handlers[command]();
            editor.focus();
          },
        },
        { group: i === 0 || command === "copy" || command === "zoom-in", priority: TOOL_PRIORITY[command] ?? 2 },
      ),
    ),
    {
      key: "zoom",
      node: (
        <span className="sfc-zoom" aria-label="Zoom">
          {Math.round(zoom * 100)} %
        </span>
      ),
    },
    ...(props.toolbarExtra ? [{ key: "extra", node: props.toolbarExtra, group: true }] : []),
    helpItem(help, () => dispatch({ type: "help", open: "toggle" })),
  ];

  return (
    <div
      className={`sfc-editor${readOnly ? " sfc-readonly" : ""}`}
      {...editor.rootProps}
      role="application"
      aria-label="Sequential function chart editor"
    >
      <OverflowBar className="ld-toolbar sfc-toolbar" label="SFC editing" moreLabel="More tools" items={toolbarItems} />
      {readOnly ? (
        <div className="ld-banner" role="status">
          {readOnly} {props.readOnlyActions}
        </div>
      ) : null}
      {message ? (
        <div className="ld-message" role="alert">
          {message}
        </div>
      ) : null}
      {help ? <ShortcutHelp scopes={["sfc", "app"]} onClose={() => dispatch({ type: "help", open: false })} /> : null}
      {menu ? (
        <MenuList x={menu.x} y={menu.y} groups={menu.groups} onClose={() => dispatch({ type: "menu", menu: null })} />
      ) : null}
      {valuePrompt && props.onlineActions ? (
        <OperandValuePrompt
          request={valuePrompt}
          commands={props.onlineActions}
          onDone={() => {
            dispatch({ type: "valuePrompt", request: null });
            editor.focus();
          }}
        />
      ) : null}
      <div className="sfc-main">
        <div className="sfc-scroll" ref={scroll}>
          {elements.length === 0 ? (
            <p className="placeholder">
              The chart is empty:{" "}
              <button type="button" onClick={() => handlers["insert-step"]()}>
                Add the initial step
              </button>
            </p>
          ) : (
            <SfcDiagram
              elements={elements}
              selected={selected}
              selectedAssociation={association}
              diagnostics={props.diagnostics}
              online={props.online}
              marks={props.debugging?.marks}
              scale={zoom}
              onSelect={(id, event) => {
                editor.focus();
                select(id);
                if (id && event.altKey && props.debugging && breakable(body, id)) props.debugging.toggle(id);
              }}
              onSelectAssociation={(step, row) => {
                editor.focus();
                dispatch({ type: "selectAssociation", step, row });
              }}
              onContextMenu={openMenu}
              onDoubleClick={(id) => {
                select(id);
                const next = editable ? editingOf(body, id) : null;
                if (next) dispatch({ type: "edit", editing: next });
              }}
            />
          )}
        </div>
        <aside className="sfc-side">
          <Properties
            body={body}
            selected={selected}
            association={association}
            editing={editing}
            setEditing={(next) => dispatch({ type: "edit", editing: next })}
            associating={associating}
            setAssociating={(open) => dispatch({ type: "associating", open })}
            variables={props.variables ?? []}
            readOnly={!editable}
            apply={apply}
            onOpen={props.onOpen}
            onSelectAssociation={(row) => dispatch({ type: "selectAssociation", step: selected!, row })}
          />
          <Parts body={body} readOnly={!editable} apply={apply} onOpen={props.onOpen} />
        </aside>
      </div>
    </div>
  );
}

interface PropertiesProps {
  body: SfcBody;
  selected: string | null;
  association: string | null;
  editing: Editing;
  setEditing(editing: Editing): void;
  associating: boolean;
  setAssociating(on: boolean): void;
  variables: readonly string[];
  readOnly: boolean;
  apply(result: ops.EditResult): boolean;
  onOpen?(part: SfcPart): void;
  onSelectAssociation(id: string | null): void;
}

/** The selected element's properties, edited in place. */
function Properties(props: PropertiesProps) {
  const { body, selected, readOnly, apply } = props;
  const place = selected ? locate(body, selected) : undefined;
  if (!place) return <p className="sfc-hint">Select a step, transition or jump to edit it.</p>;
  const element = place.element;
  const kind = kindOf(element);
  const names = [...(body.actions ?? []).map((a) => a.name), ...props.variables];
  if (kind === "step") {
    const step = element as SfcStep;
    const initial = steps(body)[0]?.id === step.id;
    return (
      <section className="sfc-properties" aria-label={`Step ${step.name}`}>
        <h3>{initial ? "Initial step" : "Step"}</h3>
        <Field
          label="Step name"
          value={step.name}
          readOnly={readOnly}
          autoFocus={props.editing?.kind === "name" && props.editing.id === step.id}
          onCommit={(name) => apply(ops.setStep(body, step.id, { name }))}
          onDone={() => props.setEditing(null)}
        />
        <h4>Actions</h4>
        <table className="sfc-association-table">
          <tbody>
            {(step.actions ?? []).map((row) => (
              <tr
                key={row.id}
                className={props.association === row.id ? "sfc-row-selected" : ""}
                onClick={() => props.onSelectAssociation(row.id)}
              >
                <td>
                  <select
                    aria-label={`Qualifier of ${row.action}`}
                    value={row.qualifier ?? "N"}
                    disabled={readOnly}
                    onChange={(e) =>
                      apply(ops.setAssociation(body, step.id, row.id, { qualifier: e.target.value as Qualifier }))
                    }
                  >
                    {QUALIFIERS.map((q) => (
                      <option key={q} value={q} title={QUALIFIER_TEXT[q]}>
                        {q}
                      </option>
                    ))}
                  </select>
                </td>
                <td>
                  <Field
                    label={`Action of ${row.id}`}
                    value={row.action}
                    readOnly={readOnly}
                    list="sfc-action-names"
                    onCommit={(action) => apply(ops.setAssociation(body, step.id, row.id, { action }))}
                  />
                </td>
                <td>
                  <Field
                    label={`Time of ${row.action}`}
                    value={row.time ?? ""}
                    placeholder={TIMED.has(row.qualifier ?? "N") ? "T#5s" : ""}
                    readOnly={readOnly}
                    onCommit={(time) => apply(ops.setAssociation(body, step.id, row.id, { time: time || null }))}
                  />
                </td>
                <td>
                  {props.onOpen && body.actions?.some((a) => a.name.toUpperCase() === row.action.toUpperCase()) ? (
                    <button type="button" onClick={() => props.onOpen?.({ kind: "action", name: row.action })}>
                      Open
                    </button>
                  ) : null}
                  {readOnly ? null : (
                    <button
                      type="button"
                      aria-label={`Remove ${row.action}`}
                      onClick={() => apply(ops.removeAssociation(body, step.id, row.id))}
                    >
                      ×
                    </button>
                  )}
                </td>
              </tr>
            ))}
          </tbody>
        </table>
        <datalist id="sfc-action-names">
          {names.map((n) => (
            <option key={n} value={n} />
          ))}
        </datalist>
        {readOnly ? null : props.associating ? (
          <NewAssociation
            names={names}
            onCancel={() => props.setAssociating(false)}
            onAdd={(row) => {
              if (apply(ops.addAssociation(body, step.id, row))) props.setAssociating(false);
            }}
          />
        ) : (
          <button type="button" onClick={() => props.setAssociating(true)}>
            Associate action…
          </button>
        )}
        <h4>Entry and exit actions, time limits</h4>
        <PartSelect
          label="Entry action"
          value={step.entry ?? ""}
          actions={body.actions ?? []}
          readOnly={readOnly}
          onChange={(entry) => apply(ops.setStep(body, step.id, { entry: entry || null }))}
        />
        <PartSelect
          label="Exit action"
          value={step.exit ?? ""}
          actions={body.actions ?? []}
          readOnly={readOnly}
          onChange={(exit) => apply(ops.setStep(body, step.id, { exit: exit || null }))}
        />
        <Field
          label="Minimum time"
          value={step.min_time ?? ""}
          placeholder="T#0s"
          readOnly={readOnly}
          onCommit={(min_time) => apply(ops.setStep(body, step.id, { min_time }))}
        />
        <Field
          label="Maximum time"
          value={step.max_time ?? ""}
          placeholder="none"
          readOnly={readOnly}
          onCommit={(max_time) => apply(ops.setStep(body, step.id, { max_time }))}
        />
      </section>
    );
  }
  if (kind === "transition") {
    const transition = element as SfcTransition;
    return (
      <section className="sfc-properties" aria-label="Transition">
        <h3>Transition</h3>
        <Field
          label="Condition"
          value={transition.condition ?? ""}
          readOnly={readOnly}
          list="sfc-transition-names"
          autoFocus={props.editing?.kind === "condition" && props.editing.id === transition.id}
          onCommit={(condition) => apply(ops.setTransition(body, transition.id, { condition: condition || "FALSE" }))}
          onDone={() => props.setEditing(null)}
        />
        <datalist id="sfc-transition-names">
          {(body.transitions ?? []).map((t) => (
            <option key={t.name} value={t.name} />
          ))}
        </datalist>
        <Field
          label="Priority"
          value={transition.priority == null ? "" : String(transition.priority)}
          placeholder="left to right"
          readOnly={readOnly}
          onCommit={(text) => {
            const priority = text.trim() === "" ? null : Number(text);
            if (priority !== null && (!Number.isInteger(priority) || priority < 0))
              return apply({ error: "A priority is a whole number, 0 or more (lower goes first)." });
            return apply(ops.setTransition(body, transition.id, { priority }));
          }}
        />
        {props.onOpen &&
        body.transitions?.some((t) => t.name.toUpperCase() === transition.condition?.trim().toUpperCase()) ? (
          <button
            type="button"
            onClick={() => props.onOpen?.({ kind: "transition", name: transition.condition!.trim() })}
          >
            Open transition {transition.condition}
          </button>
        ) : null}
      </section>
    );
  }
  if (kind === "jump") {
    return (
      <JumpTarget
        body={body}
        id={element.id}
        target={(element as { target: string }).target}
        readOnly={readOnly}
        focus={props.editing?.kind === "target"}
        apply={apply}
        onDone={() => props.setEditing(null)}
      />
    );
  }
  return (
    <p className="sfc-hint">
      {kind === "parallel" ? "Simultaneous divergence" : "Alternative divergence"}: select one of its branches.
    </p>
  );
}

function JumpTarget(props: {
  body: SfcBody;
  id: string;
  target: string;
  readOnly: boolean;
  focus: boolean;
  apply(result: ops.EditResult): boolean;
  onDone(): void;
}) {
  const select = useRef<HTMLSelectElement>(null);
  useEffect(() => {
    if (props.focus) select.current?.focus();
  }, [props.focus]);
  return (
    <section className="sfc-properties" aria-label="Jump">
      <h3>Jump</h3>
      <label>
        Jump target
        <select
          ref={select}
          aria-label="Jump target"
          value={props.target}
          disabled={props.readOnly}
          onBlur={props.onDone}
          onChange={(e) => props.apply(ops.setJump(props.body, props.id, e.target.value))}
        >
          {steps(props.body).map((s) => (
            <option key={s.id} value={s.name}>
              {s.name}
            </option>
          ))}
        </select>
      </label>
    </section>
  );
}

function NewAssociation(props: {
  names: readonly string[];
  onAdd(row: { qualifier: Qualifier; action: string; time?: string | null }): void;
  onCancel(): void;
}) {
  const [qualifier, setQualifier] = useState<Qualifier>("N");
  const [action, setAction] = useState(props.names[0] ?? "");
  const [time, setTime] = useState("");
  return (
    <form
      className="sfc-new-association"
      aria-label="New action association"
      onSubmit={(e) => {
        e.preventDefault();
        props.onAdd({ qualifier, action: action.trim(), time: TIMED.has(qualifier) ? time.trim() || null : null });
      }}
    >
      <select
        aria-label="Qualifier"
        value={qualifier}
        onChange={(e) => setQualifier(e.target.value as Qualifier)}
        autoFocus
      >
        {QUALIFIERS.map((q) => (
          <option key={q} value={q}>
            {q} – {QUALIFIER_TEXT[q]}
          </option>
        ))}
      </select>
      <input
        aria-label="Action or BOOL variable"
        value={action}
        list="sfc-action-names"
        onChange={(e) => setAction(e.target.value)}
      />
      {TIMED.has(qualifier) ? (
        <input aria-label="Time" value={time} placeholder="T#5s" onChange={(e) => setTime(e.target.value)} />
      ) : null}
      <button type="submit">Add</button>
      <button type="button" onClick={props.onCancel}>
        Cancel
      </button>
    </form>
  );
}

function PartSelect(props: {
  label: string;
  value: string;
  actions: readonly SfcAction[];
  readOnly: boolean;
  onChange(value: string): void;
}) {
  return (
    <label className="sfc-field">
      <span>{props.label}</span>
      <select
        aria-label={props.label}
        value={props.value}
        disabled={props.readOnly}
        onChange={(e) => props.onChange(e.target.value)}
      >
        <option value="">none</option>
        {props.actions.map((a) => (
          <option key={a.name} value={a.name}>
            {a.name}
          </option>
        ))}
      </select>
    </label>
  );
}

/** A text input that commits on Enter or when it loses focus; Escape puts the value back. */
function Field(props: {
  label: string;
  value: string;
  readOnly: boolean;
  placeholder?: string;
  list?: string;
  autoFocus?: boolean;
  onCommit(value: string): boolean | void;
  onDone?(): void;
}) {
  const [text, setText] = useState(props.value);
  const [seen, setSeen] = useState(props.value);
  const input = useRef<HTMLInputElement>(null);
  // Editing asked for (Enter, F2, a double-click): the field takes the focus with its text selected.
  useEffect(() => {
    if (props.autoFocus) {
      input.current?.focus();
      input.current?.select();
    }
  }, [props.autoFocus]);
  if (props.value !== seen) {
    setSeen(props.value);
    setText(props.value);
  }
  const commit = () => {
    if (text !== props.value && props.onCommit(text.trim()) === false) setText(props.value);
    props.onDone?.();
  };
  return (
    <label className="sfc-field">
      <span>{props.label}</span>
      <input
        ref={input}
        aria-label={props.label}
        value={text}
        placeholder={props.placeholder}
        readOnly={props.readOnly}
        list={props.list}
        spellCheck={false}
        onChange={(e) => setText(e.target.value)}
        onBlur={commit}
        onKeyDown={(e) => {
          if (e.key === "Enter") {
            e.preventDefault();
            commit();
          }
          if (e.key === "Escape") {
            setText(props.value);
            props.onDone?.();
          }
        }}
      />
    </label>
  );
}

/** The POU's actions and named transitions: add (name and language), rename, delete, open. */
function Parts(props: {
  body: SfcBody;
  readOnly: boolean;
  apply(result: ops.EditResult): boolean;
  onOpen?(part: SfcPart): void;
}) {
  const { body, readOnly, apply } = props;
  const lists: { kind: "action" | "transition"; title: string; items: (SfcAction | SfcNamedTransition)[] }[] = [
    { kind: "action", title: "Actions", items: body.actions ?? [] },
    { kind: "transition", title: "Named transitions", items: body.transitions ?? [] },
  ];
  return (
    <>
      {lists.map(({ kind, title, items }) => (
        <section key={kind} className="sfc-parts" aria-label={title}>
          <h3>{title}</h3>
          <ul>
            {items.map((item) => (
              <li key={item.name}>
                <Field
                  label={`Name of ${kind} ${item.name}`}
                  value={item.name}
                  readOnly={readOnly}
                  onCommit={(name) =>
                    apply(
                      kind === "action"
                        ? ops.renameAction(body, item.name, name)
                        : ops.renameNamedTransition(body, item.name, name),
                    )
                  }
                />
                <span className={`lang lang-${item.language ?? "st"}`}>{(item.language ?? "st").toUpperCase()}</span>
                {props.onOpen ? (
                  <button type="button" onClick={() => props.onOpen?.({ kind, name: item.name })}>
                    Open
                  </button>
                ) : null}
                {readOnly ? null : (
                  <button
                    type="button"
                    aria-label={`Delete ${kind} ${item.name}`}
                    onClick={() => apply(ops.removePart(body, kind, item.name))}
                  >
                    ×
                  </button>
                )}
              </li>
            ))}
          </ul>
          {readOnly ? null : <NewPart kind={kind} body={body} apply={apply} />}
        </section>
      ))}
    </>
  );
}

function NewPart(props: { kind: "action" | "transition"; body: SfcBody; apply(result: ops.EditResult): boolean }) {
  const [name, setName] = useState("");
  const [language, setLanguage] = useState<ops.PartLanguage>("st");
  return (
    <form
      className="sfc-new-part"
      aria-label={`New ${props.kind}`}
      onSubmit={(e) => {
        e.preventDefault();
        const made =
          props.kind === "action"
            ? ops.addAction(props.body, name.trim(), language)
            : ops.addNamedTransition(props.body, name.trim(), language);
        if (props.apply(made)) setName("");
      }}
    >
      <input
        aria-label={`New ${props.kind} name`}
        value={name}
        placeholder="Name"
        onChange={(e) => setName(e.target.value)}
      />
      <select
        aria-label={`New ${props.kind} language`}
        value={language}
        onChange={(e) => setLanguage(e.target.value as ops.PartLanguage)}
      >
        <option value="st">ST</option>
        <option value="il">IL</option>
        <option value="ld">LD</option>
        <option value="fbd">FBD</option>
        {props.kind === "action" ? <option value="sfc">SFC</option> : null}
      </select>
      <button type="submit">Add {props.kind}</button>
    </form>
  );
}
