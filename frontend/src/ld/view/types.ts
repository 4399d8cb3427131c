// What the diagram view shows besides the model: the selection, diagnostics and online state.
import type { MouseEvent } from "react";
import type { Diagnostic } from "../../generated/api";
import type { Place } from "../model";
import type { OperandField } from "../ops";
import type { ValueShown } from "../../online/shown";

export type Selection =
  { kind: "elements"; ids: string[] } | { kind: "place"; place: Place } | { kind: "network"; id: string };

/**
 * What the diagram shows online: `power` is the engine's right-side power of each element by id,
 * `executed` false marks elements the last scan skipped, `operands` the values of the variables
 * the operands name (by operand text in upper case: a contact's or coil's value badge, non-BOOL
 * values next to their text, forced marks), `pins` the value on each box pin by box id and pin key
 * (`in:PT`, `out:ET`, online/pinValues.ts).
 */
export interface OnlineView {
  power?: Readonly<Record<string, boolean>>;
  executed?: Readonly<Record<string, boolean>>;
  operands?: Readonly<Record<string, ValueShown>>;
  pins?: Readonly<Record<string, Readonly<Record<string, ValueShown>>>>;
}

/**
 * Debugging marks (issue 9): breakpoints on networks and elements by id (true enabled, false
 * disabled, drawn hollow) and where a halted scan stands in this POU.
 */
export interface DebugMarks {
  networks?: Readonly<Record<string, boolean>>;
  elements?: Readonly<Record<string, boolean>>;
  halted?: { network: string; element: string | null } | null;
  /** Elements the last test run with coverage never executed or never energised (tinted). */
  coverage?: ReadonlyMap<string, "never-executed" | "never-energised">;
}

/** Something the user can point at in the diagram. */
export type Target =
  { kind: "element"; id: string } | { kind: "place"; place: Place } | { kind: "network"; id: string };

export interface DiagramHandlers {
  onPointerDown?(target: Target, event: MouseEvent): void;
  /** Mouse released over a place (a drop while dragging). */
  onPlaceUp?(place: Place, event: MouseEvent): void;
  onOperand?(id: string, field: OperandField, event: MouseEvent): void;
  onDoubleClick?(target: Target, event: MouseEvent): void;
  onContextMenu?(target: Target, event: MouseEvent): void;
  /** The network number was clicked (toggles a breakpoint on the network). */
  onNetworkNumber?(network: string, event: MouseEvent): void;
}

export type DiagnosticsByElement = ReadonlyMap<string, Diagnostic[]>;
