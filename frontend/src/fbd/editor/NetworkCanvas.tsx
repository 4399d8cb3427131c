// One FBD network: its header (number - click for a breakpoint -, label, comment, network-level
// problems) and its own xyflow canvas (pan, zoom, handles, edges from the library). Canvases of
// networks far outside the viewport are not mounted, so large POUs stay usable.
import {
  Background,
  Controls,
  MarkerType,
  ReactFlow,
  ReactFlowProvider,
  useConnection,
  useNodesInitialized,
  useReactFlow,
  ViewportPortal,
  type Connection,
  type Edge,
  type EdgeChange,
  type NodeChange,
} from "@xyflow/react";
import { useEffect, useMemo, useRef, useState, type DragEvent, type MouseEvent, type ReactNode } from "react";
import type { Diagnostic } from "../../generated/api";
import { nodesOf, wireKey, wiresOf, type FbdNetwork, type FbdNode, type Position } from "../model";
import { probeOf, type FbdOnlineView } from "../online";
import { FbdNodeView, type FbdFlowNode } from "./FbdNodeView";
import { OrthogonalEdge } from "./OrthogonalEdge";
import { fitZoom } from "../../ui/zoom";

export const DRAG_FORMAT = "application/x-ladderlab-fbd";
const NODE_TYPES = { fbd: FbdNodeView };
const EDGE_TYPES = { orthogonal: OrthogonalEdge };
const MIN_HEIGHT = 170;
/** Room above and left of the diagram, so badges above a node at y = 0 (order, breakpoint) stay in view. */
const ORIGIN = { x: 12, y: 16, zoom: 1 };
const MAX_HEIGHT = 560;
const CHART_HEIGHT = 420;
const MIN_ZOOM = 0.25;
const MAX_ZOOM = 2;

export interface NetworkSelection {
  nodes: readonly string[];
  edges: readonly string[];
}

export interface NetworkCanvasProps {
  network: FbdNetwork;
  index: number;
  /** The one chart of a CFC POU: no network number, label or comment; drawn at least CHART_HEIGHT high. */
  chart?: boolean;
  readOnly: boolean;
  selected: NetworkSelection | null;
  /** The whole network is selected (its header was clicked). */
  networkSelected: boolean;
  online?: FbdOnlineView;
  /** Problems naming this network but no node. */
  problems: readonly Diagnostic[];
  breakpoint: boolean;
  halted: boolean;
  /** Where nodes without a stored position are drawn. */
  fallback: ReadonlyMap<string, Position>;
  height: (node: FbdNode) => number;
  overlay?: ReactNode;
  onSelectChanges(
    network: string,
    nodes: readonly { id: string; selected: boolean }[],
    edges: readonly { id: string; selected: boolean }[],
  ): void;
  onSelectNetwork(network: string): void;
  onToggleBreakpoint(network: string): void;
  onEditText(network: string, field: "label" | "comment"): void;
  onMove(network: string, positions: ReadonlyMap<string, Position>): void;
  onConnect(network: string, connection: Connection): void;
  /** Why a wire was refused (null: it is fine). */
  refusal(network: string, connection: Connection): string | null;
  onRefused(reason: string): void;
  onDropNew(network: string, kind: string, pos: Position): void;
  onNodeContextMenu(network: string, node: FbdNode, event: MouseEvent): void;
  onNodeClick(network: string, node: FbdNode, event: MouseEvent): void;
  /** Told when the network comes near the viewport or leaves it (only those are online and get order badges). */
  onNear(network: string, near: boolean): void;
  /** Drawn for a printed document (src/print): always mounted, every node shown, no controls or grid. */
  print?: boolean;
  /** Counts the editor's "Zoom to fit" requests: each new one fits every node into the canvas (0: none yet). */
  fitRequest?: number;
}

