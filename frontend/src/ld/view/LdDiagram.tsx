// The scrolling, virtualised LD diagram: networks are stacked at the offsets the layout computed,
// and only those intersecting the viewport (plus a margin) are rendered, so a 1,000-network POU
// opens and scrolls as fast as a small one.
import { useCallback, useEffect, useLayoutEffect, useMemo, useRef, useState, type ReactNode } from "react";
import type { Diagnostic } from "../../generated/api";
import type { LdLayout, NetworkLayout } from "../layout";
import { locate, networkOfSeries, type LdBody } from "../model";
import { NetworkView } from "./NetworkView";
import type { DebugMarks, DiagramHandlers, OnlineView, Selection } from "./types";

export interface LdDiagramProps {
  body: LdBody;
  layout: LdLayout;
  selection: Selection | null;
  diagnostics?: readonly Diagnostic[];
  online?: OnlineView;
  dropping?: boolean;
  handlers?: DiagramHandlers;
  /** Network to scroll into view (the one holding the selection). */
  reveal?: string | null;
  /** Viewport height to assume before the browser has measured one (and in tests). */
  fallbackHeight?: number;
  /** Drawn over the diagram in diagram coordinates (the operand editor), scrolling with it. */
  overlay?: ReactNode;
  /** Told the ids of the networks rendered whenever they change (online mode subscribes to them). */
  onVisibleChange?(networks: readonly string[]): void;
  /** Breakpoints and the halt; a new halt is scrolled into view. */
  debug?: DebugMarks;
  /** Scale of the drawing (1 = 100 %); the editor's zoom. */
  zoom?: number;
}

const OVERSCAN = 400;
const NO_DIAGNOSTICS: readonly Diagnostic[] = [];
const NO_HANDLERS: DiagramHandlers = {};

/** Index of the first network whose bottom is below `y` (binary search over the offsets). */
export function firstVisible(networks: readonly NetworkLayout[], y: number): number {
  let lo = 0;
  let hi = networks.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    const n = networks[mid]!;
    if (n.top + n.height <= y) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

/** The networks to render for a viewport. */
export function visibleNetworks(layout: LdLayout, scrollTop: number, height: number): NetworkLayout[] {
  const out: NetworkLayout[] = [];
  const bottom = scrollTop + height + OVERSCAN;
  for (let i = firstVisible(layout.networks, Math.max(0, scrollTop - OVERSCAN)); i < layout.networks.length; i += 1) {
    const n = layout.networks[i]!;
    if (n.top > bottom) break;
    out.push(n);
  }
  return out;
}

/** The network a selection is in, so only that network's view sees it. */
function selectionNetwork(body: LdBody, selection: Selection | null): string | null {
  if (!selection) return null;
  if (selection.kind === "network") return selection.id;
  if (selection.kind === "place") return networkOfSeries(body, selection.place.series) ?? null;
  const first = selection.ids[0];
  return first ? (locate(body, first)?.network ?? null) : null;
}

export function LdDiagram({
  body,
  layout,
  selection,
  diagnostics = NO_DIAGNOSTICS,
  online,
  dropping = false,
  handlers = NO_HANDLERS,
  reveal,
  fallbackHeight = 900,
  overlay,
  onVisibleChange,
  debug,
  zoom = 1,
}: LdDiagramProps) {
  const scroller = useRef<HTMLDivElement>(null);
  const [viewport, setViewport] = useState({ top: 0, height: fallbackHeight });

  useLayoutEffect(() => {
    const el = scroller.current;
    if (!el) return;
    const measure = () => setViewport({ top: el.scrollTop, height: el.clientHeight || fallbackHeight });
    measure();
    if (typeof ResizeObserver === "undefined") return;
    const observer = new ResizeObserver(measure);
    observer.observe(el);
    return () => observer.disconnect();
  }, [fallbackHeight]);

  /** Scrolls the least that brings network `id` into view, and reads the scroll position back. */
  const scrollTo = useCallback(
    (id: string | null | undefined) => {
      const el = scroller.current;
      const target = id ? layout.networks.find((n) => n.network.id === id) : undefined;
      if (!el || !target) return;
      const height = el.clientHeight || fallbackHeight;
      const top = target.top * zoom; // the scroller's pixels are zoomed, the layout's are not
      const bottom = (target.top + target.height) * zoom;
      if (top < el.scrollTop) el.scrollTop = top;
      else if (bottom > el.scrollTop + height) el.scrollTop = Math.max(0, bottom - height);
      setViewport({ top: el.scrollTop, height });
    },
    [layout, fallbackHeight, zoom],
  );
  useEffect(() => {
    scrollTo(reveal);
  }, [reveal, scrollTo]);
  // A halt (or a step to another network) is shown wherever the user had scrolled.
  const haltedNetwork = debug?.halted?.network;
  useEffect(() => {
    scrollTo(haltedNetwork);
  }, [haltedNetwork, scrollTo]);

  const byNetwork = useMemo(() => {
    const map = new Map<string, Diagnostic[]>();
    for (const d of diagnostics) if (d.network) map.set(d.network, [...(map.get(d.network) ?? []), d]);
    return map;
  }, [diagnostics]);

  const selected = selectionNetwork(body, selection);
  const shown = visibleNetworks(layout, viewport.top / zoom, viewport.height / zoom);
  const shownKey = shown.map((n) => n.network.id).join("\n");
  useEffect(() => {
    onVisibleChange?.(shownKey ? shownKey.split("\n") : []);
  }, [shownKey, onVisibleChange]);
  return (
    <div
      className="ld-scroller"
      ref={scroller}
      onScroll={(e) =>
        setViewport({ top: e.currentTarget.scrollTop, height: e.currentTarget.clientHeight || fallbackHeight })
      }
    >
      <div className="ld-canvas" style={{ height: layout.height, width: layout.width, zoom }}>
        {shown.map((n) => (
          <div key={n.network.id} className="ld-network-slot" style={{ top: n.top, height: n.height }}>
            <NetworkView
              layout={n}
              width={layout.width}
              selection={selected === n.network.id ? selection : null}
              diagnostics={byNetwork.get(n.network.id) ?? NO_DIAGNOSTICS}
              online={online}
              dropping={dropping}
              handlers={handlers}
              debug={debug}
            />
          </div>
        ))}
        {overlay}
      </div>
    </div>
  );
}
