// The SFC chart as SVG, from layout.ts: steps (the initial one with a double border, E and X marks for entry
// and exit actions), their action blocks (qualifier | action | time), transitions with their conditions,
// divergence and convergence lines (double for simultaneous branches), jumps. Online (SFC-09, ON-17) active
// steps and actions are blue, each step shows its time, each transition the current value of its condition
// (also when its step is not active) and a transition that fired in the last scan is blue.
import type { MouseEvent } from "react";
import type { Diagnostic } from "../generated/api";
import {
  ACTION_GAP,
  ACTION_NAME_W,
  QUALIFIER_W,
  ROW_H,
  STEP_H,
  STEP_W,
  TIME_W,
  TRANSITION_H,
  layoutChart,
  type ChartLayout,
  type Item,
} from "./layout";
import { kindOf, type Sequence, type SfcStep, type SfcTransition } from "./model";

export interface SfcOnlineView {
  /** Step ids active in the last scan. */
  active: ReadonlySet<string>;
  /** Step id -> its time as shown (T#1s200ms). */
  times: Readonly<Record<string, string>>;
  /** Transition id -> the value of its condition in the last scan (null: not known yet). */
  conditions: Readonly<Record<string, boolean | null>>;
  /** Transitions that fired in the last scan. */
  fired: ReadonlySet<string>;
  /** Upper-case names of actions running (A) and of those whose action flag Q is TRUE. */
  running: ReadonlySet<string>;
  flagged: ReadonlySet<string>;
  /** Step ids whose X is forced. */
  forced: ReadonlySet<string>;
}

export interface SfcMarks {
  breakpoints: ReadonlySet<string>;
  /** The element a halted scan stands at. */
  halted: string | null;
}

export interface SfcDiagramProps {
  elements: Sequence;
  selected: string | null;
  selectedAssociation?: string | null;
  diagnostics?: readonly Diagnostic[];
  online?: SfcOnlineView;
  marks?: SfcMarks;
  scale?: number;
  onSelect?(id: string | null, event: MouseEvent): void;
  onSelectAssociation?(step: string, association: string, event: MouseEvent): void;
  onDoubleClick?(id: string, event: MouseEvent): void;
  onContextMenu?(id: string, event: MouseEvent): void;
}

const problemsOf = (diagnostics: readonly Diagnostic[] | undefined, id: string) =>
  (diagnostics ?? []).filter((d) => d.element === id);

export function SfcDiagram(props: SfcDiagramProps) {
  const layout: ChartLayout = layoutChart(props.elements);
  const scale = props.scale ?? 1;
  return (
    <svg
      className="sfc-canvas"
      width={layout.width * scale}
      height={layout.height * scale}
      viewBox={`0 0 ${layout.width} ${layout.height}`}
      role="img"
      aria-label="Sequential function chart"
      onMouseDown={(e) => {
        if (e.target === e.currentTarget) props.onSelect?.(null, e);
      }}
    >
      {layout.lines.map((line, i) => (
        <g key={i} className={line.double ? "sfc-line sfc-double" : "sfc-line"}>
          <line x1={line.x1} y1={line.y1} x2={line.x2} y2={line.y2} />
          {line.double ? <line x1={line.x1} y1={line.y1 + 4} x2={line.x2} y2={line.y2 + 4} /> : null}
        </g>
      ))}
      {layout.items.map((item) => (
        <ItemView key={item.element.id} item={item} initial={item === firstStep(layout)} {...props} />
      ))}
    </svg>
  );
}

const firstStep = (layout: ChartLayout): Item | undefined => layout.items.find((i) => kindOf(i.element) === "step");

/** The hover text of a drawn element's problems, each with its code (as the FBD editor shows them). */
function tooltip(problems: readonly Diagnostic[]): string {
  return problems.map((d) => `${d.code}: ${d.message}`).join("\n");
}

