// The LD editor: the diagram plus selection (mouse and arrow keys), toolbar, context menu,
// keyboard shortcuts, operand entry with autocomplete and the "declare variable" offer, the box
// picker, drag to move, copy/paste through the system clipboard, undo/redo, and breakpoints
// (network number click, Alt+click, F9, context menu) when the caller supplies them. The undo
// history is owned by the caller (one per open POU), so it survives switching tabs.
import {
  useCallback,
  useEffect,
  useMemo,
  useReducer,
  useRef,
  type KeyboardEvent,
  type MouseEvent,
  type ReactNode,
} from "react";
import type { Diagnostic, LibraryEntry, SymbolInfo } from "../../generated/api";
import { parseClip, serializeClip } from "../clipboard";
import { blockEntry, pickableCalls } from "../../store/calls";
import { canRedo, canUndo, record, redo, undo, type History } from "../../store/history";
import { layoutBody } from "../layout";
import { locate, networksOf, walk, type LdBody, type Place } from "../model";
import * as ops from "../ops";
import type { EditResult, OperandField } from "../ops";
import { LdDiagram } from "../view/LdDiagram";
import type { DebugMarks, DiagramHandlers, OnlineView, Selection, Target } from "../view/types";
import { BoxPicker } from "./BoxPicker";
import {
  available,
  commandKeys,
  COMMANDS,
  insert,
  selectedNetwork,
  type CommandContext,
  type CommandGroup,
} from "./commands";
import { ContextMenu } from "./ContextMenu";
import type { MenuItem } from "../../ui/MenuList";
import { IlView } from "./IlView";
import { declareOffer, instanceName, symbolNames, type VariableDeclaration } from "./declare";
import { extend, navigate, type Direction } from "./navigation";
import { OperandEditor, type MembersAfter } from "../../ui/OperandEditor";
import { setDraggedOperand } from "./dragOperand";
import { EditorNotices } from "./EditorNotices";
import type { LastClip } from "../../ui/systemClipboard";
import { useEditorRoot, type KeyHandlers } from "../../ui/useEditorRoot";
import { fitZoom, type ZoomStep } from "../../ui/zoom";
import { OperandValuePrompt, type ValueRequest } from "../../online/ValuePrompt";
import {
  clipOf,
  fieldLabel,
  INITIAL_STATE,
  ldEditorReducer,
  liveSelection as liveSelectionOf,
  mainField,
  operandText,
  pastePlace,
  valueOperand,
  variableOf,
  type Editing,
} from "./editorState";
import { useLibraryLookup } from "../../online/editorOnline";
import { onlineOperandItems, type LdOnlineActions } from "../../online/operandCommands";
import { referencesItem } from "../../xref/store";
import { keysOf } from "../../keys/keymap";
import { ShortcutHelp } from "../../keys/ShortcutHelp";
import "../ld.css";
import { ZoomIn, ZoomOut } from "lucide-react";
import { COMMAND_ICONS } from "../../ui/icons";
import { OverflowBar, helpItem, toolItem, type BarItem } from "../../ui/OverflowBar";

export interface LdEditorProps {
  history: History<LdBody>;
  onHistoryChange(history: History<LdBody>): void;
  /** Functions and function blocks for the box picker and box pins (GET /api/library). */
  library?: readonly LibraryEntry[];
  /** The POU's symbols and the globals, for autocomplete and the declare offer. */
  symbols?: readonly SymbolInfo[];
  /** What operand autocomplete offers after a qualifier (`T1.`, `Prog.`, `Color.`); none: plain names only. */
  members?: MembersAfter;
  diagnostics?: readonly Diagnostic[];
  online?: OnlineView;
  /** Editing is off (online); the reason is shown. */
  readOnly?: string | null;
  /** Controls next to the read-only reason (online: "Go offline to edit", the instance shown). */
  readOnlyActions?: ReactNode;
  onDeclareVariable?(declaration: VariableDeclaration): void;
  /** Online commands on operands (double-click prepares a value, the context menu writes and forces). */
  onlineActions?: LdOnlineActions;
  /** Told which networks are rendered, so online mode subscribes only to those. */
  onVisibleChange?(networks: readonly string[]): void;
  /** Select and reveal a network or element (a diagnostic was clicked); `seq` repeats a jump to the same place. */
  focus?: { network?: string | null; element?: string | null; seq: number } | null;
  /** Breakpoints: drawn from `marks`; a network number click, Alt+click on an element, F9 or the context menu toggle them. */
  debugging?: LdDebugging;
}