/** Print: once the nodes are measured, zoom so the whole network fits the width, and say the height it needs. */
function usePrintFit(
  print: boolean | undefined,
  host: React.RefObject<HTMLDivElement | null>,
  fit: (h: number) => void,
) {
  const flow = useReactFlow();
  const initialized = useNodesInitialized();
  useEffect(() => {
    if (!print || !initialized) return;
    const bounds = flow.getNodesBounds(flow.getNodes());
    const width = host.current?.clientWidth || 1000;
    const zoom = Math.min(1, width / (bounds.x + bounds.width + 2 * ORIGIN.x));
    void flow.setViewport({ x: ORIGIN.x * zoom, y: ORIGIN.y * zoom, zoom });
    fit(Math.ceil((bounds.y + bounds.height + 2 * ORIGIN.y) * zoom));
  }, [print, initialized, flow, host, fit]);
}

/** The editor's "Zoom to fit" (toolbar, Ctrl+Shift+H): once measured, every node of the network in view (ui/zoom.ts). */
function useFitRequest(request: number | undefined, host: React.RefObject<HTMLDivElement | null>) {
  const flow = useReactFlow();
  const initialized = useNodesInitialized();
  useEffect(() => {
    const view = host.current;
    if (!request || !initialized || !view) return;
    const bounds = flow.getNodesBounds(flow.getNodes());
    const content = { width: bounds.width + 2 * ORIGIN.x, height: bounds.height + 2 * ORIGIN.y };
    const zoom = fitZoom(content, { width: view.clientWidth, height: view.clientHeight }, MIN_ZOOM, MAX_ZOOM);
    void flow.setViewport({ x: (ORIGIN.x - bounds.x) * zoom, y: (ORIGIN.y - bounds.y) * zoom, zoom });
  }, [request, initialized, flow, host]);
}

/** The canvas height that shows every node of the network at zoom 1 (at most MAX_HEIGHT on screen). */
export function canvasHeight(
  network: FbdNetwork,
  fallback: ReadonlyMap<string, Position>,
  height: (node: FbdNode) => number,
  limit = MAX_HEIGHT,
): number {
  const bottom = Math.max(0, ...nodesOf(network).map((n) => (n.pos ?? fallback.get(n.id) ?? { y: 0 }).y + height(n)));
  return Math.min(limit, Math.max(MIN_HEIGHT, bottom + 50));
}

function wireClass(value: unknown): string {
  if (value === true) return "fbd-wire fbd-wire-on";
  if (value === false) return "fbd-wire fbd-wire-off";
  return "fbd-wire";
}

/** While a wire is dragged over a pin it may not connect to, the reason next to the pointer. */
function ConnectionHint({ refusal }: { refusal(c: Connection): string | null }) {
  const connection = useConnection();
  if (!connection.inProgress || !connection.toHandle || connection.isValid !== false) return null;
  const [from, to] =
    connection.fromHandle.type === "source"
      ? [connection.fromHandle, connection.toHandle]
      : [connection.toHandle, connection.fromHandle];
  const why = refusal({
    source: from.nodeId,
    sourceHandle: from.id ?? null,
    target: to.nodeId,
    targetHandle: to.id ?? null,
  });
  if (!why) return null;
  return (
    <ViewportPortal>
      <div
        className="fbd-connection-hint"
        role="tooltip"
        style={{ transform: `translate(${connection.to.x + 14}px, ${connection.to.y + 14}px)` }}
      >
        {why}
      </div>
    </ViewportPortal>
  );
}

