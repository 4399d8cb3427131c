// Every panel widget as SVG, drawn from the live values. Input widgets call `act(path, value)` (a panel
// input event; null in the editor, where widgets do nothing) with the mouse, touch (pointer events)
// and the keyboard. Each widget's group carries data-* attributes (its id, type, whether it is on, its
// value) for tools and the browser tests.
import { lazy, Suspense, useRef, useState, type KeyboardEvent, type PointerEvent, type ReactNode } from "react";
import type { DisplayType } from "../generated/monitor";
import type { Value, WriteValue } from "../online/protocol";
import {
  displayText,
  fraction,
  numeric,
  pushValue,
  sevenSegmentText,
  sliderValue,
  stateOf,
  truthy,
  typedValue,
  type Widget,
  type WidgetOf,
} from "./model";
import { aspectOf, SymbolDrawing } from "./symbols";

// uPlot is loaded with the first trend (as the trace panel does).
const TrendChart = lazy(() => import("./TrendChart").then((m) => ({ default: m.TrendChart })));

/** What widgets read: values and types by path (as bound), and whether a path is forced or has a fault. */
export interface Live {
  value(path: string | null | undefined): Value | undefined;
  type(path: string | null | undefined): DisplayType | undefined;
  forced(path: string | null | undefined): boolean;
  injected(path: string | null | undefined): string | undefined;
  /** Virtual time of the values (the trend's x axis). */
  timeMs: number;
}

/** Where a widget's actions go (with the widget, which names the event in the log); null: nothing happens. */
export type Act = ((path: string, value: WriteValue, widget?: Widget) => void) | null;

interface Props<T extends Widget> {
  widget: T;
  live: Live;
  act: Act;
}

const LABEL_SIZE = 11;

function Caption({ widget, below = true }: { widget: Widget; below?: boolean }) {
  if (!widget.label) return null;
  return (
    <text
      className="hmi-caption"
      x={widget.w / 2}
      y={below ? widget.h + LABEL_SIZE + 2 : -4}
      textAnchor="middle"
      fontSize={LABEL_SIZE}
    >
      {widget.label}
    </text>
  );
}

/** The markers of a forced variable (F) and an injected fault (!) on the widget's corner. */
function Marks({ widget, live }: { widget: Widget; live: Live }) {
  const path = "bind" in widget ? widget.bind : null;
  const fault = live.injected(path);
  return (
    <>
      {live.forced(path) ? (
        <g className="hmi-forced" transform={`translate(${widget.w - 8}, -6)`}>
          <title>{`${path} is forced`}</title>
          <rect x={-6} y={-6} width={14} height={14} fill="#fb8c00" />
          <text x={1} y={5} fontSize={11} textAnchor="middle" fill="#fff" fontWeight="bold">
            F
          </text>
        </g>
      ) : null}
      {fault ? (
        <g className="hmi-injected" data-fault={fault} transform={`translate(${widget.w - 24}, -6)`}>
          <title>{`fault injected into ${path}: ${fault.replace("_", " ")}`}</title>
          <rect x={-6} y={-6} width={14} height={14} fill="#d50000" />
          <text x={1} y={5} fontSize={11} textAnchor="middle" fill="#fff" fontWeight="bold">
            !
          </text>
        </g>
      ) : null}
    </>
  );
}

/** Press and release by mouse, touch or keyboard (Space, Enter). */
function usePress(onChange: (pressed: boolean) => void, enabled: boolean) {
  const [pressed, setPressed] = useState(false);
  const set = (next: boolean) => {
    if (!enabled || next === pressed) return;
    setPressed(next);
    onChange(next);
  };
  return {
    pressed,
    handlers: {
      onPointerDown: (e: PointerEvent) => {
        if (!enabled || e.button > 0) return;
        (e.currentTarget as Element).setPointerCapture?.(e.pointerId);
        set(true);
      },
      onPointerUp: () => set(false),
      onPointerCancel: () => set(false),
      onLostPointerCapture: () => set(false),
      onKeyDown: (e: KeyboardEvent) => {
        if ((e.key === " " || e.key === "Enter") && !e.repeat) {
          e.preventDefault();
          set(true);
        }
      },
      onKeyUp: (e: KeyboardEvent) => {
        if (e.key === " " || e.key === "Enter") set(false);
      },
      onBlur: () => set(false),
    },
  };
}

