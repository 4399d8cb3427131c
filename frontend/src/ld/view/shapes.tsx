// SVG drawings of the LD elements, IEC style (GR-15..GR-27): contacts | |, coils ( ), compare
// contacts and boxes as rectangles, jumps as a double arrowhead, returns as a labelled end.
import type { MouseEvent, ReactNode } from "react";
import type { PlacedElement, PlacedPin } from "../layout";
import { METRICS, textWidth } from "../layout";
import { pinKey } from "../../online/pinValues";
import type { ValueShown } from "../../online/shown";
import type { OperandField } from "../ops";
import type { OnlineView } from "./types";

const CONTACT_MARK: Record<string, string> = { no: "", nc: "/", p: "P", n: "N" };
const COIL_MARK: Record<string, string> = { normal: "", negated: "/", set: "S", reset: "R", p: "P", n: "N" };

/** Text cut to fit `width` pixels, with an ellipsis; the full text goes in a tooltip. */
export function fit(text: string, width: number): string {
  const max = Math.floor(width / textWidth("M"));
  return text.length <= max ? text : `${text.slice(0, Math.max(1, max - 1))}…`;
}

/** Width of one character of value text (10 px monospace). */
const VALUE_CHAR = 6;
const F_MARK = 11;

/**
 * A value in a small badge, CODESYS style: TRUE blue, FALSE white with a dark frame, other values
 * framed; forced ones framed in orange with a red F; a prepared value follows as `<value>`.
 * (x, y) is the anchor point on the badge's middle line.
 */
export function ValueBadge({
  shown,
  x,
  y,
  anchor,
  maxWidth = 120,
}: {
  shown: ValueShown;
  x: number;
  y: number;
  anchor: "start" | "middle" | "end";
  maxWidth?: number;
}) {
  const max = Math.max(3, Math.floor((maxWidth - 6 - (shown.forced ? F_MARK : 0)) / VALUE_CHAR));
  const text = shown.text.length <= max ? shown.text : `${shown.text.slice(0, max - 1)}…`;
  const width = text.length * VALUE_CHAR + 6 + (shown.forced ? F_MARK : 0);
  const left = anchor === "start" ? x : anchor === "end" ? x - width : x - width / 2;
  const kind = shown.bool === null ? "ld-badge-value" : shown.bool ? "ld-badge-true" : "ld-badge-false";
  const title = `${shown.text}${shown.forced ? " (forced)" : ""}${shown.prepared !== null ? `, prepared ${shown.prepared}` : ""}`;
  return (
    <g className={`ld-badge ${kind}${shown.forced ? " ld-badge-forced" : ""}`} data-value={shown.text}>
      <title>{title}</title>
      <rect className="ld-badge-box" x={left} y={y - 7} width={width} height={13} rx={2} />
      <text className="ld-badge-text" x={left + 3} y={y + 3.5}>
        {text}
      </text>
      {shown.forced ? (
        <g className="ld-forced-badge" aria-label="forced">
          <rect x={left + width - F_MARK} y={y - 7} width={F_MARK} height={13} rx={2} />
          <text x={left + width - F_MARK / 2} y={y + 3.5} textAnchor="middle">
            F
          </text>
        </g>
      ) : null}
      {shown.prepared !== null ? (
        <text className="ld-prepared" x={left + width + 3} y={y + 3.5}>
          {`<${shown.prepared}>`}
        </text>
      ) : null}
    </g>
  );
}

interface OperandProps {
  id: string;
  field: OperandField;
  text: string;
  x: number;
  y: number;
  width: number;
  anchor?: "start" | "middle" | "end";
  online?: OnlineView;
  onOperand?: (id: string, field: OperandField, event: MouseEvent) => void;
  /** May stay empty (an FB input, an output pin): its "???" is muted instead of marked as missing. */
  optional?: boolean;
  /** Show a non-BOOL value next to the text (compare operands; boxes show theirs at the pin, contacts under the symbol). */
  withValue?: boolean;
}