function Canvas(props: NetworkCanvasProps & { onPrintHeight(height: number): void }) {
  const { network, readOnly, selected, online, fallback } = props;
  const flow = useReactFlow();
  const host = useRef<HTMLDivElement>(null);
  usePrintFit(props.print, host, props.onPrintHeight);
  useFitRequest(props.fitRequest, host);
  const built = useMemo(
    (): FbdFlowNode[] =>
      nodesOf(network).map((node) => ({
        id: node.id,
        type: "fbd",
        position: node.pos ?? fallback.get(node.id) ?? { x: 0, y: 0 },
        data: { network, node },
        selected: selected?.nodes.includes(node.id) ?? false,
      })),
    [network, selected, fallback],
  );
  // xyflow measures nodes once they are drawn; the sizes stay on our copies across model edits
  // (taken over while rendering the new model, not in an effect after it).
  const [nodes, setNodes] = useState(built);
  const [builtSeen, setBuiltSeen] = useState(built);
  if (built !== builtSeen) {
    setBuiltSeen(built);
    const old = new Map(nodes.map((n) => [n.id, n]));
    setNodes(built.map((n) => ({ ...n, measured: old.get(n.id)?.measured })));
  }
  const edges = useMemo(
    (): Edge[] =>
      wiresOf(network).map((w) => {
        const id = wireKey(w);
        const probe = online ? probeOf(network, w.from) : null;
        const value = probe ? online?.probes[probe] : undefined;
        // The value shows at the pins (FbdNodeView), the wire its BOOL state by colour.
        return {
          id,
          type: "orthogonal",
          source: w.from.node,
          sourceHandle: `out:${w.from.pin}`,
          target: w.to.node,
          targetHandle: `in:${w.to.pin}`,
          selected: selected?.edges.includes(id) ?? false,
          className: wireClass(value),
          markerEnd: { type: MarkerType.ArrowClosed, width: 12, height: 12 },
        };
      }),
    [network, selected, online],
  );

  const onNodesChange = (changes: NodeChange<FbdFlowNode>[]) => {
    const kept = changes.filter((c) => c.type === "dimensions" || c.type === "position");
    if (kept.length) {
      setNodes((current) =>
        current.map((n) => {
          let next = n;
          for (const c of kept) {
            if (c.id !== n.id) continue;
            if (c.type === "dimensions" && c.dimensions) next = { ...next, measured: c.dimensions };
            if (c.type === "position" && c.position) next = { ...next, position: c.position };
          }
          return next;
        }),
      );
    }
    const select = changes.flatMap((c) => (c.type === "select" ? [{ id: c.id, selected: c.selected }] : []));
    if (select.length) props.onSelectChanges(network.id, select, []);
  };
  const onEdgesChange = (changes: EdgeChange[]) => {
    const select = changes.flatMap((c) => (c.type === "select" ? [{ id: c.id, selected: c.selected }] : []));
    if (select.length) props.onSelectChanges(network.id, [], select);
  };

  const drop = (event: DragEvent) => {
    const kind = event.dataTransfer.getData(DRAG_FORMAT);
    if (!kind || readOnly) return;
    event.preventDefault();
    props.onDropNew(network.id, kind, flow.screenToFlowPosition({ x: event.clientX, y: event.clientY }));
  };

  const asConnection = (c: Connection | Edge): Connection => ({
    source: c.source,
    target: c.target,
    sourceHandle: c.sourceHandle ?? null,
    targetHandle: c.targetHandle ?? null,
  });
  return (
    <div
      className="fbd-canvas"
      ref={host}
      onDragOver={(e) => {
        if (e.dataTransfer.types.includes(DRAG_FORMAT)) e.preventDefault();
      }}
      onDrop={drop}
    >
      <ReactFlow<FbdFlowNode>
        nodes={nodes}
        edges={edges}
        nodeTypes={NODE_TYPES}
        edgeTypes={EDGE_TYPES}
        onNodesChange={onNodesChange}
        onEdgesChange={onEdgesChange}
        onNodeDragStop={(_e, _node, dragged) =>
          props.onMove(
            network.id,
            new Map(dragged.map((n) => [n.id, { x: Math.round(n.position.x), y: Math.round(n.position.y) }])),
          )
        }
        onConnect={(c) => props.onConnect(network.id, c)}
        isValidConnection={(c) => props.refusal(network.id, asConnection(c)) === null}
        onConnectEnd={(_e, state) => {
          if (state.isValid !== false || !state.fromHandle || !state.toHandle) return;
          const [from, to] =
            state.fromHandle.type === "source"
              ? [state.fromHandle, state.toHandle]
              : [state.toHandle, state.fromHandle];
          const why = props.refusal(network.id, {
            source: from.nodeId,
            sourceHandle: from.id ?? null,
            target: to.nodeId,
            targetHandle: to.id ?? null,
          });
          if (why) props.onRefused(why);
        }}
        onNodeContextMenu={(e, n) => props.onNodeContextMenu(network.id, n.data.node, e)}
        onNodeClick={(e, n) => props.onNodeClick(network.id, n.data.node, e)}
        nodesDraggable={!readOnly}
        nodesConnectable={!readOnly}
        deleteKeyCode={null}
        selectionKeyCode={null}
        multiSelectionKeyCode="Shift"
        zoomOnScroll={false}
        zoomOnDoubleClick={false}
        preventScrolling={false}
        zoomActivationKeyCode="Control"
        defaultViewport={ORIGIN}
        minZoom={MIN_ZOOM}
        maxZoom={MAX_ZOOM}
        proOptions={{ hideAttribution: true }}
      >
        {props.print ? null : <Background gap={20} size={1} />}
        <ConnectionHint refusal={(c) => props.refusal(network.id, c)} />
        {props.print ? null : <Controls showInteractive={false} position="bottom-right" />}
      </ReactFlow>
    </div>
  );
}

