// The FBD editor: networks listed top to bottom, each its own xyflow canvas; a palette (click to
// add, or drag onto a network), the shared block picker, operand entry with autocomplete and the
// declare offer, typed wiring that refuses incompatible pins with the reason, pin flags from the
// pin's context menu, execution-order badges from the backend with "run earlier/later",
// auto-arrange, undo/redo, copy/paste, diagnostics on nodes and pins, online values on wires,
// write/force from the context menu, and breakpoints. The undo history is the caller's (one per POU).
// With `chart` it edits a CFC POU's one chart (docs/diagrams.md "CFC"): no networks, an execution
// order number on every executed element that "run earlier/later" moves freely, "Order by data flow".
import "@xyflow/react/dist/style.css";
import "../../ld/ld.css";
import { useNodeLayout } from "./useNodeLayout";
import "./fbd.css";
import { COMMAND_ICONS } from "../../ui/icons";
import { OverflowBar, helpItem, toolItem, type BarItem, type Tool } from "../../ui/OverflowBar";
import type { Connection } from "@xyflow/react";
import { useCallback, useEffect, useMemo, useReducer, useRef, type MouseEvent, type ReactNode } from "react";
import type { Diagnostic, FbdOrder, LibraryEntry, SymbolInfo } from "../../generated/api";
import { BoxPicker } from "../../ld/editor/BoxPicker";
import { MenuList, type MenuItem } from "../../ui/MenuList";
import { instanceName, symbolNames, type VariableDeclaration } from "../../ld/editor/declare";
import { EditorNotices } from "../../ld/editor/EditorNotices";
import type { LdOnlineActions } from "../../online/operandCommands";
import { OperandEditor, type MembersAfter } from "../../ui/OperandEditor";
import type { LastClip } from "../../ui/systemClipboard";
import { useEditorRoot, type KeyHandlers } from "../../ui/useEditorRoot";
import { OperandValuePrompt, type ValueRequest } from "../../online/ValuePrompt";
import { useLibraryLookup } from "../../online/editorOnline";
import { onlineOperandItems } from "../../online/operandCommands";
import { referencesItem } from "../../xref/store";
import { pickableCalls } from "../../store/calls";
import { canRedo, canUndo, record, redo, undo, type History } from "../../store/history";

import { parseClip, pasteClip, serializeClip } from "../clipboard";
import { refusal } from "../compat";
import {
  findNode,
  kindOf,
  networksOf,
  nextInput,
  nodePins,
  nodesOf,
  wiresOf,
  type Block,
  type FbdBody,
  type FbdNetwork,
  type FbdNode,
  type OutputMode,
  type Position,
} from "../model";
import type { FbdOnlineView } from "../online";
import { operandOf } from "../online";
import * as ops from "../ops";
import { feedbackPins, moveInOrder, orderByDataFlow, orderNumbers, ordered } from "../order";
import { fetchChartOrder, fetchOrder, useEvaluationOrder } from "../useOrder";
import { FbdEditorContext, type FbdEditorApi, type NodeView } from "./context";
import { pinOfHandle } from "./FbdNodeView";
import { DRAG_FORMAT, NetworkCanvas } from "./NetworkCanvas";
import {
  breakpointTarget,
  clipOfSelection,
  declareOffer,
  deletion,
  fbdEditorReducer,
  INITIAL_STATE,
  instancesOf,
  nodeChanged,
  nodeVariable,
  pinOperand,
  revealPending,
  selectedNetworkIndex,
  singleNode,
  targetNetwork as targetNetworkOf,
  type FbdEditorState,
} from "./editorState";
import { keysOf, type CommandOf } from "../../keys/keymap";
import { ShortcutHelp } from "../../keys/ShortcutHelp";

/** A toolbar tooltip: the action and its key from the keymap. */
/** A palette entry's icon (the symbol it adds). */
function PaletteIcon({ kind }: { kind: PaletteKind }) {
  const Icon = COMMAND_ICONS[kind]!;
  return <Icon size={16} aria-hidden="true" />;
}

const keyed = (command: CommandOf<"fbd">) => keysOf("fbd", command);