function ItemView(props: SfcDiagramProps & { item: Item; initial: boolean }) {
  const { item, online, marks, selected } = props;
  const id = item.element.id;
  const kind = kindOf(item.element);
  if (kind === "alternative" || kind === "parallel") return null;
  const problems = problemsOf(props.diagnostics, id);
  const classes = [
    "sfc-item",
    `sfc-${kind}`,
    selected === id ? "sfc-selected" : "",
    problems.some((d) => d.severity === "error") ? "sfc-error" : problems.length ? "sfc-warning" : "",
    marks?.halted === id ? "sfc-halted" : "",
  ]
    .filter(Boolean)
    .join(" ");
  const handlers = {
    onMouseDown: (e: MouseEvent) => {
      e.stopPropagation();
      props.onSelect?.(id, e);
    },
    onDoubleClick: (e: MouseEvent) => props.onDoubleClick?.(id, e),
    onContextMenu: (e: MouseEvent) => props.onContextMenu?.(id, e),
  };
  const title = tooltip(problems);
  const breakpoint = marks?.breakpoints.has(id) ? (
    <circle className="sfc-breakpoint" cx={item.x - STEP_W / 2 - 10} cy={item.y + item.height / 2} r={5} />
  ) : null;
  if (kind === "step") {
    const step = item.element as SfcStep;
    const active = online?.active.has(id) ?? false;
    const left = item.x - STEP_W / 2;
    const top = item.y + (item.height - STEP_H) / 2;
    return (
      <g className={`${classes}${active ? " sfc-active" : ""}`} data-sfc-id={id} aria-label={`step ${step.name}`}>
        {title ? <title>{title}</title> : null}
        <g {...handlers}>
          <rect className="sfc-box" x={left} y={top} width={STEP_W} height={STEP_H} />
          {props.initial ? (
            <rect className="sfc-box-inner" x={left + 4} y={top + 4} width={STEP_W - 8} height={STEP_H - 8} />
          ) : null}
          <text className="sfc-name" x={item.x} y={top + (online ? 16 : 24)}>
            {step.name}
          </text>
          {online ? (
            <text className="sfc-time" x={item.x} y={top + 32}>
              {online.forced.has(id) ? "F " : ""}
              {online.times[id] ?? ""}
            </text>
          ) : null}
          {step.entry ? (
            <text className="sfc-mark" x={left + 6} y={top + STEP_H - 4}>
              E
            </text>
          ) : null}
          {step.exit ? (
            <text className="sfc-mark" x={left + STEP_W - 13} y={top + STEP_H - 4}>
              X
            </text>
          ) : null}
        </g>
        {breakpoint}
        <ActionBlock {...props} step={step} x={left + STEP_W} y={item.y} />
      </g>
    );
  }
  if (kind === "transition") {
    const transition = item.element as SfcTransition;
    const mid = item.y + TRANSITION_H / 2;
    const value = online?.conditions[id];
    const fired = online?.fired.has(id) ?? false;
    return (
      <g
        className={`${classes}${fired ? " sfc-fired" : ""}`}
        data-sfc-id={id}
        aria-label={`transition ${transition.condition}`}
      >
        {title ? <title>{title}</title> : null}
        <g {...handlers}>
          <line className="sfc-line" x1={item.x} y1={item.y} x2={item.x} y2={item.y + TRANSITION_H} />
          <rect
            className="sfc-hit"
            x={item.x - 16}
            y={item.y}
            width={32 + 8 * (transition.condition?.length ?? 0)}
            height={TRANSITION_H}
          />
          <line className="sfc-bar" x1={item.x - 12} y1={mid} x2={item.x + 12} y2={mid} />
          {online ? (
            <text
              className={`sfc-condition-value ${value ? "sfc-true" : "sfc-false"}`}
              x={item.x + 16}
              y={mid + 4}
              data-condition={id}
            >
              {value === null || value === undefined ? "?" : value ? "TRUE" : "FALSE"}
            </text>
          ) : null}
          <text className="sfc-condition" x={item.x + (online ? 62 : 18)} y={mid + 4}>
            {transition.priority != null ? `[${transition.priority}] ` : ""}
            {transition.condition}
          </text>
        </g>
        {breakpoint}
      </g>
    );
  }
  const target = (item.element as { target: string }).target;
  return (
    <g className={classes} data-sfc-id={id} aria-label={`jump to ${target}`} {...handlers}>
      {title ? <title>{title}</title> : null}
      <line className="sfc-line" x1={item.x} y1={item.y} x2={item.x} y2={item.y + 12} />
      <path
        className="sfc-arrow"
        d={`M ${item.x - 7} ${item.y + 12} L ${item.x + 7} ${item.y + 12} L ${item.x} ${item.y + 22} Z`}
      />
      <text className="sfc-condition" x={item.x + 12} y={item.y + 20}>
        {target}
      </text>
    </g>
  );
}

function ActionBlock(props: SfcDiagramProps & { step: SfcStep; x: number; y: number }) {
  const { step, x, y, online } = props;
  const rows = step.actions ?? [];
  if (!rows.length) return null;
  const left = x + ACTION_GAP;
  return (
    <g className="sfc-actions">
      <line className="sfc-line" x1={x} y1={y + STEP_H / 2} x2={left} y2={y + STEP_H / 2} />
      {rows.map((row, i) => {
        const top = y + i * ROW_H;
        const name = row.action.trim().toUpperCase();
        const running = online?.running.has(name) ?? false;
        const flagged = online?.flagged.has(name) ?? false;
        const problems = problemsOf(props.diagnostics, row.id);
        const classes = [
          "sfc-association",
          running ? "sfc-active" : "",
          running && !flagged ? "sfc-final" : "",
          props.selectedAssociation === row.id ? "sfc-selected" : "",
          problems.some((d) => d.severity === "error") ? "sfc-error" : "",
        ]
          .filter(Boolean)
          .join(" ");
        return (
          <g
            key={row.id}
            className={classes}
            data-sfc-association={row.id}
            aria-label={`${row.qualifier ?? "N"} ${row.action}`}
            onMouseDown={(e) => {
              e.stopPropagation();
              props.onSelectAssociation?.(step.id, row.id, e);
            }}
          >
            {problems.length ? <title>{tooltip(problems)}</title> : null}
            <rect className="sfc-cell" x={left} y={top} width={QUALIFIER_W} height={ROW_H} />
            <rect
              className="sfc-cell sfc-action-name"
              x={left + QUALIFIER_W}
              y={top}
              width={ACTION_NAME_W}
              height={ROW_H}
            />
            <rect className="sfc-cell" x={left + QUALIFIER_W + ACTION_NAME_W} y={top} width={TIME_W} height={ROW_H} />
            <text className="sfc-cell-text" x={left + QUALIFIER_W / 2} y={top + 15}>
              {row.qualifier ?? "N"}
            </text>
            <text className="sfc-cell-text" x={left + QUALIFIER_W + ACTION_NAME_W / 2} y={top + 15}>
              {row.action}
            </text>
            <text className="sfc-cell-text" x={left + QUALIFIER_W + ACTION_NAME_W + TIME_W / 2} y={top + 15}>
              {row.time ?? ""}
            </text>
          </g>
        );
      })}
    </g>
  );
}