/** Mounts its children only while near the viewport (no IntersectionObserver, as in tests: always). */
function useNearViewport(): [React.RefObject<HTMLDivElement | null>, boolean] {
  const ref = useRef<HTMLDivElement>(null);
  const [near, setNear] = useState(typeof IntersectionObserver === "undefined");
  useEffect(() => {
    if (typeof IntersectionObserver === "undefined" || !ref.current) return;
    const observer = new IntersectionObserver(([entry]) => setNear(entry?.isIntersecting ?? true), {
      rootMargin: "400px 0px",
    });
    observer.observe(ref.current);
    return () => observer.disconnect();
  }, []);
  return [ref, near];
}

export function NetworkCanvas(props: NetworkCanvasProps) {
  const { network, index } = props;
  const [ref, nearViewport] = useNearViewport();
  const near = nearViewport || props.print === true;
  const { onNear } = props;
  useEffect(() => {
    onNear(network.id, near);
  }, [onNear, network.id, near]);
  useEffect(() => () => onNear(network.id, false), [onNear, network.id]);
  const [printHeight, setPrintHeight] = useState<number | null>(null);
  const fitted = canvasHeight(network, props.fallback, props.height, props.print ? Infinity : MAX_HEIGHT);
  const height = printHeight ?? (props.chart ? Math.max(CHART_HEIGHT, fitted) : fitted);
  const classes = [
    "fbd-network",
    props.networkSelected ? "fbd-network-selected" : "",
    props.halted ? "fbd-network-halted" : "",
  ]
    .filter(Boolean)
    .join(" ");
  return (
    <section
      className={classes}
      ref={ref}
      data-network={network.id}
      aria-label={props.chart ? "CFC chart" : `Network ${index + 1}`}
    >
      <header className="fbd-network-header" onMouseDown={() => props.onSelectNetwork(network.id)}>
        <button
          type="button"
          className={`fbd-network-number${props.breakpoint ? " fbd-has-breakpoint" : ""}`}
          title={props.chart ? "Toggle a breakpoint on the chart" : "Toggle a breakpoint on this network"}
          aria-pressed={props.breakpoint}
          onClick={() => props.onToggleBreakpoint(network.id)}
        >
          {props.chart ? "CFC" : index + 1}
        </button>
        {props.chart ? null : (
          <>
            <span className="fbd-network-label" onDoubleClick={() => props.onEditText(network.id, "label")}>
              {network.label ? `${network.label}:` : ""}
            </span>
            <span className="fbd-network-comment" onDoubleClick={() => props.onEditText(network.id, "comment")}>
              {network.comment ?? ""}
            </span>
          </>
        )}
        {props.problems.map((d, i) => (
          <span key={i} className="fbd-network-problem" role="note">
            {d.code}: {d.message}
          </span>
        ))}
      </header>
      {props.overlay}
      <div style={{ height }}>
        {near ? (
          <ReactFlowProvider>
            <Canvas {...props} onPrintHeight={setPrintHeight} />
          </ReactFlowProvider>
        ) : (
          <div className="fbd-canvas-placeholder">{nodesOf(network).length} nodes</div>
        )}
      </div>
    </section>
  );
}
