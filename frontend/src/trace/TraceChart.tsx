// The trace as a uPlot time chart: drag to zoom (x), double click to reset, Shift+drag or the
// buttons to pan, Ctrl+wheel to zoom around the cursor; the legend shows the values under the
// cursor. While the user has not zoomed, the chart follows new samples; a zoom holds still. A click shows the
// scan under the cursor from the scan history, and the scan the history shows holds the cursor (a line marks it).
import { useEffect, useEffectEvent, useRef, useState } from "react";
import uPlot from "uplot";
import "uplot/dist/uPlot.min.css";
import type { DisplayType } from "../generated/monitor";
import { usePanels } from "../store/panels";
import { chartData, legendValue, LANE, type ChartData } from "./chartData";
import type { Kind } from "./csv";
import type { SampleRing } from "./ring";
import { sampleOfScan } from "./scrub";

const COLORS = [
  "#1f77b4",
  "#d62728",
  "#2ca02c",
  "#9467bd",
  "#ff7f0e",
  "#17becf",
  "#8c564b",
  "#e377c2",
  "#7f7f7f",
  "#bcbd22",
];
/** The plot's height at least; a taller bottom panel (dragged up) gives it the rest, less PANEL_CHROME. */
const HEIGHT = 180;
/** What the panel's tabs, the chart's buttons and its legend take of the panel's height. */
const PANEL_CHROME = 120;

export interface TraceChartProps {
  paths: readonly string[];
  kinds: readonly (Kind | null)[];
  /** How to show each path's values in the legend (an enumeration's names). */
  types: readonly (DisplayType | null)[];
  ring: SampleRing;
  /** Changes whenever the ring does. */
  version: number;
  origin: number;
  laneView: boolean;
  /** The past scan the scan history shows (null: live): the cursor stays on its sample. */
  viewing: number | null;
  /** A click on the chart: show this scan from the history. */
  onPick: (scan: number) => void;
}

/** How long a click waits for a second one (a double click resets the zoom, it shows no scan). */
const CLICK_MS = 250;
/** The colour of the history's viewing banner, for the line at the scan it shows. */
const VIEWING = "#bf8700";

/** Moves the x range by `fraction` of its width (negative: back in time). */
function panX(u: uPlot, fraction: number): void {
  const { min, max } = u.scales.x ?? {};
  if (min == null || max == null) return;
  const d = (max - min) * fraction;
  u.setScale("x", { min: min + d, max: max + d });
}

/** Zooms the x range by `factor` (< 1: in) keeping the value at `at` (0..1 of the width) in place. */
function zoomX(u: uPlot, factor: number, at = 0.5): void {
  const { min, max } = u.scales.x ?? {};
  if (min == null || max == null) return;
  const center = min + (max - min) * at;
  u.setScale("x", { min: center - (center - min) * factor, max: center + (max - center) * factor });
}

/** Puts the visible x range on the chart's element (data-x-min, data-x-max), for tools and tests. */
function showRange(u: uPlot): void {
  const { min, max } = u.scales.x ?? {};
  const host = u.root.parentElement;
  if (!host || min == null || max == null) return;
  host.dataset.xMin = String(min);
  host.dataset.xMax = String(max);
}