/** An operand text: click to edit; shows "???" when empty, a forced variable on an orange ground, and a value. */
export function Operand({
  id,
  field,
  text,
  x,
  y,
  width,
  anchor = "middle",
  online,
  onOperand,
  optional = false,
  withValue = false,
}: OperandProps) {
  const shown = online?.operands?.[text.trim().toUpperCase()];
  const forced = shown?.forced ?? false;
  const label = text ? fit(text, width) : "???";
  const textLeft = anchor === "end" ? x - textWidth(label) : anchor === "middle" ? x - textWidth(label) / 2 : x;
  return (
    <g
      className={`ld-operand${text ? "" : optional ? " ld-operand-unset" : " ld-operand-empty"}${forced ? " ld-forced" : ""}`}
      data-field={field.kind === "input" || field.kind === "output" ? `${field.kind}:${field.pin}` : field.kind}
    >
      {forced ? (
        <rect
          className="ld-forced-ground"
          x={textLeft - 2}
          y={y - 11}
          width={textWidth(label) + 4}
          height={14}
          rx={2}
        />
      ) : null}
      <text x={x} y={y} textAnchor={anchor} onClick={onOperand ? (event) => onOperand(id, field, event) : undefined}>
        {text && label !== text ? <title>{text}</title> : null}
        {label}
      </text>
      {withValue && shown && shown.bool === null ? (
        <ValueBadge
          shown={shown}
          x={anchor === "end" ? textLeft - 4 : textLeft + textWidth(label) + 4}
          y={y - 4}
          anchor={anchor === "end" ? "end" : "start"}
        />
      ) : null}
    </g>
  );
}

/** A contact's or coil's variable value (TRUE/FALSE, forced, prepared) under its symbol. */
function VariableValue({ placed: p, online }: { placed: PlacedElement; online?: OnlineView }) {
  if (p.element.type !== "contact" && p.element.type !== "coil") return null;
  const shown = online?.operands?.[p.element.var.trim().toUpperCase()];
  return shown ? (
    <ValueBadge shown={shown} x={p.x + p.width / 2} y={p.lineY + 20} anchor="middle" maxWidth={p.width} />
  ) : null;
}

interface ShapeProps {
  placed: PlacedElement;
  online?: OnlineView;
  onOperand?: OperandProps["onOperand"];
}

/** The lead wires through an element's width, leaving a gap of `half` around its centre. */
function leads(p: PlacedElement, half: number): ReactNode {
  const cx = p.x + p.width / 2;
  return (
    <>
      <line className="ld-lead" x1={p.x} y1={p.lineY} x2={cx - half} y2={p.lineY} />
      <line className="ld-lead" x1={cx + half} y1={p.lineY} x2={p.x + p.width} y2={p.lineY} />
    </>
  );
}

export function ContactShape({ placed: p, online, onOperand }: ShapeProps) {
  if (p.element.type !== "contact") return null;
  const cx = p.x + p.width / 2;
  const mode = p.element.mode ?? "no";
  return (
    <>
      {leads(p, 8)}
      <line className="ld-symbol" x1={cx - 8} y1={p.lineY - 12} x2={cx - 8} y2={p.lineY + 12} />
      <line className="ld-symbol" x1={cx + 8} y1={p.lineY - 12} x2={cx + 8} y2={p.lineY + 12} />
      {mode === "nc" ? (
        <line className="ld-symbol ld-mark" x1={cx - 6} y1={p.lineY + 10} x2={cx + 6} y2={p.lineY - 10} />
      ) : null}
      {mode === "p" || mode === "n" ? (
        <text className="ld-mark" x={cx} y={p.lineY + 4} textAnchor="middle">
          {CONTACT_MARK[mode]}
        </text>
      ) : null}
      <Operand
        id={p.id}
        field={{ kind: "var" }}
        text={p.element.var}
        x={cx}
        y={p.lineY - 18}
        width={p.width}
        online={online}
        onOperand={onOperand}
      />
      <VariableValue placed={p} online={online} />
    </>
  );
}