/** Breakpoints and the halt, for this POU (debug/store.ts holds them). */
export interface FbdDebug {
  networks: ReadonlySet<string>;
  elements: ReadonlySet<string>;
  halted: { network?: string | null; element?: string | null } | null;
  toggle(bp: { network: string } | { element: string }): void;
  /** Nodes the last test run with coverage never executed or never energised (tinted). */
  coverage?: ReadonlyMap<string, "never-executed" | "never-energised">;
}

export interface FbdEditorProps {
  history: History<FbdBody>;
  onHistoryChange(history: History<FbdBody>): void;
  library?: readonly LibraryEntry[];
  symbols?: readonly SymbolInfo[];
  /** What a variable node's autocomplete offers after a qualifier (`T1.`, `Prog.`, `Color.`). */
  members?: MembersAfter;
  diagnostics?: readonly Diagnostic[];
  online?: FbdOnlineView;
  readOnly?: string | null;
  readOnlyActions?: ReactNode;
  onDeclareVariable?(declaration: VariableDeclaration): void;
  onlineActions?: LdOnlineActions;
  debug?: FbdDebug;
  focus?: { network?: string | null; element?: string | null; seq: number } | null;
  /** Told which networks are near the viewport, so online mode subscribes only to those. */
  onVisibleChange?(networks: readonly string[]): void;
  /** Told the input pins fed over feedback wires (order.ts feedbackPins), whose online values are what they read. */
  onFeedbackChange?(pins: ReadonlySet<string>): void;
  /** POST /api/fbd/order (replaced in tests); on a chart, its execution order (?chart=true). */
  orderOf?(network: FbdNetwork): Promise<FbdOrder>;
  /** A CFC POU: the body's one network is a free chart whose order list is the execution order (CFC-01/02). */
  chart?: boolean;
  /** On a chart: the FBD (data-flow) order of the chart, for "Order by data flow" (replaced in tests). */
  dataFlowOf?(network: FbdNetwork): Promise<FbdOrder>;
}

type PaletteKind =
  "input" | "output" | "block" | "jump" | "label" | "return" | "connector" | "continuation" | "comment";

const PALETTE: { kind: PaletteKind; label: string }[] = [
  { kind: "input", label: "Input" },
  { kind: "output", label: "Output" },
  { kind: "block", label: "Block…" },
  { kind: "jump", label: "Jump" },
  { kind: "label", label: "Label" }, // CFC only: FBD labels its networks
  { kind: "return", label: "Return" },
  { kind: "connector", label: "Connector" },
  { kind: "continuation", label: "Continuation" },
  { kind: "comment", label: "Comment box" },
];
const COLUMN_OF: Record<PaletteKind, number> = {
  input: 20,
  continuation: 20,
  block: 240,
  output: 480,
  jump: 480,
  label: 20,
  return: 480,
  connector: 480,
  comment: 20,
};
const WITH_TEXT = new Set(["input", "output", "jump", "label", "connector", "continuation", "comment"]);
const OUTPUT_MODES: { mode: OutputMode; label: string }[] = [
  { mode: "normal", label: "Output: normal" },
  { mode: "negated", label: "Output: negated" },
  { mode: "set", label: "Output: set (S)" },
  { mode: "reset", label: "Output: reset (R)" },
];
const NO_LIBRARY: readonly LibraryEntry[] = [];
const NO_SYMBOLS: readonly SymbolInfo[] = [];
const NO_DIAGNOSTICS: readonly Diagnostic[] = [];

/** The last clip copied in this tab, for toolbar paste when the browser keeps the clipboard closed. */
const lastClip: LastClip = { text: null };