function PushButton({ widget, live, act }: Props<WidgetOf<"push_button">>) {
  const { pressed, handlers } = usePress((down) => act?.(widget.bind, pushValue(down, widget.nc)), act !== null);
  const color = widget.color ?? "#2e7d32";
  const r = Math.min(widget.w, widget.h) / 2;
  return (
    <g
      role="button"
      aria-label={widget.label || widget.id}
      aria-pressed={pressed}
      tabIndex={act ? 0 : undefined}
      className="hmi-input"
      data-on={truthy(live.value(widget.bind))}
      {...handlers}
    >
      <rect width={widget.w} height={widget.h} rx={r / 2} fill="#37474f" />
      <rect
        x={3}
        y={pressed ? 5 : 3}
        width={widget.w - 6}
        height={widget.h - 8}
        rx={r / 2}
        fill={color}
        filter={pressed ? undefined : "url(#hmi-raise)"}
      />
      <Caption widget={widget} />
    </g>
  );
}

function ToggleSwitch({ widget, live, act }: Props<WidgetOf<"toggle_switch">>) {
  const on = truthy(live.value(widget.bind));
  const flip = () => act?.(widget.bind, !on);
  const knob = Math.min(widget.h - 6, widget.w / 2 - 4);
  return (
    <g
      role="switch"
      aria-checked={on}
      aria-label={widget.label || widget.id}
      tabIndex={act ? 0 : undefined}
      className="hmi-input"
      data-on={on}
      onClick={flip}
      onKeyDown={(e) => {
        if (e.key === " " || e.key === "Enter") {
          e.preventDefault();
          flip();
        }
      }}
    >
      <rect width={widget.w} height={widget.h} rx={widget.h / 2} fill={on ? "#43a047" : "#9e9e9e"} />
      <circle cx={on ? widget.w - widget.h / 2 : widget.h / 2} cy={widget.h / 2} r={knob / 2} fill="#fff" />
      <text x={widget.w / 2} y={widget.h / 2 + 4} textAnchor="middle" fontSize={11} fill="#fff">
        {on ? "ON" : "OFF"}
      </text>
      <Caption widget={widget} />
    </g>
  );
}

function SelectorSwitch({ widget, live, act }: Props<WidgetOf<"selector_switch">>) {
  const value = live.value(widget.bind);
  const index = Math.max(
    0,
    widget.positions.findIndex((p) => p.value === value || numeric(p.value as Value) === numeric(value)),
  );
  const count = widget.positions.length;
  const angleOf = (i: number) => (count === 2 ? (i === 0 ? -45 : 45) : (i - 1) * 45);
  const cx = widget.w / 2;
  const cy = widget.h / 2 + 6;
  const r = Math.min(widget.w / 2, widget.h / 2) - 12;
  const turn = (i: number) => act?.(widget.bind, widget.positions[i]!.value as WriteValue);
  return (
    <g
      role="radiogroup"
      aria-label={widget.label || widget.id}
      className="hmi-input"
      data-value={String(widget.positions[index]?.value)}
    >
      <circle cx={cx} cy={cy} r={r} fill="#263238" />
      <rect
        x={cx - 5}
        y={cy - r + 2}
        width={10}
        height={r * 2 - 4}
        rx={4}
        fill="#eceff1"
        transform={`rotate(${angleOf(index)} ${cx} ${cy})`}
      />
      {widget.positions.map((p, i) => {
        const a = ((angleOf(i) - 90) * Math.PI) / 180;
        return (
          <text
            key={i}
            role="radio"
            aria-checked={i === index}
            aria-label={p.label}
            tabIndex={act ? 0 : undefined}
            x={cx + Math.cos(a) * (r + 8)}
            y={cy + Math.sin(a) * (r + 8)}
            textAnchor="middle"
            fontSize={11}
            fontWeight={i === index ? "bold" : undefined}
            onClick={() => turn(i)}
            onKeyDown={(e) => (e.key === " " || e.key === "Enter") && turn(i)}
          >
            {p.label}
          </text>
        );
      })}
      <Caption widget={widget} />
    </g>
  );
}

