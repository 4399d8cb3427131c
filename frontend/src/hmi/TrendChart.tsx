// A panel's small trend: the last `spanMs` of virtual time of up to four variables, one uPlot line each.
// It samples the values it is given whenever their virtual time moves on (the panel's updates).
import { useEffect, useRef } from "react";
import uPlot from "uplot";
import "uplot/dist/uPlot.min.css";
import { appendSample } from "./trend";

const COLORS = ["#1e88e5", "#e53935", "#43a047", "#8e24aa"];

export interface TrendChartProps {
  paths: readonly string[];
  values: readonly (number | null)[];
  timeMs: number;
  spanMs: number;
  width: number;
  height: number;
  min: number | null;
  max: number | null;
}

export function TrendChart({ paths, values, timeMs, spanMs, width, height, min, max }: TrendChartProps) {
  const host = useRef<HTMLDivElement>(null);
  const plot = useRef<uPlot | null>(null);
  const data = useRef<(number | null)[][]>([[], ...paths.map(() => [])]);

  useEffect(() => {
    if (!host.current) return;
    const chart = new uPlot(
      {
        width,
        height,
        legend: { show: false },
        cursor: { show: false },
        scales: { x: { time: false }, y: min != null && max != null ? { range: [min, max] } : {} },
        axes: [
          { size: 20, font: "9px sans-serif" },
          { size: 34, font: "9px sans-serif" },
        ],
        series: [{}, ...paths.map((p, i) => ({ label: p, stroke: COLORS[i % COLORS.length], width: 1.5 }))],
      },
      data.current as uPlot.AlignedData,
      host.current,
    );
    plot.current = chart;
    return () => {
      chart.destroy();
      plot.current = null;
    };
  }, [paths, width, height, min, max]);

  useEffect(() => {
    const next = appendSample(data.current, timeMs, values, spanMs);
    if (next === data.current) return;
    data.current = next;
    plot.current?.setData(next as uPlot.AlignedData);
    if (host.current) host.current.dataset.samples = String(next[0]?.length ?? 0); // for tools and tests
  }, [timeMs, values, spanMs]);

  return <div ref={host} className="hmi-trend" />;
}