export function FbdEditor({
  history,
  onHistoryChange,
  library = NO_LIBRARY,
  symbols = NO_SYMBOLS,
  members,
  diagnostics = NO_DIAGNOSTICS,
  online,
  readOnly = null,
  readOnlyActions,
  onDeclareVariable,
  onlineActions,
  debug,
  focus,
  chart = false,
  orderOf = chart ? fetchChartOrder : fetchOrder,
  dataFlowOf = fetchOrder,
  onVisibleChange,
  onFeedbackChange,
}: FbdEditorProps) {
  const body = history.present;
  const root = useRef<HTMLDivElement>(null);
  const [state, dispatch] = useReducer(fbdEditorReducer, INITIAL_STATE);
  const { selection, networkSelected, editing, networkText, picker, menu, message, offer, valuePrompt, help, near } =
    state;
  const setMessage = (text: string | null) => dispatch({ type: "message", text });
  const setEditing = (id: string | null) => dispatch({ type: "edit", id });
  const setNetworkText = (text: FbdEditorState["networkText"]) => dispatch({ type: "networkText", text });
  const setPicker = (at: FbdEditorState["picker"]) => dispatch({ type: "picker", at });
  const setOffer = (next: VariableDeclaration | null) => dispatch({ type: "offer", offer: next });
  const setValuePrompt = (request: ValueRequest | null) => dispatch({ type: "valuePrompt", request });

  const lookup = useLibraryLookup(library);
  const known = useMemo(() => symbolNames(symbols), [symbols]);
  const pickable = useMemo(() => pickableCalls(library, symbols, lookup), [library, symbols, lookup]);
  const onNear = useCallback(
    (network: string, isNear: boolean) => dispatch({ type: "near", network, near: isNear }),
    [],
  );
  useEffect(() => {
    onVisibleChange?.([...near]);
  }, [near, onVisibleChange]);
  const orders = useEvaluationOrder(body, orderOf, near);
  const networks = networksOf(body);
  useEffect(() => {
    const pins = new Set<string>();
    for (const network of networksOf(body)) {
      const order = orders.get(network.id);
      if (order) for (const pin of feedbackPins(network, order)) pins.add(pin);
    }
    onFeedbackChange?.(pins);
  }, [body, orders, onFeedbackChange]);
  const locked = readOnly !== null;

  // Nodes without a stored position (imported, hand-written) are drawn where auto-arrange would put them.
  const { heightOf, fallbacks } = useNodeLayout(networks, lookup, symbols);

  const byElement = useMemo(() => {
    const map = new Map<string, Diagnostic[]>();
    for (const d of diagnostics) if (d.element) map.set(d.element, [...(map.get(d.element) ?? []), d]);
    return map;
  }, [diagnostics]);

  const apply = useCallback(
    (result: ops.EditResult) => {
      if (result.ok) onHistoryChange(record(history, result.body));
      dispatch({ type: "edited", result });
      return result.ok;
    },
    [history, onHistoryChange],
  );

  const targetNetwork = () => targetNetworkOf(state, body);

  /** A free spot in the column new nodes of `kind` go to: below what is there. */
  const freeSpot = (network: FbdNetwork, kind: PaletteKind): Position => {
    const x = COLUMN_OF[kind];
    const below = nodesOf(network)
      .filter((n) => n.pos && Math.abs(n.pos.x - x) < 150)
      .map((n) => n.pos!.y + heightOf(network)(n) + 20);
    return { x, y: Math.max(20, ...below) };
  };

  /** Adds a node (creating the first network when there is none); text nodes open their editor. */
  const addNode = (spec: ops.NodeSpec, networkId: string | null, pos: Position | null) => {
    let base = body;
    let network = networkId;
    if (!network) {
      const created = ops.addNetwork(base);
      if (!created.ok) return;
      base = created.body;
      network = created.select[0]!;
    }
    const net = networksOf(base).find((n) => n.id === network)!;
    const result = ops.addNode(base, network, spec, pos ?? freeSpot(net, spec.type));
    if (apply(result) && result.ok && WITH_TEXT.has(spec.type)) setEditing(result.select[0]!);
    return result;
  };

  const paletteAdd = (kind: PaletteKind, network: string | null, pos: Position | null) => {
    if (kind === "block") setPicker({ network, pos });
    else addNode({ type: kind } as ops.NodeSpec, network, pos);
  };

  const pickBlock = (entry: LibraryEntry, en: boolean) => {
    const at = picker;
    setPicker(null);
    root.current?.focus();
    const used = new Set([...known, ...instancesOf(body)]);
    const instance = entry.kind === "function_block" ? instanceName(entry.name, used) : null;
    const result = addNode(
      { type: "block", call: entry.name, instance, en },
      at?.network ?? targetNetwork(),
      at?.pos ?? null,
    );
    if (result?.ok && instance && onDeclareVariable) setOffer({ name: instance, type: entry.name });
  };

  const commitEdit = (id: string, text: string) => {
    setEditing(null);
    root.current?.focus();
    const at = findNode(body, id);
    if (!at) return;
    const result = ops.setNodeText(body, id, text);
    if (!result.ok) return void setMessage(result.error);
    if (nodeChanged(body, result.body, id)) apply(result);
    const declaration = declareOffer(result.body, id, text, known, lookup, symbols);
    setOffer(declaration && onDeclareVariable ? declaration : null);
  };

  const selectedNodes = selection?.nodes ?? [];
  const deleteSelection = () => {
    const result = locked ? null : deletion(state, body);
    if (!result) return;
    if (apply(result) && selection) dispatch({ type: "select", selection: null });
  };

  const take = (cut: boolean): string | null => {
    const clip = clipOfSelection(state, body);
    if (!clip) return null;
    if (cut && !locked) apply(ops.deleteNodes(body, selection!.nodes));
    return serializeClip(clip);
  };
  const pasteText = (text: string | null) => {
    const clip = text ? parseClip(text) : null;
    const network = targetNetwork();
    if (!clip) return void setMessage("The clipboard holds no LadderLab FBD nodes.");
    if (!network) return void setMessage("Add a network to paste into.");
    apply(pasteClip(body, network, clip));
  };
  const editor = useEditorRoot({
    root,
    scope: "fbd",
    handlers: () => keyActions,
    busy: editing !== null || picker !== null || networkText !== null,
    clipboard: { take, paste: pasteText, isClip: (text) => parseClip(text) !== null, locked },
    last: lastClip,
  });

  const reorder = (delta: -1 | 1) => {
    const id = selectedNodes[0];
    const network = selection?.network;
    if (!id || !network) return;
    apply(moveInOrder(body, network, orders.get(network) ?? [], id, delta, chart));
  };

  /** A chart's "Order by data flow": each element after those feeding it, the current numbers breaking ties. */
  const orderChartByDataFlow = () => {
    const network = networks[0];
    if (!network) return;
    dataFlowOf(network).then(
      ({ order }) => apply(orderByDataFlow(body, network.id, order, orders.get(network.id) ?? [])),
      () => setMessage("The data-flow order could not be computed; try again in a moment."),
    );
  };

  const autoArrange = () => {
    const network = targetNetwork();
    const net = network && networks.find((n) => n.id === network);
    if (net) apply(ops.arrangeNetwork(body, net.id, heightOf(net), orders.get(net.id) ?? null, chart));
  };

  const addInput = (id: string) => apply(ops.addInput(body, id, lookup));

  // ------------------------------------------------------------ menus
  const openMenu = (event: MouseEvent, groups: MenuItem[][]) => {
    event.preventDefault();
    event.stopPropagation();
    const box = root.current?.getBoundingClientRect();
    dispatch({
      type: "menu",
      menu: {
        x: event.clientX - (box?.left ?? 0),
        y: event.clientY - (box?.top ?? 0),
        groups: groups.filter((g) => g.length),
      },
    });
  };

  const onlineItems = (operand: string | null): MenuItem[] => {
    if (!onlineActions || !operand) return [];
    return onlineOperandItems(operand, onlineActions, (action) => setValuePrompt({ operand, action }));
  };

  const nodeMenu = (network: string, node: FbdNode, event: MouseEvent) => {
    if (!selectedNodes.includes(node.id))
      dispatch({ type: "select", selection: { network, nodes: [node.id], edges: [] } });
    const kind = kindOf(node);
    const net = networks.find((n) => n.id === network)!;
    const edit: MenuItem[] = locked
      ? []
      : [
          ...(WITH_TEXT.has(kind) || kind === "block"
            ? [{ id: "edit", label: kind === "block" ? "Edit instance" : "Edit text", run: () => setEditing(node.id) }]
            : []),
          ...(kind === "block" && nextInput(node as Block, lookup((node as Block).call), wiresOf(net))
            ? [{ id: "add-input", label: "Add input", run: () => addInput(node.id) }]
            : []),
          ...(kind === "block"
            ? [
                {
                  id: "en",
                  label: (node as Block).en ? "Remove EN/ENO" : "Add EN/ENO",
                  run: () => apply(ops.toggleEn(body, node.id)),
                },
              ]
            : []),
          ...(kind === "output"
            ? OUTPUT_MODES.map(({ mode, label }) => ({
                id: `mode-${mode}`,
                label,
                run: () => apply(ops.setOutputMode(body, node.id, mode)),
              }))
            : []),
        ];
    const order: MenuItem[] =
      locked || !ordered(net, node.id, chart)
        ? []
        : [
            {
              id: "earlier",
              label: "Run earlier",
              keys: keysOf("fbd", "run-earlier"),
              run: () => apply(moveInOrder(body, network, orders.get(network) ?? [], node.id, -1, chart)),
            },
            {
              id: "later",
              label: "Run later",
              keys: keysOf("fbd", "run-later"),
              run: () => apply(moveInOrder(body, network, orders.get(network) ?? [], node.id, 1, chart)),
            },
          ];
    const debugItems: MenuItem[] = debug
      ? [
          {
            id: "breakpoint",
            label: debug.elements.has(node.id) ? "Remove breakpoint" : "Set breakpoint",
            keys: keysOf("fbd", "toggle-breakpoint"),
            run: () => debug.toggle({ element: node.id }),
          },
        ]
      : [];
    const clip: MenuItem[] = [
      { id: "copy", label: "Copy", keys: keysOf("fbd", "copy"), run: () => editor.copy(false) },
      ...(locked
        ? []
        : [
            {
              id: "delete",
              label: "Delete",
              keys: keysOf("fbd", "delete"),
              run: () => apply(ops.deleteNodes(body, selectedNodes.includes(node.id) ? selectedNodes : [node.id])),
            },
          ]),
    ];
    const operand = operandOf(node);
    const named = nodeVariable(node);
    const references: MenuItem[] = named ? [referencesItem(named)] : [];
    // The declare dialog again (after Escape, or for a name pasted in): the node's undeclared variable.
    const offered =
      named && onDeclareVariable && !locked ? declareOffer(body, node.id, named, known, lookup, symbols) : null;
    const declare: MenuItem[] = offered
      ? [{ id: "declare", label: `Declare ${offered.name}…`, run: () => setOffer(offered) }]
      : [];
    openMenu(event, [onlineItems(operand), edit, declare, order, debugItems, references, clip]);
  };

  const pinMenu = (node: FbdNode, pin: string, side: "in" | "out", event: MouseEvent) => {
    if (locked) return;
    const at = findNode(body, node.id);
    if (!at) return;
    const flags = kindOf(node) === "block" ? ((node as Block).pins?.[pin] ?? {}) : null;
    const flagItems: MenuItem[] = flags
      ? [
          {
            id: "negate",
            label: flags.negated ? `Remove negation of ${pin}` : `Negate ${pin}`,
            run: () => apply(ops.togglePinFlag(body, node.id, pin, "negated", side)),
          },
          ...(side === "in"
            ? (["rising", "falling"] as const).map((edge) => ({
                id: edge,
                label:
                  flags.edge === edge
                    ? `Remove ${edge} edge`
                    : `${edge === "rising" ? "Rising" : "Falling"} edge on ${pin}`,
                run: () => apply(ops.togglePinFlag(body, node.id, pin, edge, side)),
              }))
            : []),
        ]
      : [];
    const wired = ops.wiresAt(at.network, { node: node.id, pin }, side);
    const wireItems: MenuItem[] = wired.length
      ? [{ id: "disconnect", label: `Disconnect ${pin}`, run: () => apply(ops.disconnect(body, at.network.id, wired)) }]
      : [];
    openMenu(event, [flagItems, wireItems]);
  };

  // ------------------------------------------------------------ views
  const chartNumbers = useMemo(() => {
    const network = networks[0];
    const order = chart && network ? orders.get(network.id) : undefined;
    return network && order ? orderNumbers(network, order) : null;
  }, [chart, networks, orders]);
  const view = useCallback(
    (network: FbdNetwork, node: FbdNode): NodeView => {
      const order = chartNumbers ? (chartNumbers.get(node.id) ?? -1) - 1 : orders.get(network.id)?.indexOf(node.id);
      return {
        pins: nodePins(node, network, lookup, symbols),
        order: order !== undefined && order >= 0 ? order + 1 : undefined,
        diagnostics: byElement.get(node.id) ?? NO_DIAGNOSTICS,
        breakpoint: debug?.elements.has(node.id) ?? false,
        halted: debug?.halted?.element === node.id,
        fb: kindOf(node) === "block" && lookup((node as Block).call)?.kind === "function_block",
        coverage: debug?.coverage?.get(node.id),
      };
    },
    [orders, chartNumbers, lookup, symbols, byElement, debug],
  );

  /** Prepares a value for `operand` (CODESYS double-click): a BOOL toggles, others ask for the value. */
  const prepare = (operand: string | null, type?: string) => {
    if (onlineActions && operand && !onlineActions.prepare(operand, undefined, type))
      setValuePrompt({ operand, action: "prepare" });
  };
  const api: FbdEditorApi = {
    readOnly: locked,
    symbols,
    members,
    online,
    editing,
    view,
    startEdit: (id) => !locked && setEditing(id),
    commitEdit,
    cancelEdit: () => {
      setEditing(null);
      root.current?.focus();
    },
    pinMenu,
    valueDoubleClick: (node) => prepare(operandOf(node)),
    pinDoubleClick: (node, side, pin) => {
      const network = findNode(body, node.id)?.network;
      const pins = network ? nodePins(node, network, lookup, symbols) : null;
      const type = (side === "in" ? pins?.inputs : pins?.outputs)?.find((p) => p.name === pin)?.type;
      prepare(pinOperand(body, node as Block, side, pin, lookup), type);
    },
  };

  const onSelectChanges = useCallback(
    (
      network: string,
      nodes: readonly { id: string; selected: boolean }[],
      edges: readonly { id: string; selected: boolean }[],
    ) => dispatch({ type: "selectChanges", network, nodes, edges }),
    [],
  );

  const onConnect = (network: string, c: Connection) => {
    if (locked) return;
    apply(
      ops.connect(
        body,
        network,
        {
          from: { node: c.source, pin: pinOfHandle(c.sourceHandle) },
          to: { node: c.target, pin: pinOfHandle(c.targetHandle) },
        },
        lookup,
        symbols,
      ),
    );
  };
  const refusalOf = (network: string, c: Connection) => {
    const net = networks.find((n) => n.id === network);
    return net
      ? refusal(
          net,
          {
            from: { node: c.source, pin: pinOfHandle(c.sourceHandle) },
            to: { node: c.target, pin: pinOfHandle(c.targetHandle) },
          },
          lookup,
          symbols,
        )
      : null;
  };

  // A new halt place or a clicked diagnostic selects the place (while rendering, as the request
  // arrives: later edits do not move the selection) and scrolls its network into view.
  const halted = debug?.halted;
  const haltKey = halted ? `${halted.network ?? ""}:${halted.element ?? ""}` : null;
  if (revealPending(state, haltKey, focus?.seq ?? null))
    dispatch({ type: "reveal", halt: { key: haltKey, place: halted }, focus, body });
  const { revealed } = state;
  useEffect(() => {
    const network = revealed.network;
    if (network)
      root.current?.querySelector(`[data-network="${CSS.escape(network)}"]`)?.scrollIntoView?.({ block: "center" });
  }, [revealed]);

  /** What each FBD key does (src/keys/keymap.ts, scope "fbd"); false when it does not apply now. */
  const keyActions: KeyHandlers<"fbd"> = {
    delete: () => (deleteSelection(), true),
    undo: () => !locked && (onHistoryChange(undo(history)), true),
    redo: () => !locked && (onHistoryChange(redo(history)), true),
    "run-earlier": () => (reorder(-1), true),
    "run-later": () => (reorder(1), true),
    "clear-selection": () => (dispatch({ type: "clear" }), true),
    "toggle-breakpoint": () => {
      const target = breakpointTarget(state);
      if (!debug || !target) return false;
      debug.toggle(target);
      return true;
    },
    "zoom-fit": () => (dispatch({ type: "fit" }), true),
  };

  const single = singleNode(state);
  const selectedBlock = single ? findNode(body, single)?.node : undefined;
  const netIndex = selectedNetworkIndex(state, body);
  const tool = (id: string, label: string, run: () => void, enabled = !locked, keys?: string, hint?: string): Tool => ({
    id,
    icon: COMMAND_ICONS[id]!,
    label,
    run,
    disabled: !enabled,
    keys,
    hint,
  });

  // The toolbar, one row: as it narrows, the network and clipboard tools go into More first, the palette last.
  const grouped = (tools: (Tool | null)[], priority: number): BarItem[] =>
    tools.filter((t): t is Tool => t !== null).map((t, i) => toolItem(t, { group: i === 0, priority }));
  const toolbarItems: BarItem[] = [
    ...PALETTE.filter(({ kind }) => chart || kind !== "label").map(({ kind, label }, i): BarItem => ({
      key: `palette-${kind}`,
      node: (
        <button
          type="button"
          className="tool-button"
          aria-label={label}
          draggable={!locked}
          disabled={locked}
          title={`Add ${label.replace("…", "")} (or drag it onto a network)`}
          onDragStart={(e) => {
            e.dataTransfer.setData(DRAG_FORMAT, kind);
            e.dataTransfer.effectAllowed = "copy";
          }}
          onClick={() => paletteAdd(kind, targetNetwork(), null)}
        >
          <PaletteIcon kind={kind} />
        </button>
      ),
      entries: [
        {
          id: `palette-${kind}`,
          label: `Add ${label}`,
          disabled: locked,
          run: () => paletteAdd(kind, targetNetwork(), null),
        },
      ],
      group: i === 0,
      priority: 3,
    })),
    ...grouped(
      [
        tool(
          "add-input",
          "Add input",
          () => selectedBlock && addInput(selectedBlock.id),
          !locked &&
            !!selectedBlock &&
            kindOf(selectedBlock) === "block" &&
            !!nextInput(
              selectedBlock as Block,
              lookup((selectedBlock as Block).call),
              wiresOf(findNode(body, selectedBlock.id)!.network),
            ),
        ),
        tool("run-earlier", "Run earlier", () => reorder(-1), !locked && !!selectedBlock, keyed("run-earlier")),
        tool("run-later", "Run later", () => reorder(1), !locked && !!selectedBlock, keyed("run-later")),
        chart
          ? tool(
              "order-by-flow",
              "Order by data flow",
              orderChartByDataFlow,
              !locked && networks.length > 0,
              undefined,
              "Number every element after the elements feeding it (the current numbers break ties)",
            )
          : null,
        tool("arrange", "Auto-arrange", autoArrange, !locked && networks.length > 0),
        tool(
          "zoom-fit",
          "Zoom to fit",
          () => dispatch({ type: "fit" }),
          networks.length > 0,
          keyed("zoom-fit"),
          "Zoom every network so all its nodes show",
        ),
        tool("delete", "Delete", deleteSelection, !locked && (!!selection || !!networkSelected), keyed("delete")),
      ],
      2,
    ),
    ...(chart
      ? []
      : grouped(
          [
            tool("network-add", "Add network", () =>
              apply(ops.addNetwork(body, netIndex < 0 ? networks.length : netIndex + 1)),
            ),
            tool(
              "network-up",
              "Network up",
              () => apply(ops.moveNetwork(body, networks[netIndex]!.id, -1)),
              !locked && netIndex > 0,
            ),
            tool(
              "network-down",
              "Network down",
              () => apply(ops.moveNetwork(body, networks[netIndex]!.id, 1)),
              !locked && netIndex >= 0 && netIndex < networks.length - 1,
            ),
            tool(
              "network-label",
              "Label",
              () => setNetworkText({ network: networks[netIndex]!.id, field: "label" }),
              !locked && netIndex >= 0,
            ),
            tool(
              "network-comment",
              "Comment",
              () => setNetworkText({ network: networks[netIndex]!.id, field: "comment" }),
              !locked && netIndex >= 0,
            ),
          ],
          0,
        )),
    ...grouped(
      [
        tool("copy", "Copy", () => editor.copy(false), selectedNodes.length > 0, keyed("copy")),
        tool("paste", "Paste", editor.paste, !locked, keyed("paste")),
        tool("undo", "Undo", () => onHistoryChange(undo(history)), !locked && canUndo(history), keyed("undo")),
        tool("redo", "Redo", () => onHistoryChange(redo(history)), !locked && canRedo(history), keyed("redo")),
      ],
      1,
    ),
    helpItem(help, () => dispatch({ type: "help", open: "toggle" })),
  ];

  return (
    <FbdEditorContext.Provider value={api}>
      <div
        className={`fbd-editor${locked ? " fbd-readonly" : ""}`}
        {...editor.rootProps}
        role="application"
        aria-label={chart ? "Continuous function chart editor" : "Function block diagram editor"}
      >
        <OverflowBar
          className="ld-toolbar fbd-toolbar"
          label="FBD editing"
          moreLabel="More tools"
          items={toolbarItems}
        />
        {help ? <ShortcutHelp scopes={["fbd", "app"]} onClose={() => dispatch({ type: "help", open: false })} /> : null}
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
        <div className="fbd-networks">
          {networks.map((network, index) => (
            <NetworkCanvas
              key={network.id}
              network={network}
              index={index}
              chart={chart}
              readOnly={locked}
              selected={selection?.network === network.id ? selection : null}
              networkSelected={networkSelected === network.id}
              online={online}
              problems={diagnostics.filter((d) => d.network === network.id && !d.element)}
              breakpoint={debug?.networks.has(network.id) ?? false}
              halted={halted?.network === network.id}
              fallback={fallbacks.get(network.id)!}
              fitRequest={state.fitRequest}
              height={heightOf(network)}
              overlay={
                networkText?.network === network.id ? (
                  <OperandEditor
                    key={networkText.field}
                    label={networkText.field === "label" ? "Network label" : "Network comment"}
                    initial={network[networkText.field] ?? ""}
                    onCommit={(text) => {
                      setNetworkText(null);
                      root.current?.focus();
                      if (text !== (network[networkText.field] ?? ""))
                        apply(ops.setNetworkText(body, network.id, networkText.field, text));
                    }}
                    onCancel={() => setNetworkText(null)}
                  />
                ) : null
              }
              onSelectChanges={onSelectChanges}
              onSelectNetwork={(network) => dispatch({ type: "selectNetwork", network })}
              onToggleBreakpoint={(id) => debug?.toggle({ network: id })}
              onEditText={(id, field) => !locked && setNetworkText({ network: id, field })}
              onMove={(_id, positions) => {
                const moved = [...positions].some(([id, p]) => {
                  const old = findNode(body, id)?.node.pos;
                  return !old || old.x !== p.x || old.y !== p.y;
                });
                if (moved && !locked) apply(ops.moveNodes(body, positions));
              }}
              onConnect={onConnect}
              refusal={refusalOf}
              onRefused={setMessage}
              onDropNew={(id, kind, pos) =>
                paletteAdd(kind as PaletteKind, id, { x: Math.round(pos.x), y: Math.round(pos.y) })
              }
              onNodeContextMenu={nodeMenu}
              onNear={onNear}
              onNodeClick={(_id, node, event) => {
                if (event.altKey && debug) debug.toggle({ element: node.id });
              }}
            />
          ))}
        </div>
        {networks.length === 0 ? (
          <p className="ld-empty-hint">This POU has no networks yet: add a node from the palette, or "Add network".</p>
        ) : null}
        {menu ? (
          <MenuList x={menu.x} y={menu.y} groups={menu.groups} onClose={() => dispatch({ type: "menu", menu: null })} />
        ) : null}
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
        {picker ? (
          <BoxPicker
            library={pickable}
            title="Insert block"
            defaultEn={() => false}
            onPick={pickBlock}
            onCancel={() => {
              setPicker(null);
              root.current?.focus();
            }}
          />
        ) : null}
      </div>
    </FbdEditorContext.Provider>
  );
}