function EmergencyStop({ widget, live, act }: Props<WidgetOf<"emergency_stop">>) {
  const nc = widget.nc ?? true;
  const pressed = truthy(live.value(widget.bind)) !== nc; // NC: FALSE while pressed
  const toggle = () => act?.(widget.bind, nc ? pressed : !pressed);
  const r = Math.min(widget.w, widget.h) / 2;
  return (
    <g
      role="button"
      aria-label={widget.label || widget.id}
      aria-pressed={pressed}
      tabIndex={act ? 0 : undefined}
      className="hmi-input"
      data-on={pressed}
      onClick={toggle}
      onKeyDown={(e) => {
        if (e.key === " " || e.key === "Enter") {
          e.preventDefault();
          toggle();
        }
      }}
    >
      <circle cx={widget.w / 2} cy={widget.h / 2} r={r} fill="#fdd835" />
      <circle cx={widget.w / 2} cy={widget.h / 2} r={r * (pressed ? 0.6 : 0.72)} fill="#c62828" stroke="#7f0000" />
      {pressed ? (
        <text x={widget.w / 2} y={widget.h / 2 + 4} textAnchor="middle" fontSize={10} fill="#fff">
          PRESSED
        </text>
      ) : null}
      <Caption widget={widget} />
    </g>
  );
}

function Lamp({ widget, live }: Props<WidgetOf<"lamp">>) {
  const on = truthy(live.value(widget.bind));
  const blink = on && widget.blink;
  return (
    <g data-on={on} role="img" aria-label={`${widget.label || widget.id}: ${on ? "on" : "off"}`}>
      <ellipse
        cx={widget.w / 2}
        cy={widget.h / 2}
        rx={widget.w / 2}
        ry={widget.h / 2}
        fill={on ? (widget.on_color ?? "#43a047") : (widget.off_color ?? "#5f6368")}
        stroke="#263238"
        className={blink ? "hmi-blink" : undefined}
        style={blink ? { animationDuration: `${2 * (widget.blink_ms ?? 500)}ms` } : undefined}
      />
      {on ? (
        <ellipse
          cx={widget.w / 2 - widget.w / 6}
          cy={widget.h / 2 - widget.h / 6}
          rx={widget.w / 8}
          ry={widget.h / 8}
          fill="#fff"
          opacity={0.6}
        />
      ) : null}
      <Caption widget={widget} />
    </g>
  );
}

function Box({
  widget,
  text,
  color,
  children,
}: {
  widget: Widget;
  text: string;
  color?: string;
  children?: ReactNode;
}) {
  return (
    <>
      <rect width={widget.w} height={widget.h} rx={3} fill={color ?? "#fff"} stroke="#607d8b" />
      <text
        className="hmi-value"
        x={widget.w - 6}
        y={widget.h / 2 + 5}
        textAnchor="end"
        fontSize={Math.min(16, widget.h * 0.55)}
        fontFamily="monospace"
        fill={color ? "#fff" : "#202124"}
      >
        {text}
      </text>
      {children}
      <Caption widget={widget} />
    </>
  );
}

function Multistate({ widget, live }: Props<WidgetOf<"multistate">>) {
  const state = stateOf(widget.states, live.value(widget.bind));
  return (
    <g data-text={state?.text ?? widget.default_text ?? "?"}>
      <Box widget={widget} text={state?.text ?? widget.default_text ?? "?"} color={state?.color ?? "#5f6368"} />
    </g>
  );
}

function NumericDisplay({ widget, live }: Props<WidgetOf<"numeric_display">>) {
  const text = displayText(live.value(widget.bind), live.type(widget.bind), widget.decimals);
  const shown = widget.unit ? `${text} ${widget.unit}` : text;
  return (
    <g data-text={shown}>
      <Box widget={widget} text={shown} />
    </g>
  );
}

