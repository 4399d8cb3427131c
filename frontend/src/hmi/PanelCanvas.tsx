// A panel drawn as one SVG: its widgets at their places, shown while their `visible` BOOL is TRUE and
// moved by their `move_x`/`move_y` values (in the editor every widget shows, unmoved). The editor adds
// its selection and handles through `overlay` and `widgetProps`.
import type { MouseEvent, ReactNode, SVGProps } from "react";
import type { Panel } from "../generated/api";
import type { MonitorState } from "../online/monitor";
import { pathKey } from "../online/monitor";
import { motionOffset, truthy, widgetsOf, type Widget } from "./model";
import { Marks, WidgetBody, type Act, type Live } from "./widgets";
import "./hmi.css";

/** What widgets read, from the monitor's state (values keyed by upper-case path). */
export function liveOf(monitor: Pick<MonitorState, "values" | "types" | "forced" | "injected" | "timeMs">): Live {
  const key = (path: string | null | undefined) => (path ? pathKey(path) : "");
  return {
    value: (path) => (path ? monitor.values[key(path)] : undefined),
    type: (path) => (path ? monitor.types[key(path)] : undefined),
    forced: (path) => !!path && monitor.forced.has(key(path)),
    injected: (path) => (path ? monitor.injected[key(path)] : undefined),
    timeMs: monitor.timeMs,
  };
}

export interface PanelCanvasProps {
  panel: Panel;
  live: Live;
  /** Run mode: where widget actions go; null in the editor. */
  act: Act;
  /** The editor: widgets at their places, all shown. */
  editing?: boolean;
  /** Pixels per panel pixel. */
  zoom?: number;
  overlay?: ReactNode;
  widgetProps?: (widget: Widget) => SVGProps<SVGGElement>;
  canvasProps?: SVGProps<SVGSVGElement>;
  onWidgetMenu?: (widget: Widget, event: MouseEvent) => void;
}

export function PanelCanvas({
  panel,
  live,
  act,
  editing = false,
  zoom = 1,
  overlay,
  widgetProps,
  canvasProps,
  onWidgetMenu,
}: PanelCanvasProps) {
  const width = panel.width ?? 800;
  const height = panel.height ?? 480;
  const grid = panel.grid ?? 10;
  return (
    <svg
      className={`hmi-canvas${editing ? " hmi-editing" : ""}`}
      data-panel={panel.name}
      width={width * zoom}
      height={height * zoom}
      viewBox={`0 0 ${width} ${height}`}
      role="group"
      aria-label={`Panel ${panel.title || panel.name}`}
      {...canvasProps}
    >
      <defs>
        <filter id="hmi-raise" x="-10%" y="-10%" width="120%" height="130%">
          <feDropShadow dx="0" dy="2" stdDeviation="1.2" floodOpacity="0.35" />
        </filter>
        {editing && grid ? (
          <pattern id="hmi-grid" width={grid} height={grid} patternUnits="userSpaceOnUse">
            <circle cx={0.5} cy={0.5} r={0.6} fill="#90a4ae" />
          </pattern>
        ) : null}
      </defs>
      <rect width={width} height={height} fill={panel.background ?? "#eceff1"} />
      {editing && grid ? <rect width={width} height={height} fill="url(#hmi-grid)" pointerEvents="none" /> : null}
      {widgetsOf(panel).map((widget) => {
        const shown = editing || !widget.visible || truthy(live.value(widget.visible));
        const dx = editing ? 0 : motionOffset(widget.move_x, live.value(widget.move_x?.path));
        const dy = editing ? 0 : motionOffset(widget.move_y, live.value(widget.move_y?.path));
        return (
          <g
            key={widget.id}
            className="hmi-widget"
            data-widget={widget.id}
            data-type={widget.type}
            transform={`translate(${widget.x + dx} ${widget.y + dy})`}
            visibility={shown ? undefined : "hidden"}
            data-shown={shown}
            onContextMenu={onWidgetMenu ? (e) => onWidgetMenu(widget, e) : undefined}
            {...widgetProps?.(widget)}
          >
            <WidgetBody widget={widget} live={live} act={act ? (path, value) => act(path, value, widget) : null} />
            {editing ? null : <Marks widget={widget} live={live} />}
          </g>
        );
      })}
      {overlay}
    </svg>
  );
}
