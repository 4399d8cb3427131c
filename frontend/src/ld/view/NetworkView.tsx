// One network as its own SVG: header (number, label, comment), rails, wires, elements, insertion
// slots, diagnostic markers, breakpoint dots and the halt highlight. Memoised: the diagram
// re-renders only networks whose layout, selection, diagnostics, online or debug state changed.
import { memo, type MouseEvent } from "react";
import type { Diagnostic } from "../../generated/api";
import type { LaidWire, NetworkLayout, PlacedElement } from "../layout";
import { sameSeries, type Place } from "../model";
import { SHAPES, fit } from "./shapes";
import type { DebugMarks, DiagramHandlers, OnlineView, Selection, Target } from "./types";

export interface NetworkViewProps {
  layout: NetworkLayout;
  width: number;
  /** The selection when it concerns this network, else null (keeps other networks memoised). */
  selection: Selection | null;
  diagnostics: readonly Diagnostic[];
  online?: OnlineView;
  /** Show the insertion slots as drop targets (while dragging). */
  dropping: boolean;
  handlers: DiagramHandlers;
  debug?: DebugMarks;
}

/** "ld-on"/"ld-off" from the engine's power flow, nothing when offline or unknown. */
function powerClass(online: OnlineView | undefined, source: string | null): string {
  if (!online?.power) return "";
  if (source === null) return " ld-on";
  const value = online.power[source];
  return value === undefined ? "" : value ? " ld-on" : " ld-off";
}

const samePlace = (a: Place, b: Place) => a.index === b.index && sameSeries(a.series, b.series);

function Wire({ wire, online }: { wire: LaidWire; online?: OnlineView }) {
  const dimmed = wire.power !== null && online?.executed?.[wire.power] === false ? " ld-not-executed" : "";
  return (
    <line
      className={`ld-${wire.kind}${powerClass(online, wire.power)}${dimmed}`}
      x1={wire.x1}
      y1={wire.y1}
      x2={wire.x2}
      y2={wire.y2}
    />
  );
}

/** A breakpoint: a red dot, hollow when disabled. */
function BreakpointDot({
  x,
  y,
  r,
  enabled,
  label,
}: {
  x: number;
  y: number;
  r: number;
  enabled: boolean;
  label: string;
}) {
  return (
    <circle
      className={`ld-breakpoint${enabled ? "" : " ld-breakpoint-disabled"}`}
      cx={x}
      cy={y}
      r={r}
      role="img"
      aria-label={`${label}${enabled ? "" : " (disabled)"}`}
    >
      <title>{`${label}${enabled ? "" : " (disabled)"}`}</title>
    </circle>
  );
}

interface ElementProps {
  placed: PlacedElement;
  selected: boolean;
  /** true/false: an enabled/disabled breakpoint on the element; undefined: none. */
  breakpoint?: boolean;
  halted: boolean;
  problems: readonly Diagnostic[];
  online?: OnlineView;
  handlers: DiagramHandlers;
  coverage?: "never-executed" | "never-energised";
}

function Element({ placed, selected, breakpoint, halted, problems, online, handlers, coverage }: ElementProps) {
  const type = placed.element.type ?? "contact";
  const target: Target = { kind: "element", id: placed.id };
  const mode = "mode" in placed.element ? ` ld-mode-${placed.element.mode}` : "";
  const classes = [
    `ld-element ld-${type}${mode}`,
    selected ? "ld-selected" : "",
    powerClass(online, placed.id).trim(),
    online?.executed?.[placed.id] === false ? "ld-not-executed" : "",
    problems.length ? "ld-has-diagnostic" : "",
    halted ? "ld-halted" : "",
    coverage ? `ld-coverage-${coverage}` : "",
  ].filter(Boolean);
  const Shape = type === "parallel" ? null : SHAPES[type];
  return (
    <g
      className={classes.join(" ")}
      data-id={placed.id}
      onMouseDown={handlers.onPointerDown && ((e) => handlers.onPointerDown!(target, e))}
      onDoubleClick={handlers.onDoubleClick && ((e) => handlers.onDoubleClick!(target, e))}
      onContextMenu={handlers.onContextMenu && ((e) => handlers.onContextMenu!(target, e))}
    >
      <rect className="ld-hit" x={placed.x} y={placed.y} width={placed.width} height={placed.height} />
      {halted ? (
        <rect
          className="ld-halt-frame"
          x={placed.x - 2}
          y={placed.y - 2}
          width={placed.width + 4}
          height={placed.height + 4}
          rx={4}
        />
      ) : null}
      {Shape ? <Shape placed={placed} online={online} onOperand={handlers.onOperand} /> : null}
      {problems.length ? <Marker x={placed.x + placed.width - 6} y={placed.y + 8} problems={problems} /> : null}
      {breakpoint !== undefined ? (
        <BreakpointDot
          x={placed.x + 5}
          y={placed.y + 5}
          r={4}
          enabled={breakpoint}
          label={`Breakpoint on element ${placed.id}`}
        />
      ) : null}
    </g>
  );
}

/** A red marker whose tooltip lists the messages. */
function Marker({ x, y, problems }: { x: number; y: number; problems: readonly Diagnostic[] }) {
  const text = problems.map((d) => (d.pin ? `${d.pin}: ${d.message}` : d.message)).join("\n");
  return (
    <g className="ld-marker" role="img" aria-label={text}>
      <title>{text}</title>
      <circle cx={x} cy={y} r={7} />
      <text x={x} y={y + 4} textAnchor="middle">
        !
      </text>
    </g>
  );
}