function NumericInput({ widget, live, act }: Props<WidgetOf<"numeric_input">>) {
  const current = displayText(live.value(widget.bind), live.type(widget.bind));
  const [text, setText] = useState<string | null>(null);
  const commit = () => {
    const value = text === null ? null : typedValue(text);
    const n = typeof value === "number" ? value : null;
    if (
      value !== null &&
      (n === null || ((widget.min == null || n >= widget.min) && (widget.max == null || n <= widget.max)))
    )
      act?.(widget.bind, value);
    setText(null);
  };
  return (
    <g data-text={current}>
      <foreignObject width={widget.w} height={widget.h}>
        <input
          className="hmi-field"
          aria-label={widget.label || widget.id}
          value={text ?? current}
          disabled={!act}
          onFocus={(e) => {
            setText(current);
            e.currentTarget.select();
          }}
          onChange={(e) => setText(e.target.value)}
          onKeyDown={(e) => {
            if (e.key === "Enter") commit();
            if (e.key === "Escape") setText(null);
          }}
          onBlur={() => setText(null)}
        />
      </foreignObject>
      <Caption widget={widget} />
    </g>
  );
}

/** Slider changes sent at most this often while dragging (each is an input event; the last always goes). */
const SLIDER_THROTTLE_MS = 100;

function Slider({ widget, live, act }: Props<WidgetOf<"slider">>) {
  const min = widget.min ?? 0;
  const max = widget.max ?? 100;
  const step = widget.step ?? 1;
  const value = numeric(live.value(widget.bind)) ?? min;
  const [dragging, setDragging] = useState<number | null>(null);
  const last = useRef(0);
  const shown = dragging ?? value;
  const send = (v: number, force = false) => {
    const now = Date.now();
    if (force || now - last.current >= SLIDER_THROTTLE_MS) {
      last.current = now;
      act?.(widget.bind, v);
    }
  };
  const at = (e: PointerEvent) => {
    const box = (e.currentTarget as Element).getBoundingClientRect();
    return widget.vertical ? 1 - (e.clientY - box.top) / box.height : (e.clientX - box.left) / box.width;
  };
  const f = (shown - min) / (max - min || 1);
  const len = widget.vertical ? widget.h : widget.w;
  const pos = widget.vertical ? widget.h - f * len : f * len;
  return (
    <g
      role="slider"
      aria-label={widget.label || widget.id}
      aria-valuemin={min}
      aria-valuemax={max}
      aria-valuenow={shown}
      tabIndex={act ? 0 : undefined}
      className="hmi-input"
      data-value={shown}
      onPointerDown={(e) => {
        if (!act) return;
        (e.currentTarget as Element).setPointerCapture?.(e.pointerId);
        const v = sliderValue(at(e), min, max, step);
        setDragging(v);
        send(v, true);
      }}
      onPointerMove={(e) => {
        if (dragging === null) return;
        const v = sliderValue(at(e), min, max, step);
        setDragging(v);
        send(v);
      }}
      onPointerUp={() => {
        if (dragging !== null) send(dragging, true);
        setDragging(null);
      }}
      onKeyDown={(e) => {
        const delta =
          e.key === "ArrowRight" || e.key === "ArrowUp"
            ? step
            : e.key === "ArrowLeft" || e.key === "ArrowDown"
              ? -step
              : 0;
        if (delta) {
          e.preventDefault();
          send(Math.min(max, Math.max(min, value + delta)), true);
        }
      }}
    >
      <rect width={widget.w} height={widget.h} fill="transparent" />
      {widget.vertical ? (
        <>
          <rect x={widget.w / 2 - 3} width={6} height={widget.h} rx={3} fill="#b0bec5" />
          <rect x={widget.w / 2 - 12} y={pos - 6} width={24} height={12} rx={3} fill="#1e88e5" />
        </>
      ) : (
        <>
          <rect y={widget.h / 2 - 3} width={widget.w} height={6} rx={3} fill="#b0bec5" />
          <rect x={pos - 6} y={widget.h / 2 - 12} width={12} height={24} rx={3} fill="#1e88e5" />
        </>
      )}
      <text x={widget.w} y={-4} textAnchor="end" fontSize={11}>
        {shown}
      </text>
      <Caption widget={widget} />
    </g>
  );
}