/** What the editor needs for breakpoints (the caller owns them: the debug store). */
export interface LdDebugging {
  marks: DebugMarks;
  toggle(target: { network: string } | { element: string }): void;
}

const TOOLBAR: { group: CommandGroup; ids: string[] }[] = [
  { group: "insert", ids: ["contact", "contact-nc", "coil", "compare", "box", "parallel", "jump", "return"] },
  { group: "edit", ids: ["cycle-mode", "toggle-en", "delete"] },
  {
    group: "network",
    ids: ["network-add", "network-duplicate", "network-up", "network-down", "network-label", "network-comment"],
  },
  { group: "clipboard", ids: ["copy", "cut", "paste"] },
  { group: "history", ids: ["undo", "redo"] },
];

/** How long each group stays in the toolbar as it narrows (ui/OverflowBar.tsx): higher stays longer. */
const TOOL_PRIORITY: Record<CommandGroup, number> = {
  insert: 3,
  edit: 2,
  mode: 2,
  history: 2,
  network: 0,
  clipboard: 0,
};

/** The keys of the LD scope that are not editing commands (COMMANDS): selection, breakpoints, zoom. */
export const LD_EDITOR_KEYS = [
  "move-selection",
  "extend-selection",
  "clear-selection",
  "toggle-breakpoint",
  "zoom-in",
  "zoom-out",
  "zoom-reset",
  "zoom-fit",
] as const;
type LdEditorKey = (typeof LD_EDITOR_KEYS)[number];
const CLIPBOARD_COMMANDS: ReadonlySet<string> = new Set(["copy", "cut", "paste"]);

const NO_LIBRARY: readonly LibraryEntry[] = [];
const NO_SYMBOLS: readonly SymbolInfo[] = [];
const ARROWS: Record<string, Direction> = { ArrowLeft: "left", ArrowRight: "right", ArrowUp: "up", ArrowDown: "down" };

/** The last clip copied in this tab, for toolbar paste when the browser keeps the clipboard closed. */
const lastClip: LastClip = { text: null };