export function CoilShape({ placed: p, online, onOperand }: ShapeProps) {
  if (p.element.type !== "coil") return null;
  const cx = p.x + p.width / 2;
  const mode = p.element.mode ?? "normal";
  const y = p.lineY;
  return (
    <>
      {leads(p, 10)}
      <path className="ld-symbol" d={`M ${cx - 6} ${y - 12} A 14 14 0 0 0 ${cx - 6} ${y + 12}`} fill="none" />
      <path className="ld-symbol" d={`M ${cx + 6} ${y - 12} A 14 14 0 0 1 ${cx + 6} ${y + 12}`} fill="none" />
      {mode === "negated" ? <line className="ld-symbol ld-mark" x1={cx - 5} y1={y + 9} x2={cx + 5} y2={y - 9} /> : null}
      {mode !== "normal" && mode !== "negated" ? (
        <text className="ld-mark" x={cx} y={y + 4} textAnchor="middle">
          {COIL_MARK[mode]}
        </text>
      ) : null}
      <Operand
        id={p.id}
        field={{ kind: "var" }}
        text={p.element.var}
        x={cx}
        y={y - 18}
        width={p.width}
        online={online}
        onOperand={onOperand}
      />
      <VariableValue placed={p} online={online} />
    </>
  );
}

export function CompareShape({ placed: p, online, onOperand }: ShapeProps) {
  if (p.element.type !== "compare") return null;
  const left = p.x + 6;
  const width = p.width - 12;
  const cx = p.x + p.width / 2;
  return (
    <>
      <line className="ld-lead" x1={p.x} y1={p.lineY} x2={left} y2={p.lineY} />
      <line className="ld-lead" x1={left + width} y1={p.lineY} x2={p.x + p.width} y2={p.lineY} />
      <rect className="ld-symbol ld-compare-box" x={left} y={p.y + 6} width={width} height={p.height - 8} rx={3} />
      <text className="ld-title" x={cx} y={p.y + 20} textAnchor="middle">
        {p.element.op}
      </text>
      <Operand
        id={p.id}
        field={{ kind: "left" }}
        text={p.element.left}
        x={cx}
        y={p.y + 36}
        width={width - 4}
        online={online}
        onOperand={onOperand}
        withValue
      />
      <Operand
        id={p.id}
        field={{ kind: "right" }}
        text={p.element.right}
        x={cx}
        y={p.y + 50}
        width={width - 4}
        online={online}
        onOperand={onOperand}
        withValue
      />
    </>
  );
}

export function JumpShape({ placed: p, onOperand }: ShapeProps) {
  if (p.element.type !== "jump") return null;
  const y = p.lineY;
  const tip = p.x + 26;
  return (
    <>
      <line className="ld-lead" x1={p.x} y1={y} x2={tip} y2={y} />
      <path
        className="ld-symbol ld-arrow"
        d={`M ${tip - 12} ${y - 6} L ${tip - 6} ${y} L ${tip - 12} ${y + 6} M ${tip - 6} ${y - 6} L ${tip} ${y} L ${tip - 6} ${y + 6}`}
        fill="none"
      />
      <Operand
        id={p.id}
        field={{ kind: "target" }}
        text={p.element.target}
        x={tip + 4}
        y={y + 4}
        width={p.width - 30}
        anchor="start"
        onOperand={onOperand}
      />
    </>
  );
}

export function ReturnShape({ placed: p }: ShapeProps) {
  if (p.element.type !== "return") return null;
  return (
    <>
      <line className="ld-lead" x1={p.x} y1={p.lineY} x2={p.x + 8} y2={p.lineY} />
      <rect className="ld-symbol" x={p.x + 8} y={p.lineY - 10} width={p.width - 16} height={20} rx={10} />
      <text className="ld-title" x={p.x + p.width / 2} y={p.lineY + 4} textAnchor="middle">
        RETURN
      </text>
    </>
  );
}