function Bar({ widget, live }: Props<WidgetOf<"bar">>) {
  const value = live.value(widget.bind);
  const n = numeric(value);
  const min = widget.min ?? 0;
  const max = widget.max ?? 100;
  const f = fraction(value, min, max);
  const alarm =
    n !== null &&
    ((widget.low_alarm != null && n <= widget.low_alarm) || (widget.high_alarm != null && n >= widget.high_alarm));
  const fill = alarm ? "#e53935" : (widget.color ?? "#1e88e5");
  const vertical = widget.vertical ?? true;
  const limit = (level: number | null | undefined) => {
    if (level == null) return null;
    const at = (level - min) / (max - min || 1);
    return vertical ? (
      <line
        x1={-4}
        x2={widget.w + 4}
        y1={widget.h * (1 - at)}
        y2={widget.h * (1 - at)}
        stroke="#e53935"
        strokeDasharray="4 2"
      />
    ) : (
      <line y1={-4} y2={widget.h + 4} x1={widget.w * at} x2={widget.w * at} stroke="#e53935" strokeDasharray="4 2" />
    );
  };
  const r = widget.tank ? Math.min(widget.w, widget.h) / 6 : 2;
  return (
    <g
      data-value={n ?? ""}
      data-alarm={alarm}
      role="meter"
      aria-label={widget.label || widget.id}
      aria-valuenow={n ?? undefined}
    >
      <clipPath id={`hmi-clip-${widget.id}`}>
        <rect width={widget.w} height={widget.h} rx={r} />
      </clipPath>
      <rect
        width={widget.w}
        height={widget.h}
        rx={r}
        fill="#eceff1"
        stroke="#607d8b"
        strokeWidth={widget.tank ? 3 : 1}
      />
      <g clipPath={`url(#hmi-clip-${widget.id})`}>
        {vertical ? (
          <rect
            className="hmi-fill"
            y={widget.h * (1 - f)}
            width={widget.w}
            height={widget.h * f}
            fill={fill}
            opacity={0.85}
          />
        ) : (
          <rect className="hmi-fill" width={widget.w * f} height={widget.h} fill={fill} opacity={0.85} />
        )}
      </g>
      {limit(widget.low_alarm)}
      {limit(widget.high_alarm)}
      <Caption widget={widget} />
    </g>
  );
}

/** Segments a..g of each character: top, top right, bottom right, bottom, bottom left, top left, middle. */
const SEGMENTS: Record<string, string> = {
  "0": "abcdef",
  "1": "bc",
  "2": "abdeg",
  "3": "abcdg",
  "4": "bcfg",
  "5": "acdfg",
  "6": "acdefg",
  "7": "abc",
  "8": "abcdefg",
  "9": "abcdfg",
  "-": "g",
  " ": "",
};
const SEGMENT_PATHS: Record<string, string> = {
  a: "M2 1 H10 L9 3 H3 Z",
  b: "M10 1 L11 2 V9 L9.5 10 L9 9 V3 Z",
  c: "M9.5 10 L11 11 V18 L10 19 L9 17 V11 Z",
  d: "M3 17 H9 L10 19 H2 Z",
  e: "M2 11 L2.5 10 L3 11 V17 L2 19 L1 18 V11 Z",
  f: "M1 2 L2 1 L3 3 V9 L2.5 10 L1 9 Z",
  g: "M3 9 H9 L9.5 10 L9 11 H3 L2.5 10 Z",
};