function NetworkViewImpl({
  layout,
  width,
  selection,
  diagnostics,
  online,
  dropping,
  handlers,
  debug,
}: NetworkViewProps) {
  const { network } = layout;
  const networkTarget: Target = { kind: "network", id: network.id };
  const selectedIds = new Set(selection?.kind === "elements" ? selection.ids : []);
  const byElement = new Map<string, Diagnostic[]>();
  const own: Diagnostic[] = [];
  for (const d of diagnostics) {
    if (d.element) byElement.set(d.element, [...(byElement.get(d.element) ?? []), d]);
    else own.push(d);
  }
  const known = new Set(layout.elements.map((e) => e.id));
  for (const [id, list] of byElement) if (!known.has(id)) own.push(...list);
  const networkSelected = selection?.kind === "network";
  const executed = online?.executed?.[network.id] !== false;
  const onNetwork = (handler?: (t: Target, e: MouseEvent) => void) =>
    handler && ((e: MouseEvent) => handler(networkTarget, e));
  const breakpoint = debug?.networks?.[network.id];
  const halted = debug?.halted?.network === network.id ? debug.halted : null;
  const number = layout.index + 1;
  return (
    <svg
      className={`ld-network${networkSelected ? " ld-selected" : ""}${executed ? "" : " ld-not-executed"}${halted ? " ld-halted" : ""}`}
      data-network={network.id}
      width={width}
      height={layout.height}
      role="group"
      aria-label={`Network ${layout.index + 1}${network.label ? ` ${network.label}` : ""}`}
    >
      <g
        className="ld-header"
        onMouseDown={onNetwork(handlers.onPointerDown)}
        onContextMenu={onNetwork(handlers.onContextMenu)}
        onDoubleClick={onNetwork(handlers.onDoubleClick)}
      >
        <rect className="ld-header-bg" x={0} y={0} width={width} height={layout.rungTop - 4} />
        <g
          className={`ld-number-hit${handlers.onNetworkNumber ? " ld-clickable" : ""}`}
          role={handlers.onNetworkNumber ? "button" : undefined}
          aria-label={handlers.onNetworkNumber ? `Toggle breakpoint on network ${number}` : undefined}
          onClick={handlers.onNetworkNumber && ((e) => handlers.onNetworkNumber!(network.id, e))}
        >
          <rect className="ld-number-bg" x={0} y={0} width={layout.leftRailX - 2} height={22} />
          {breakpoint !== undefined ? (
            <BreakpointDot x={8} y={12} r={5} enabled={breakpoint} label={`Breakpoint on network ${number}`} />
          ) : null}
          <text className="ld-number" x={layout.leftRailX - 4} y={16} textAnchor="end">
            {number}
          </text>
        </g>
        {network.label ? (
          <text className="ld-label" x={layout.leftRailX} y={16}>
            {network.label}:
          </text>
        ) : null}
        {network.comment ? (
          <text className="ld-comment" x={layout.leftRailX} y={network.label ? 32 : 16}>
            {fit(network.comment.split("\n")[0]!, layout.rightRailX - layout.leftRailX)}
          </text>
        ) : null}
        {own.length ? <Marker x={layout.rightRailX - 10} y={12} problems={own} /> : null}
      </g>
      <line
        className={`ld-rail${online?.power ? " ld-on" : ""}`}
        x1={layout.leftRailX}
        y1={layout.rungTop - 2}
        x2={layout.leftRailX}
        y2={layout.rungBottom + 2}
      />
      <line
        className="ld-rail ld-rail-right"
        x1={layout.rightRailX}
        y1={layout.rungTop - 2}
        x2={layout.rightRailX}
        y2={layout.rungBottom + 2}
      />
      {layout.wires.map((wire, i) => (
        <Wire key={i} wire={wire} online={online} />
      ))}
      {layout.elements.map((placed) => (
        <Element
          key={placed.id}
          placed={placed}
          selected={selectedIds.has(placed.id)}
          breakpoint={debug?.elements?.[placed.id]}
          halted={halted?.element === placed.id}
          problems={byElement.get(placed.id) ?? []}
          online={online}
          handlers={handlers}
          coverage={debug?.coverage?.get(placed.id)}
        />
      ))}
      {layout.slots.map((slot) => {
        const selected = selection?.kind === "place" && samePlace(selection.place, slot.place);
        const target: Target = { kind: "place", place: slot.place };
        return (
          <rect
            key={`${JSON.stringify(slot.place.series)}:${slot.place.index}`}
            className={`ld-slot${selected ? " ld-selected" : ""}${dropping ? " ld-drop" : ""}`}
            x={slot.x - 6}
            y={slot.y - 6}
            width={12}
            height={12}
            rx={3}
            onMouseDown={handlers.onPointerDown && ((e) => handlers.onPointerDown!(target, e))}
            onMouseUp={handlers.onPlaceUp && ((e) => handlers.onPlaceUp!(slot.place, e))}
            onContextMenu={handlers.onContextMenu && ((e) => handlers.onContextMenu!(target, e))}
          />
        );
      })}
    </svg>
  );
}

export const NetworkView = memo(NetworkViewImpl);