export function LdEditor({
  history,
  onHistoryChange,
  library = NO_LIBRARY,
  symbols = NO_SYMBOLS,
  members,
  diagnostics,
  online,
  readOnly = null,
  readOnlyActions,
  onDeclareVariable,
  onlineActions,
  onVisibleChange,
  focus,
  debugging,
}: LdEditorProps) {
  const body = history.present;
  const root = useRef<HTMLDivElement>(null);
  const [state, dispatch] = useReducer(ldEditorReducer, INITIAL_STATE);
  const { anchor, editing, picker, menu, message, offer, dropping, help, zoom, pendingEdit, valuePrompt, asIl } = state;
  const drag = useRef<{ ids: string[]; x: number; y: number } | null>(null);
  const setMessage = (text: string | null) => dispatch({ type: "message", text });
  const setEditing = (next: Editing | null) => dispatch({ type: "edit", editing: next });
  const setPicker = (open: boolean) => dispatch({ type: "picker", open });
  const setMenu = (at: { x: number; y: number } | null) => dispatch({ type: "menu", at });
  const setOffer = (next: VariableDeclaration | null) => dispatch({ type: "offer", offer: next });
  const setZoom = (step: ZoomStep) => dispatch({ type: "zoom", step });
  const setValuePrompt = (request: ValueRequest | null) => dispatch({ type: "valuePrompt", request });

  const libraryEntry = useLibraryLookup(library);
  // A box calls a library entry, else an instance's method (`inst.M`): its pins are the method's.
  const lookup = useCallback((call: string) => blockEntry(call, libraryEntry, symbols), [libraryEntry, symbols]);
  const pickable = useMemo(() => pickableCalls(library, symbols, libraryEntry), [library, symbols, libraryEntry]);
  const values = online !== undefined;
  const layout = useMemo(() => layoutBody(body, { library: lookup, values }), [body, lookup, values]);
  const known = useMemo(() => symbolNames(symbols), [symbols]);

  const liveSelection = useMemo(() => liveSelectionOf(body, state.selection), [body, state.selection]);
  const select = (selection: Selection | null, newAnchor?: string | null) =>
    dispatch({ type: "select", selection, anchor: newAnchor });
  const selectAndReveal = (selection: Selection | null, of: LdBody, newAnchor?: string | null) =>
    dispatch({ type: "reveal", selection, body: of, anchor: newAnchor });

  // Only a new focus request moves the selection (while rendering, as it arrives), not later edits of the body.
  const focusSeq = focus?.seq ?? null;
  if (focus && focusSeq !== state.focusSeen) dispatch({ type: "focus", focus, body });
  useEffect(() => {
    if (focusSeq !== null) root.current?.focus();
  }, [focusSeq]);

  const apply = useCallback(
    (result: EditResult, then?: "edit") => {
      if (result.ok) onHistoryChange(record(history, result.body));
      dispatch({ type: "edited", result, then });
    },
    [history, onHistoryChange],
  );

  /** Opens the operand editor over `field` of element `id`. */
  const editField = useCallback(
    (id: string, field: OperandField) => {
      const n = layout.networks.find((net) => net.elements.some((e) => e.id === id));
      const placed = n?.elements.find((e) => e.id === id);
      if (!n || !placed) return;
      let { x, y } = { x: placed.x, y: n.top + placed.y };
      if (field.kind === "input" || field.kind === "output") {
        const pin = placed.pins?.find(
          (p) => p.name === field.pin && p.side === (field.kind === "input" ? "in" : "out"),
        );
        if (pin) ({ x, y } = { x: field.kind === "input" ? pin.x - 150 : pin.x + 4, y: n.top + pin.y - 22 });
      } else if (field.kind === "right") y = n.top + placed.y + 36;
      dispatch({ type: "edit", editing: { kind: "operand", id, field, x: Math.max(0, x), y } });
    },
    [layout],
  );

  // The new element is laid out in this render: its operand editor opens now.
  if (pendingEdit && locate(body, pendingEdit)) {
    dispatch({ type: "pendingEditDone" });
    const field = mainField(body, pendingEdit, lookup);
    if (field) editField(pendingEdit, field);
  }

  const commitOperand = (id: string, field: OperandField, text: string) => {
    setEditing(null);
    root.current?.focus();
    if (text.trim() === operandText(body, id, field)) return;
    const result = ops.setOperand(body, id, field, text);
    apply(result);
    if (!result.ok) return;
    const declaration = declareOffer(result.body, id, field, text, known, lookup, symbols);
    setOffer(declaration && onDeclareVariable ? declaration : null);
  };

  const editNetwork = (field: "label" | "comment") => {
    const id = selectedNetwork({ body, selection: liveSelection });
    const n = layout.networks.find((net) => net.network.id === id);
    if (!id || !n) return;
    setEditing({ kind: "network", id, field, x: n.leftRailX, y: n.top + (field === "label" ? 0 : 18) });
  };

  const pasteText = (text: string | null) => {
    const clip = text ? parseClip(text) : null;
    if (!clip) {
      setMessage("The clipboard holds no LadderLab elements or networks.");
      return;
    }
    const networks = networksOf(body);
    if (clip.kind === "networks") {
      const index = networks.findIndex((n) => n.id === selectedNetwork({ body, selection: liveSelection }));
      apply(ops.pasteNetworks(body, index < 0 ? networks.length : index + 1, clip.networks));
      return;
    }
    const place = pastePlace(body, liveSelection);
    if (!place) {
      setMessage("Select where to paste: an element, a wire or a network.");
      return;
    }
    apply(ops.pasteElements(body, place, clip.elements));
  };

  const take = (cut: boolean): string | null => {
    const clip = clipOf(body, liveSelection);
    if (!clip) return null;
    if (cut && !readOnly) {
      apply(
        liveSelection?.kind === "network"
          ? ops.deleteNetworks(body, [liveSelection.id])
          : ops.deleteElements(body, clip.kind === "elements" ? clip.elements.map((e) => e.id) : []),
      );
    }
    return serializeClip(clip);
  };
  const editor = useEditorRoot({
    root,
    scope: "ld",
    handlers: (event) => keyHandlers(event),
    busy: editing !== null || picker,
    clipboard: { take, paste: pasteText, isClip: (text) => parseClip(text) !== null, locked: readOnly !== null },
    last: lastClip,
    onZoom: setZoom,
  });

  const ctx: CommandContext = {
    body,
    selection: liveSelection,
    readOnly: readOnly !== null,
    canUndo: canUndo(history),
    canRedo: canRedo(history),
    apply,
    undo: () => {
      setMessage(null);
      onHistoryChange(undo(history));
    },
    redo: () => {
      setMessage(null);
      onHistoryChange(redo(history));
    },
    editOperand: () => {
      const id = liveSelection?.kind === "elements" ? liveSelection.ids[0] : undefined;
      const field = id ? mainField(body, id, lookup) : undefined;
      if (id && field) editField(id, field);
    },
    openBoxPicker: () => setPicker(true),
    editNetwork,
    copy: editor.copy,
    paste: editor.paste,
  };

  const pickBox = (entry: LibraryEntry, en: boolean) => {
    setPicker(false);
    root.current?.focus();
    const used = new Set([
      ...known,
      ...[...walk(body)].flatMap((l) =>
        l.element.type === "box" && l.element.instance ? [l.element.instance.toUpperCase()] : [],
      ),
    ]);
    const instance = entry.kind === "function_block" ? instanceName(entry.name, used) : null;
    const result = insert(ctx, ops.box(entry.name, instance, en), "after");
    apply(result);
    if (result.ok && instance) {
      setOffer(onDeclareVariable ? { name: instance, type: entry.name } : null);
    }
  };

  // Drag to move: a press on an element becomes a drag once the mouse travels; slots are the drop targets.
  useEffect(() => {
    const move = (e: globalThis.MouseEvent) => {
      const d = drag.current;
      if (d && !dropping && Math.hypot(e.clientX - d.x, e.clientY - d.y) > 5)
        dispatch({ type: "dropping", dropping: true });
    };
    const up = () => {
      drag.current = null;
      dispatch({ type: "dropping", dropping: false });
    };
    window.addEventListener("mousemove", move);
    window.addEventListener("mouseup", up);
    return () => {
      window.removeEventListener("mousemove", move);
      window.removeEventListener("mouseup", up);
    };
  }, [dropping]);

  const handlers: DiagramHandlers = {
    onPointerDown: (target: Target, event: MouseEvent) => {
      if (event.button !== 0) return;
      event.stopPropagation();
      root.current?.focus();
      setMenu(null);
      if (target.kind === "element") {
        if (event.altKey && debugging) {
          select({ kind: "elements", ids: [target.id] });
          debugging.toggle({ element: target.id });
          return;
        }
        if (event.shiftKey && anchor) {
          select({ kind: "elements", ids: ops.rangeIds(body, anchor, target.id) }, anchor);
          return;
        }
        const keep = liveSelection?.kind === "elements" && liveSelection.ids.includes(target.id);
        const ids = keep ? liveSelection.ids : [target.id];
        select({ kind: "elements", ids }, keep ? anchor : target.id);
        setDraggedOperand(variableOf(body, target.id));
        if (!readOnly) drag.current = { ids, x: event.clientX, y: event.clientY };
      } else if (target.kind === "place") select({ kind: "place", place: target.place });
      else select({ kind: "network", id: target.id });
    },
    onPlaceUp: (place: Place) => {
      const d = drag.current;
      if (!d || !dropping) return;
      drag.current = null;
      dispatch({ type: "dropping", dropping: false });
      apply(ops.moveElements(body, d.ids, place));
    },
    onOperand: (id, field, event) => {
      if (readOnly) return;
      event.stopPropagation();
      select({ kind: "elements", ids: [id] });
      editField(id, field);
    },
    onDoubleClick: (target, event) => {
      if (onlineActions && target.kind === "element") {
        const pin = (event.target as Element).closest?.("[data-pin-value]")?.getAttribute("data-pin-value");
        const value = valueOperand(body, target.id, pin ?? null, lookup);
        if (value && !onlineActions.prepare(value.operand, undefined, value.type))
          setValuePrompt({ operand: value.operand, action: "prepare" });
        return;
      }
      if (readOnly) return;
      if (target.kind === "network") {
        select({ kind: "network", id: target.id });
        return;
      }
      if (target.kind !== "element") return;
      const field = mainField(body, target.id, lookup);
      if (field) editField(target.id, field);
    },
    onContextMenu: (target, event) => {
      event.preventDefault();
      const box = root.current?.getBoundingClientRect();
      if (target.kind === "element") {
        if (!(liveSelection?.kind === "elements" && liveSelection.ids.includes(target.id)))
          select({ kind: "elements", ids: [target.id] });
      } else if (target.kind === "place") select({ kind: "place", place: target.place });
      else select({ kind: "network", id: target.id });
      setMenu({ x: event.clientX - (box?.left ?? 0), y: event.clientY - (box?.top ?? 0) });
    },
    onNetworkNumber: debugging && ((network) => debugging.toggle({ network })),
  };

  /** The breakpoint F9 and the context menu toggle: the selected element, else the selected network. */
  const breakpointTarget = (): { network: string } | { element: string } | null => {
    if (liveSelection?.kind === "elements") return { element: liveSelection.ids[0]! };
    const network = selectedNetwork({ body, selection: liveSelection });
    return network ? { network } : null;
  };

  /** Zoom so the whole diagram fits the scroller (ui/zoom.ts). */
  const fit = () => {
    const view = root.current?.querySelector(".ld-scroller");
    if (!view) return false;
    dispatch({ type: "zoomTo", zoom: fitZoom(layout, { width: view.clientWidth, height: view.clientHeight }) });
    return true;
  };

  /** The editor's keys besides its commands (src/keys/keymap.ts, scope "ld"); each says whether it acted. */
  const keyActions = (event: KeyboardEvent<HTMLElement>): Record<LdEditorKey, () => boolean> => ({
    "move-selection": () => {
      selectAndReveal(navigate(body, layout, liveSelection, ARROWS[event.key]!), body);
      return true;
    },
    "extend-selection": () => {
      const focus = liveSelection?.kind === "elements" ? liveSelection.ids[liveSelection.ids.length - 1] : undefined;
      if (!anchor || !focus) return false;
      const next = extend(body, anchor, focus, ARROWS[event.key] as "left" | "right");
      selectAndReveal({ kind: "elements", ids: ops.rangeIds(body, anchor, next) }, body, anchor);
      return true;
    },
    "clear-selection": () => {
      setMenu(null);
      select(null);
      return true;
    },
    "toggle-breakpoint": () => {
      const target = debugging ? breakpointTarget() : null;
      if (target) debugging!.toggle(target);
      return debugging !== undefined;
    },
    "zoom-in": () => (setZoom("in"), true),
    "zoom-out": () => (setZoom("out"), true),
    "zoom-reset": () => (setZoom("reset"), true),
    "zoom-fit": fit,
  });
  /** Every LD key: the editing commands (when available) and the editor's own keys. */
  function keyHandlers(event: KeyboardEvent<HTMLElement>): KeyHandlers<"ld"> {
    const commands = COMMANDS.filter((c) => !CLIPBOARD_COMMANDS.has(c.id)).map((c) => [
      c.id,
      () => available(c, ctx) && (c.run(ctx), true),
    ]);
    return { ...Object.fromEntries(commands), ...keyActions(event) } as KeyHandlers<"ld">;
  }

  /** The items of the context menu besides the editing commands: breakpoints, online commands on the selected element's variable. */
  const extraItems = (): MenuItem[] => {
    const target = debugging ? breakpointTarget() : null;
    const breakpoint: MenuItem[] =
      debugging && target
        ? [
            {
              id: "toggle-breakpoint",
              label: "element" in target ? "Toggle breakpoint on element" : "Toggle breakpoint on network",
              keys: keysOf("ld", "toggle-breakpoint"),
              run: () => debugging.toggle(target),
            },
          ]
        : [];
    const network = selectedNetwork({ body, selection: liveSelection });
    const il: MenuItem[] = network
      ? [{ id: "view-il", label: "View as IL", run: () => dispatch({ type: "asIl", network }) }]
      : [];
    const selected = liveSelection?.kind === "elements" ? variableOf(body, liveSelection.ids[0]!) : null;
    const references = selected ? [referencesItem(selected)] : [];
    // The declare dialog again (after Escape): the selected element's undeclared operand.
    const id = liveSelection?.kind === "elements" && liveSelection.ids.length === 1 ? liveSelection.ids[0]! : null;
    const field = id && onDeclareVariable && !readOnly ? mainField(body, id, lookup) : undefined;
    const offered =
      id && field ? declareOffer(body, id, field, operandText(body, id, field), known, lookup, symbols) : null;
    const declare: MenuItem[] = offered
      ? [{ id: "declare", label: `Declare ${offered.name}…`, run: () => setOffer(offered) }]
      : [];
    const operand = onlineActions ? selected : null;
    if (!onlineActions || !operand) return [...declare, ...breakpoint, ...il, ...references];
    return [
      ...breakpoint,
      ...il,
      ...onlineOperandItems(operand, onlineActions, (action) => setValuePrompt({ operand, action })),
      ...references,
    ];
  };

  const editorOverlay = editing ? (
    editing.kind === "operand" ? (
      <OperandEditor
        key={`${editing.id}:${JSON.stringify(editing.field)}`}
        label={fieldLabel(editing.field)}
        initial={operandText(body, editing.id, editing.field)}
        suggestions={editing.field.kind === "target" ? [] : symbols}
        members={editing.field.kind === "target" ? undefined : members}
        style={{ left: editing.x, top: editing.y }}
        onCommit={(text) => commitOperand(editing.id, editing.field, text)}
        onCancel={() => {
          setEditing(null);
          root.current?.focus();
        }}
      />
    ) : (
      <OperandEditor
        key={`${editing.id}:${editing.field}`}
        label={editing.field === "label" ? "Network label" : "Network comment"}
        initial={
          (editing.field === "label"
            ? networksOf(body).find((n) => n.id === editing.id)?.label
            : networksOf(body).find((n) => n.id === editing.id)?.comment) ?? ""
        }
        style={{ left: editing.x, top: editing.y }}
        onCommit={(text) => {
          setEditing(null);
          root.current?.focus();
          const current = networksOf(body).find((n) => n.id === editing.id);
          if (((editing.field === "label" ? current?.label : current?.comment) ?? "") === text) return;
          apply(
            editing.field === "label"
              ? ops.setNetworkLabel(body, editing.id, text)
              : ops.setNetworkComment(body, editing.id, text),
          );
        }}
        onCancel={() => {
          setEditing(null);
          root.current?.focus();
        }}
      />
    )
  ) : null;

  // The toolbar, one row: as it narrows, the clipboard and network tools go into More first, the insert tools last.
  const toolbarItems: BarItem[] = [
    ...TOOLBAR.flatMap(({ group, ids }) =>
      ids.map((id, i) => {
        const command = COMMANDS.find((c) => c.id === id)!;
        return toolItem(
          {
            id,
            icon: COMMAND_ICONS[id]!,
            label: command.label,
            keys: commandKeys(command) || undefined,
            disabled: !available(command, ctx),
            run: () => command.run(ctx),
          },
          { group: i === 0, priority: TOOL_PRIORITY[group] },
        );
      }),
    ),
    toolItem(
      { id: "zoom-out", icon: ZoomOut, label: "Zoom out", keys: "Ctrl+- or Ctrl+wheel", run: () => setZoom("out") },
      { group: true, priority: 1 },
    ),
    {
      key: "zoom",
      node: (
        <button type="button" title="Actual size (Ctrl+0)" aria-label="Zoom" onClick={() => setZoom("reset")}>
          {Math.round(zoom * 100)}%
        </button>
      ),
      entries: [
        {
          id: "zoom",
          label: `Actual size (now ${Math.round(zoom * 100)}%)`,
          keys: "Ctrl+0",
          run: () => setZoom("reset"),
        },
      ],
      priority: 1,
    },
    toolItem(
      { id: "zoom-in", icon: ZoomIn, label: "Zoom in", keys: "Ctrl++ or Ctrl+wheel", run: () => setZoom("in") },
      { priority: 1 },
    ),
    toolItem(
      // eslint-disable-next-line react-hooks/refs -- toolItem keeps `fit` for the click and the More entry, never calls it
      {
        id: "zoom-fit",
        icon: COMMAND_ICONS["zoom-fit"]!,
        label: "Zoom to fit",
        keys: keysOf("ld", "zoom-fit"),
        run: fit,
      },
      { priority: 1 },
    ),
    helpItem(help, () => dispatch({ type: "help", open: "toggle" })),
  ];

  return (
    <div
      className={`ld-editor${readOnly ? " ld-readonly" : ""}`}
      {...editor.rootProps}
      role="application"
      aria-label="Ladder diagram editor"
      onMouseDown={(e) => {
        if (e.target === e.currentTarget || (e.target as HTMLElement).classList.contains("ld-canvas")) select(null);
      }}
    >
      <OverflowBar className="ld-toolbar" label="LD editing" moreLabel="More tools" items={toolbarItems} />
      {help ? <ShortcutHelp scopes={["ld", "app"]} onClose={() => dispatch({ type: "help", open: false })} /> : null}
      <EditorNotices
        readOnly={readOnly}
        readOnlyActions={readOnlyActions}
        message={message}
        onDismissMessage={() => setMessage(null)}
        offer={offer}
        onDeclare={(declaration) => {
          setOffer(null);
          onDeclareVariable?.(declaration);
          root.current?.focus();
        }}
        onDismissOffer={() => setOffer(null)}
      />
      <LdDiagram
        body={body}
        layout={layout}
        selection={liveSelection}
        diagnostics={diagnostics}
        online={online}
        dropping={dropping}
        handlers={handlers}
        reveal={state.reveal}
        overlay={editorOverlay}
        onVisibleChange={onVisibleChange}
        debug={debugging?.marks}
        zoom={zoom}
      />
      {networksOf(body).length === 0 ? (
        <p className="ld-empty-hint">This POU has no networks yet: press Ctrl+Enter or C to start a rung.</p>
      ) : null}
      {menu ? <ContextMenu x={menu.x} y={menu.y} ctx={ctx} extra={extraItems()} onClose={() => setMenu(null)} /> : null}
      {valuePrompt && onlineActions ? (
        <OperandValuePrompt
          request={valuePrompt}
          commands={onlineActions}
          onDone={() => {
            setValuePrompt(null);
            root.current?.focus();
          }}
        />
      ) : null}
      {asIl && networksOf(body).some((n) => n.id === asIl) ? (
        <IlView
          network={networksOf(body).find((n) => n.id === asIl)!}
          number={networksOf(body).findIndex((n) => n.id === asIl) + 1}
          onClose={() => {
            dispatch({ type: "asIl", network: null });
            root.current?.focus();
          }}
        />
      ) : null}
      {picker ? (
        <BoxPicker
          library={pickable}
          onPick={pickBox}
          onCancel={() => {
            setPicker(false);
            root.current?.focus();
          }}
        />
      ) : null}
    </div>
  );
}
