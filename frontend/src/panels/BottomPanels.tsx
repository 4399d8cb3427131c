// The panels under the editor: Diagnostics, Watch list, I/O, Online log, Breakpoints, Trace, Tests and Cross
// references, one shown at a time.
import { lazy, Suspense } from "react";
import { useDebug } from "../debug/store";
import type { Diagnostic } from "../generated/api";
import { draggedOperand } from "../ld/editor/dragOperand";
import { onlineStore, useOnline } from "../online/store";
import { useTests } from "../tests/store";
import { DiagnosticsPanel } from "./DiagnosticsPanel";
import { IoPanel } from "./IoPanel";
import { LogPanel } from "./LogPanel";
import { panelsStore, usePanels, type PanelId } from "../store/panels";
import { WatchPanel } from "./WatchPanel";
import { ViewBoundary } from "../ui/ViewBoundary";
import { Splitter } from "../ui/Splitter";
import { OverflowBar } from "../ui/OverflowBar";

// The panels used now and then are loaded when first shown (issue 22 item 8: the initial chunk).
const TracePanel = lazy(() => import("../trace/TracePanel").then((m) => ({ default: m.TracePanel })));
const TestsPanel = lazy(() => import("../tests/TestsPanel").then((m) => ({ default: m.TestsPanel })));
const XrefPanel = lazy(() => import("../xref/XrefPanel").then((m) => ({ default: m.XrefPanel })));
const BreakpointsPanel = lazy(() => import("./BreakpointsPanel").then((m) => ({ default: m.BreakpointsPanel })));

/** Each panel in the user's words, for the message when it fails. */
const PANEL_NAMES: Record<PanelId, string> = {
  diagnostics: "diagnostics panel",
  watch: "watch list",
  io: "I/O view",
  log: "online log",
  breakpoints: "breakpoints panel",
  trace: "trace panel",
  tests: "tests panel",
  xref: "cross references panel",
};

export interface BottomPanelsProps {
  onReveal(d: Diagnostic): void;
  /** Turns a variable dragged from the open diagram into a path (its POU instance first). */
  pathOfOperand(operand: string): string | null;
}

export function BottomPanels({ onReveal, pathOfOperand }: BottomPanelsProps) {
  const panel = usePanels((s) => s.panel);
  const show = usePanels((s) => s.show);
  const problems = usePanels((s) => s.diagnostics?.length ?? 0);
  const watched = useOnline((s) => s.watch.length);
  const addresses = useOnline((s) => s.io.length);
  const logged = useOnline((s) => s.monitor.log.length);
  const breakpoints = useDebug((s) => s.breakpoints.length);
  const failed = useTests((s) => Object.values(s.results).filter((r) => r.outcome === "failed").length);
  const tabs: { id: PanelId; label: string }[] = [
    { id: "diagnostics", label: `Diagnostics (${problems})` },
    { id: "watch", label: `Watch list (${watched})` },
    { id: "io", label: `I/O (${addresses})` },
    { id: "log", label: `Online log (${logged})` },
    { id: "breakpoints", label: `Breakpoints (${breakpoints})` },
    { id: "trace", label: "Trace" },
    { id: "tests", label: failed ? `Tests (${failed} failed)` : "Tests" },
    { id: "xref", label: "Cross references" },
  ];
  const body = {
    diagnostics: <DiagnosticsPanel onReveal={onReveal} />,
    watch: <WatchPanel />,
    io: <IoPanel />,
    log: <LogPanel />,
    breakpoints: <BreakpointsPanel />,
    trace: <TracePanel />,
    tests: <TestsPanel />,
    xref: <XrefPanel onReveal={onReveal} />,
  };
  // A variable dragged from the diagram and released over the panels joins the watch list.
  const drop = () => {
    const operand = draggedOperand();
    const path = operand ? pathOfOperand(operand) : null;
    if (!path) return;
    onlineStore.getState().addWatch(path);
    show("watch");
  };
  return (
    <section className="bottom-panels" aria-label="Panels" onMouseUp={drop}>
      <PanelResizer />
      <OverflowBar
        className="panel-tabs"
        role="tablist"
        label="Panel tabs"
        moreLabel="More panels"
        items={tabs.map((t) => ({
          key: t.id,
          node: (
            <button type="button" role="tab" aria-selected={panel === t.id} onClick={() => show(t.id)}>
              {t.label}
            </button>
          ),
          // the panel shown keeps its tab in the row
          entries: panel === t.id ? [] : [{ id: t.id, label: t.label, run: () => show(t.id) }],
        }))}
      />
      <div className="panel-body" role="tabpanel">
        <ViewBoundary key={panel} name={`The ${PANEL_NAMES[panel]}`}>
          <Suspense fallback={<p className="panel-empty">Loading…</p>}>{body[panel]}</Suspense>
        </ViewBoundary>
      </div>
    </section>
  );
}

/**
 * The top edge of the panels: dragging it up or down (or Arrow up/down when focused) gives the
 * panels more or less of the height, e.g. for a trace chart; the height is kept after a reload.
 */
function PanelResizer() {
  const height = usePanels((s) => s.height);
  return (
    <Splitter
      label="Resize the panels"
      orientation="horizontal"
      grow={-1}
      className="panel-resizer"
      value={height}
      size={(edge) => panelsStore.getState().height ?? edge.parentElement!.getBoundingClientRect().height}
      onResize={(px) => panelsStore.getState().setHeight(px, window.innerHeight)}
    />
  );
}
