// The SFC editor: the chart drawn from its structure (layout.ts, so every chart it draws is well formed),
// the toolbar and keys of the keymap's "sfc" scope (insert a step and a transition below, alternative and
// simultaneous branches, jump, associate an action with its qualifier, delete, copy/paste through the system
// clipboard, undo/redo, zoom), arrow-key navigation across the chart, and a properties panel for the selection
// (step name, action associations with the qualifier picker and time, entry and exit actions, time limits;
// a transition's condition and priority; a jump's target). The actions and named transitions are listed
// below; "Open" shows one in its own editor (the caller's). The undo history is the caller's (one per POU).
import {
  useCallback,
  useEffect,
  useMemo,
  useRef,
  useState,
  type KeyboardEvent,
  type MouseEvent,
  type ReactNode,
} from "react";
import type { Diagnostic } from "../generated/api";
import type { SfcAction, SfcNamedTransition } from "../generated/api";
import { MenuList, type MenuItem } from "../ld/editor/ContextMenu";
import { clipboardActions, type LastClip } from "../ld/editor/systemClipboard";
import type { LdOnlineActions } from "../ld/editor/LdEditor";
import { OperandValuePrompt, type ValueRequest } from "../ld/editor/ValuePrompt";
import { canRedo, canUndo, record, redo, undo, type History } from "../store/history";
import { onlineOperandItems } from "../online/operandCommands";
import { dispatchKey, keysOf, type CommandOf } from "../keys/keymap";
import { ShortcutHelp } from "../keys/ShortcutHelp";
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
type Editing = { kind: "name" | "condition" | "target"; id: string } | null;

const ZOOMS = [0.5, 0.67, 0.8, 1, 1.25, 1.5, 2];
/** The last fragment copied in this tab (the browser may keep its clipboard closed to the toolbar's Paste). */
const lastClip: LastClip = { text: null };