function options(
  chart: ChartData,
  width: number,
  height: number,
  onUserZoom: () => void,
  onReset: () => void,
  onPick: (index: number) => void,
  marked: () => number | null,
): uPlot.Options {
  const numbers = chart.series.some((s) => s.scale === "y");
  const steps = uPlot.paths.stepped!({ align: 1 });
  const lanes = chart.series.filter((s) => s.scale === "lanes");
  let start: { x: number; min: number; max: number } | null = null;
  let panned: uPlot | null = null;
  const move = (e: MouseEvent) => {
    if (!start || !panned) return;
    const d = ((e.clientX - start.x) / panned.over.clientWidth) * (start.max - start.min);
    onUserZoom();
    panned.setScale("x", { min: start.min - d, max: start.max - d });
  };
  const up = () => void (start = null);
  const pan = (u: uPlot) => {
    panned = u;
    u.over.addEventListener("mousedown", (e) => {
      const { min, max } = u.scales.x ?? {};
      if (!e.shiftKey || min == null || max == null) return;
      start = { x: e.clientX, min, max };
    });
    window.addEventListener("mousemove", move);
    window.addEventListener("mouseup", up);
    u.over.addEventListener("wheel", (e) => {
      if (!e.ctrlKey && !e.metaKey) return; // the plain wheel scrolls the panel
      e.preventDefault();
      onUserZoom();
      zoomX(u, e.deltaY > 0 ? 1.25 : 0.8, e.offsetX / u.over.clientWidth);
    });
    let pressed: number | null = null;
    let pending: number | undefined;
    u.over.addEventListener("mousedown", (e) => void (pressed = e.clientX));
    u.over.addEventListener("click", (e) => {
      const dragged = pressed === null || Math.abs(e.clientX - pressed) > 3; // a zoom or a pan, not a pick
      window.clearTimeout(pending);
      if (dragged || e.shiftKey || e.detail > 1) return;
      const index = u.posToIdx(e.offsetX);
      pending = window.setTimeout(() => onPick(index), CLICK_MS);
    });
    u.over.addEventListener("dblclick", () => {
      window.clearTimeout(pending);
      onReset();
    });
  };
  const line = (u: uPlot) => {
    const x = marked();
    if (x === null) return;
    const left = Math.round(u.valToPos(x, "x", true));
    const { ctx } = u;
    ctx.save();
    ctx.strokeStyle = VIEWING;
    ctx.lineWidth = 2;
    ctx.beginPath();
    ctx.moveTo(left, u.bbox.top);
    ctx.lineTo(left, u.bbox.top + u.bbox.height);
    ctx.stroke();
    ctx.restore();
  };
  return {
    width,
    height,
    scales: {
      x: { time: false },
      y: { auto: true },
      lanes: { auto: false, range: [-0.2, Math.max(1, lanes.length) * LANE - 0.2] },
    },
    axes: [
      { label: "ms since the first sample", size: 40 },
      { scale: "y", show: numbers },
      {
        scale: "lanes",
        side: 1,
        show: lanes.length > 0,
        size: 90,
        splits: () => lanes.map((s) => s.offset + 0.5),
        values: (_u, splits) =>
          splits.map(
            (v) =>
              lanes
                .find((s) => s.offset + 0.5 === v)
                ?.path.split(".")
                .slice(-2)
                .join(".") ?? "",
          ),
        grid: { show: false },
      },
    ],
    series: [
      { label: "t (ms)" },
      ...chart.series.map((plan, i): uPlot.Series => ({
        label: plan.path,
        scale: plan.scale,
        stroke: COLORS[i % COLORS.length],
        width: 1.5,
        paths: plan.kind === "bool" ? steps : undefined,
        value: (_u, v) => legendValue(plan, v),
        points: { show: false },
      })),
    ],
    cursor: {
      drag: { x: true, y: false, setScale: true },
      // Shift+drag pans: the selection must not start then.
      bind: { mousedown: (_u, _t, handler) => (e) => (e.shiftKey ? null : handler(e)) },
    },
    hooks: {
      ready: [pan],
      draw: [line],
      destroy: [
        () => {
          window.removeEventListener("mousemove", move);
          window.removeEventListener("mouseup", up);
        },
      ],
      setSelect: [(u) => void (u.select.width > 0 && onUserZoom())],
      setScale: [(u, key) => void (key === "x" && showRange(u))],
    },
  };
}