/** What a pin shows online: its bound value, else the power feeding it (a series or the rung). */
function pinShown(pin: PlacedPin, boxId: string, online?: OnlineView): ValueShown | undefined {
  const bound = online?.pins?.[boxId]?.[pinKey(pin.side, pin.name)];
  if (bound || pin.feed === undefined || !online?.power) return bound;
  const power = pin.feed === null ? true : online.power[pin.feed];
  return power === undefined
    ? undefined
    : { text: power ? "TRUE" : "FALSE", bool: power, forced: false, prepared: null };
}

function Pin({
  pin,
  boxId,
  instanced,
  online,
  onOperand,
}: {
  pin: PlacedPin;
  boxId: string;
  instanced: boolean;
  online?: OnlineView;
  onOperand?: OperandProps["onOperand"];
}) {
  const inside = pin.side === "in" ? pin.x + 4 : pin.x - 4;
  const outside = pin.side === "in" ? pin.x - 10 : pin.x + 10;
  const field: OperandField = { kind: pin.side === "in" ? "input" : "output", pin: pin.name };
  const text = typeof pin.value === "string" ? pin.value : "";
  const shown = pin.name ? pinShown(pin, boxId, online) : undefined;
  const valueAt = inside + (pin.side === "in" ? 1 : -1) * (textWidth(pin.name) * (10 / 12) + 4);
  return (
    <g className={`ld-pin ld-pin-${pin.side}${pin.power ? " ld-pin-power" : ""}`} data-pin={pin.name}>
      {!pin.power ? (
        <line className="ld-lead" x1={pin.x} y1={pin.y} x2={pin.side === "in" ? pin.x - 8 : pin.x + 8} y2={pin.y} />
      ) : null}
      <text className="ld-pin-name" x={inside} y={pin.y + 4} textAnchor={pin.side === "in" ? "start" : "end"}>
        {pin.name}
      </text>
      {shown ? (
        <g className="ld-pin-value" data-pin-value={pinKey(pin.side, pin.name)}>
          <ValueBadge
            shown={shown}
            x={valueAt}
            y={pin.y}
            anchor={pin.side === "in" ? "start" : "end"}
            maxWidth={METRICS.pinValue - 4}
          />
        </g>
      ) : null}
      {!pin.power && !Array.isArray(pin.value) && pin.name ? (
        <Operand
          id={boxId}
          field={field}
          text={text}
          x={outside}
          y={pin.y - 3}
          width={200}
          anchor={pin.side === "in" ? "end" : "start"}
          online={online}
          onOperand={onOperand}
          optional={pin.side === "out" || instanced}
        />
      ) : null}
    </g>
  );
}

export function BoxShape({ placed: p, online, onOperand }: ShapeProps) {
  if (p.element.type !== "box" || !p.body) return null;
  const b = p.body;
  const cx = b.x + b.width / 2;
  return (
    <>
      <rect className="ld-symbol ld-box-body" x={b.x} y={b.y} width={b.width} height={b.height} rx={2} />
      <text className="ld-title" x={cx} y={b.y + 14} textAnchor="middle">
        {p.element.call}
      </text>
      {p.instanced ? (
        <Operand
          id={p.id}
          field={{ kind: "instance" }}
          text={p.element.instance ?? ""}
          x={cx}
          y={b.y - 5}
          width={b.width}
          online={online}
          onOperand={onOperand}
        />
      ) : null}
      {p.pins?.map((pin) => (
        <Pin
          key={`${pin.side}:${pin.name}`}
          pin={pin}
          boxId={p.id}
          instanced={!!p.instanced}
          online={online}
          onOperand={onOperand}
        />
      ))}
    </>
  );
}

export const SHAPES = {
  contact: ContactShape,
  coil: CoilShape,
  compare: CompareShape,
  box: BoxShape,
  jump: JumpShape,
  return: ReturnShape,
} as const;