function SevenSegment({ widget, live }: Props<WidgetOf<"seven_segment">>) {
  const digits = widget.digits ?? 4;
  const text = sevenSegmentText(live.value(widget.bind), digits);
  const cell = widget.w / digits;
  const scale = Math.min(cell / 12, widget.h / 20);
  return (
    <g data-text={text.trim()} role="img" aria-label={`${widget.label || widget.id}: ${text.trim()}`}>
      <rect width={widget.w} height={widget.h} fill="#212121" rx={3} />
      {[...text].map((ch, i) => (
        <g
          key={i}
          transform={`translate(${i * cell + (cell - 12 * scale) / 2}, ${(widget.h - 20 * scale) / 2}) scale(${scale})`}
        >
          {Object.entries(SEGMENT_PATHS).map(([segment, d]) => (
            <path
              key={segment}
              d={d}
              fill={(SEGMENTS[ch] ?? "").includes(segment) ? (widget.color ?? "#e53935") : "#3a3a3a"}
            />
          ))}
        </g>
      ))}
      <Caption widget={widget} />
    </g>
  );
}

function Label({ widget }: Props<WidgetOf<"label">>) {
  return (
    <text
      y={Math.min(widget.h, (widget.size ?? 14) + 2)}
      fontSize={widget.size ?? 14}
      fill={widget.color ?? "#202124"}
      fontWeight={widget.bold ? "bold" : undefined}
    >
      {widget.text}
    </text>
  );
}

function Trend({ widget, live }: Props<WidgetOf<"trend">>) {
  return (
    <g>
      <foreignObject width={widget.w} height={widget.h}>
        <Suspense fallback={<div className="hmi-trend-loading">…</div>}>
          <TrendChart
            paths={widget.paths}
            values={widget.paths.map((p) => numeric(live.value(p)))}
            timeMs={live.timeMs}
            spanMs={(widget.span_s ?? 10) * 1000}
            width={widget.w}
            height={widget.h}
            min={widget.min ?? null}
            max={widget.max ?? null}
          />
        </Suspense>
      </foreignObject>
      <Caption widget={widget} />
    </g>
  );
}

function SymbolWidget({ widget, live }: Props<WidgetOf<"symbol">>) {
  const value = live.value(widget.bind);
  const on = truthy(value);
  const amount = fraction(value, widget.min ?? 0, widget.max ?? 100);
  const fault = truthy(live.value(widget.fault));
  return (
    <g
      data-on={on}
      data-amount={amount.toFixed(3)}
      data-fault={fault}
      role="img"
      aria-label={widget.label || widget.id}
    >
      <svg
        width={widget.w}
        height={widget.h}
        viewBox="0 0 100 100"
        preserveAspectRatio={aspectOf(widget.shape)}
        overflow="visible"
      >
        <SymbolDrawing shape={widget.shape} on={on} amount={amount} color={widget.color ?? "#546e7a"} fault={fault} />
      </svg>
      <Caption widget={widget} />
    </g>
  );
}

/** One widget by its type. */
export function WidgetBody({ widget, live, act }: Props<Widget>): ReactNode {
  switch (widget.type) {
    case "push_button":
      return <PushButton widget={widget} live={live} act={act} />;
    case "toggle_switch":
      return <ToggleSwitch widget={widget} live={live} act={act} />;
    case "selector_switch":
      return <SelectorSwitch widget={widget} live={live} act={act} />;
    case "emergency_stop":
      return <EmergencyStop widget={widget} live={live} act={act} />;
    case "lamp":
      return <Lamp widget={widget} live={live} act={act} />;
    case "multistate":
      return <Multistate widget={widget} live={live} act={act} />;
    case "numeric_display":
      return <NumericDisplay widget={widget} live={live} act={act} />;
    case "numeric_input":
      return <NumericInput widget={widget} live={live} act={act} />;
    case "slider":
      return <Slider widget={widget} live={live} act={act} />;
    case "bar":
      return <Bar widget={widget} live={live} act={act} />;
    case "seven_segment":
      return <SevenSegment widget={widget} live={live} act={act} />;
    case "label":
      return <Label widget={widget} live={live} act={act} />;
    case "trend":
      return <Trend widget={widget} live={live} act={act} />;
    case "symbol":
      return <SymbolWidget widget={widget} live={live} act={act} />;
  }
}

export { Marks };