export function TraceChart({ paths, kinds, types, ring, version, origin, laneView, viewing, onPick }: TraceChartProps) {
  const host = useRef<HTMLDivElement>(null);
  const plot = useRef<uPlot | null>(null);
  const zoomed = useRef(false);
  /** The x (ms) of the sample of the scan the history shows, for the line the chart draws there. */
  const marked = useRef<number | null>(null);
  const [width, setWidth] = useState(640);
  const panelHeight = usePanels((s) => s.height);
  const height = Math.max(HEIGHT, (panelHeight ?? 0) - PANEL_CHROME);
  const layout = JSON.stringify([paths, kinds, types, laneView]);

  useEffect(() => {
    const el = host.current;
    if (!el || typeof ResizeObserver === "undefined") return;
    const observer = new ResizeObserver(() => setWidth(Math.max(200, el.clientWidth)));
    observer.observe(el);
    return () => observer.disconnect();
  }, []);

  /** A chart of the current series in `el` (effect events read the props of the latest render). */
  const build = useEffectEvent((el: HTMLDivElement) => {
    zoomed.current = false;
    const chart = chartData(paths, kinds, ring.columnsInOrder(), origin, laneView, types);
    const onZoom = () => void (zoomed.current = true);
    const onReset = () => void (zoomed.current = false);
    const pick = (index: number) => {
      const scan = ring.columnsInOrder().scans[index];
      if (scan !== undefined) onPick(scan);
    };
    const u = new uPlot(
      options(chart, width, height, onZoom, onReset, pick, () => marked.current),
      chart.data as uPlot.AlignedData,
      el,
    );
    return u;
  });
  /** The cursor and the line on the sample of the scan the history shows (none while live). */
  const follow = useEffectEvent((u: uPlot) => {
    const scans = ring.columnsInOrder().scans;
    const index = viewing === null ? null : sampleOfScan(scans, viewing);
    const x = index === null ? null : (u.data[0][index] ?? null);
    marked.current = x;
    if (host.current) host.current.dataset.viewingScan = index === null ? "" : String(scans[index]);
    if (x !== null) u.setCursor({ left: u.valToPos(x, "x"), top: u.over.clientHeight / 2 });
    u.redraw(false);
  });
  const refresh = useEffectEvent((u: uPlot) => {
    const chart = chartData(paths, kinds, ring.columnsInOrder(), origin, laneView, types);
    u.setData(chart.data as uPlot.AlignedData, !zoomed.current);
  });

  // Rebuilt only when the series change; new data and sizes go to the same chart below.
  useEffect(() => {
    if (!host.current) return;
    const u = build(host.current);
    plot.current = u;
    follow(u);
    return () => {
      u.destroy();
      plot.current = null;
    };
  }, [layout, ring]);

  useEffect(() => {
    plot.current?.setSize({ width, height });
  }, [width, height]);

  // The ring changes in place: `version` says when.
  useEffect(() => {
    if (plot.current) refresh(plot.current);
  }, [version, origin]);

  useEffect(() => {
    if (plot.current) follow(plot.current);
  }, [viewing]);

  const act = (action: (u: uPlot) => void) => {
    const u = plot.current;
    if (!u) return;
    zoomed.current = true;
    action(u);
  };
  const reset = () => {
    const u = plot.current;
    if (!u) return;
    zoomed.current = false;
    u.setData(u.data, true);
  };
  return (
    <div className="trace-chart">
      <div className="trace-chart-tools" role="toolbar" aria-label="Chart zoom and pan">
        <button type="button" onClick={() => act((u) => panX(u, -0.25))} title="Pan back in time (or Shift+drag)">
          ◀
        </button>
        <button
          type="button"
          onClick={() => act((u) => zoomX(u, 0.5))}
          title="Zoom in (or drag over the chart, or Ctrl+wheel)"
        >
          Zoom in
        </button>
        <button type="button" onClick={() => act((u) => zoomX(u, 2))}>
          Zoom out
        </button>
        <button type="button" onClick={() => act((u) => panX(u, 0.25))} title="Pan forward in time (or Shift+drag)">
          ▶
        </button>
        <button type="button" onClick={reset} title="Show every sample (or double click the chart)">
          Reset zoom
        </button>
      </div>
      <div ref={host} className="trace-plot" aria-label="Trace chart" role="img" />
    </div>
  );
}