export function SfcEditor(props: SfcEditorProps) {
  const { history, onHistoryChange, readOnly } = props;
  const body = history.present;
  const elements = chartOf(body);
  const [selected, setSelected] = useState<string | null>(null);
  const [association, setAssociation] = useState<string | null>(null);
  const [message, setMessage] = useState<string | null>(null);
  const [zoom, setZoom] = useState(3);
  const [help, setHelp] = useState(false);
  const [editing, setEditing] = useState<Editing>(null);
  const [associating, setAssociating] = useState(false);
  const [menu, setMenu] = useState<{ x: number; y: number; groups: MenuItem[][] } | null>(null);
  const [valuePrompt, setValuePrompt] = useState<ValueRequest | null>(null);
  const root = useRef<HTMLDivElement>(null);
  const layout = useMemo(() => layoutChart(elements), [elements]);
  const place = selected ? locate(body, selected) : undefined;

  // A diagnostic clicked elsewhere selects its element here.
  const [focusSeen, setFocusSeen] = useState(props.focus);
  if (props.focus !== focusSeen) {
    setFocusSeen(props.focus);
    if (props.focus?.element) setSelected(props.focus.element);
  }
  useEffect(() => {
    if (!selected) return;
    root.current?.querySelector(`[data-sfc-id="${CSS.escape(selected)}"]`)?.scrollIntoView?.({ block: "nearest" });
  }, [selected]);

  const apply = useCallback(
    (result: ops.EditResult) => {
      if ("error" in result) {
        setMessage(result.error);
        return false;
      }
      setMessage(null);
      onHistoryChange(record(history, result.body));
      if (result.select !== undefined) setSelected(result.select);
      return true;
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

  const clipboard = clipboardActions(
    {
      take: (cut) => {
        const fragment = selected ? ops.copyFragment(body, selected) : null;
        if (!fragment) return null;
        if (cut && editable) apply(ops.remove(body, selected!));
        return ops.serializeFragment(fragment);
      },
      paste: (text) => {
        const fragment = text ? ops.parseFragment(text) : null;
        if (!fragment) setMessage("The clipboard holds no SFC steps or transitions.");
        else if (!selected) setMessage("Select where to paste first.");
        else apply(ops.pasteFragment(body, selected, fragment));
      },
      isClip: (text) => ops.parseFragment(text) !== null,
      locked: !editable,
    },
    lastClip,
  );

  const handlers: Record<Command, () => boolean> = {
    "insert-step": () => editable && apply(ops.insertBelow(body, selected)),
    alternative: need((id) => ops.addAlternative(body, id)),
    parallel: need((id) => ops.addParallel(body, id)),
    jump: need((id) => ops.addJump(body, id)),
    associate: () => {
      if (!editable || !place || kindOf(place.element) !== "step") return false;
      setAssociating(true);
      return true;
    },
    edit: () => {
      if (!editable || !place) return false;
      const kind = kindOf(place.element);
      if (kind === "step") setEditing({ kind: "name", id: place.element.id });
      else if (kind === "transition") setEditing({ kind: "condition", id: place.element.id });
      else if (kind === "jump") setEditing({ kind: "target", id: place.element.id });
      else return false;
      return true;
    },
    open: () => {
      const row =
        place && kindOf(place.element) === "step"
          ? (place.element as SfcStep).actions?.find((a) => a.id === association)
          : undefined;
      const action = row && body.actions?.find((a) => a.name.toUpperCase() === row.action.toUpperCase());
      if (!action || !props.onOpen) return false;
      props.onOpen({ kind: "action", name: action.name });
      return true;
    },
    delete: () => {
      if (!editable || !selected) return false;
      if (association && place) return apply(ops.removeAssociation(body, place.element.id, association));
      return apply(ops.remove(body, selected)) && (setSelected(null), true);
    },
    "delete-branch": () => (editable && selected ? apply(ops.removeBranch(body, selected)) : false),
    // Copy, cut and paste arrive as clipboard events (below), which reach the system clipboard.
    copy: () => false,
    cut: () => false,
    paste: () => false,
    undo: () => editable && canUndo(history) && (onHistoryChange(undo(history)), true),
    redo: () => editable && canRedo(history) && (onHistoryChange(redo(history)), true),
    "zoom-in": () => (setZoom((z) => Math.min(ZOOMS.length - 1, z + 1)), true),
    "zoom-out": () => (setZoom((z) => Math.max(0, z - 1)), true),
    "zoom-reset": () => (setZoom(3), true),
    "move-selection": () => false, // the arrows are handled below with their direction
    "clear-selection": () => (setSelected(null), setAssociation(null), true),
    "toggle-breakpoint": () => {
      if (!props.debugging || !place) return false;
      const kind = kindOf(place.element);
      if (kind !== "step" && kind !== "transition") return false;
      props.debugging.toggle(place.element.id);
      return true;
    },
  };

  /** The context menu of a step or transition: its breakpoint; online, a step's flag X (write, force, watch). */
  const openMenu = (id: string, event: MouseEvent) => {
    const element = locate(body, id)?.element;
    const kind = element ? kindOf(element) : null;
    if (kind !== "step" && kind !== "transition") return;
    event.preventDefault();
    setSelected(id);
    setAssociation(null);
    const groups: MenuItem[][] = [];
    const { onlineActions, debugging } = props;
    if (kind === "step" && onlineActions) {
      const operand = `${(element as SfcStep).name}.X`;
      groups.push(onlineOperandItems(operand, onlineActions, (action) => setValuePrompt({ operand, action })));
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
    setMenu({ x: event.clientX - (box?.left ?? 0), y: event.clientY - (box?.top ?? 0), groups });
  };

  const onKeyDown = (event: KeyboardEvent) => {
    if ((event.target as HTMLElement).closest("input, select, textarea")) return;
    const arrows: Record<string, Direction> = {
      ArrowUp: "up",
      ArrowDown: "down",
      ArrowLeft: "left",
      ArrowRight: "right",
    };
    const direction = arrows[event.key];
    if (direction && !event.ctrlKey && !event.altKey && !event.metaKey && !event.shiftKey) {
      event.preventDefault();
      setAssociation(null);
      setSelected(neighbour(layout, selected, direction));
      return;
    }
    if (dispatchKey("sfc", event, handlers)) return;
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
    { label: "Zoom in", command: "zoom-in", enabled: zoom < ZOOMS.length - 1 },
    { label: "Zoom out", command: "zoom-out", enabled: zoom > 0 },
  ];

  return (
    <div
      className={`sfc-editor${readOnly ? " sfc-readonly" : ""}`}
      ref={root}
      tabIndex={0}
      role="application"
      aria-label="Sequential function chart editor"
      onKeyDown={onKeyDown}
      {...clipboard.events}
    >
      <div className="ld-toolbar sfc-toolbar" role="toolbar" aria-label="SFC editing">
        {toolbar.map(({ label, command, enabled }) => (
          <button
            key={command}
            type="button"
            disabled={!enabled}
            title={keysOf("sfc", command) ? `${label} (${keysOf("sfc", command)})` : label}
            onMouseDown={(e) => e.preventDefault()}
            onClick={() => {
              if (command === "copy" || command === "cut") clipboard.copy(command === "cut");
              else if (command === "paste") clipboard.paste();
              else handlers[command]();
              root.current?.focus();
            }}
          >
            {label}
          </button>
        ))}
        <span className="sfc-zoom" aria-label="Zoom">
          {Math.round(ZOOMS[zoom]! * 100)} %
        </span>
        {props.toolbarExtra}
        <button type="button" className="ld-help-button" aria-expanded={help} onClick={() => setHelp((h) => !h)}>
          Shortcuts
        </button>
      </div>
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
      {help ? <ShortcutHelp scopes={["sfc", "app"]} onClose={() => setHelp(false)} /> : null}
      {menu ? <MenuList x={menu.x} y={menu.y} groups={menu.groups} onClose={() => setMenu(null)} /> : null}
      {valuePrompt && props.onlineActions ? (
        <OperandValuePrompt
          request={valuePrompt}
          commands={props.onlineActions}
          onDone={() => {
            setValuePrompt(null);
            root.current?.focus();
          }}
        />
      ) : null}
      <div className="sfc-main">
        <div className="sfc-scroll">
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
              scale={ZOOMS[zoom]}
              onSelect={(id, event) => {
                root.current?.focus();
                setAssociation(null);
                setSelected(id);
                if (id && event.altKey && props.debugging) {
                  const kind = kindOf(locate(body, id)?.element ?? ({ type: "jump" } as never));
                  if (kind === "step" || kind === "transition") props.debugging.toggle(id);
                }
              }}
              onSelectAssociation={(step, row) => {
                root.current?.focus();
                setSelected(step);
                setAssociation(row);
              }}
              onContextMenu={openMenu}
              onDoubleClick={(id) => {
                setSelected(id);
                if (editable) {
                  const kind = kindOf(locate(body, id)?.element ?? ({ type: "alternative" } as never));
                  if (kind === "step") setEditing({ kind: "name", id });
                  if (kind === "transition") setEditing({ kind: "condition", id });
                  if (kind === "jump") setEditing({ kind: "target", id });
                }
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
            setEditing={setEditing}
            associating={associating}
            setAssociating={setAssociating}
            variables={props.variables ?? []}
            readOnly={!editable}
            apply={apply}
            onOpen={props.onOpen}
            onSelectAssociation={setAssociation}
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
