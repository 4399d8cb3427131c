// The pins a box shows, in drawing order. Row 0 carries the rung's power: EN/ENO when the box has
// them, else its first BOOL input and first BOOL output (a BOOL function's result), as the LD
// lowering feeds it (issue 5). Pins come from the library entry; pins the model connects but the
// library does not list (extensible inputs IN3, IN4, ... or an unknown block) follow in model order.
import type { LibraryEntry, Pin } from "../generated/api";
import { boxInputs, boxOutputs, type Box, type Series } from "./model";

/** Name of a function's result pin, as in the FBD model (ir/fbd_order.py SIMPLE_OUT). */
export const RESULT_PIN = "OUT";

export interface BoxPin {
  /** "" for a power pin the library could not name. */
  name: string;
  type?: string;
  /** Carries the rung's power (row 0). */
  power: boolean;
  /** Operand text or a series fed from the left rail (inputs), or the target variable (outputs). */
  value?: string | Series;
}

export interface BoxPins {
  inputs: BoxPin[];
  outputs: BoxPin[];
}

const isBool = (pin: Pin) => pin.type.toUpperCase() === "BOOL";

function arrange(pins: Pin[], en: boolean, enName: string, values: Record<string, string | Series>): BoxPin[] {
  const power = en ? { name: enName, type: "BOOL" } : (pins.find(isBool) ?? { name: "", type: undefined });
  const rows: BoxPin[] = [{ name: power.name, type: power.type, power: true, value: values[power.name] }];
  for (const pin of pins)
    if (pin !== power) rows.push({ name: pin.name, type: pin.type, power: false, value: values[pin.name] });
  const listed = new Set(rows.map((r) => r.name));
  for (const [name, value] of Object.entries(values)) {
    if (!listed.has(name)) rows.push({ name, power: false, value });
  }
  return rows;
}

export function boxPins(box: Box, entry: LibraryEntry | undefined): BoxPins {
  const en = box.en ?? false;
  const inputPins = entry ? [...entry.inputs, ...entry.in_outs] : [];
  const result = entry?.kind === "function" && entry.return_type ? [{ name: RESULT_PIN, type: entry.return_type }] : [];
  const outputPins = entry ? [...result, ...entry.outputs] : [];
  return {
    inputs: arrange(inputPins, en, "EN", boxInputs(box)),
    outputs: arrange(outputPins, en, "ENO", boxOutputs(box)),
  };
}
