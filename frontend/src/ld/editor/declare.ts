// The "declare variable" offer: is an operand an undeclared plain name, and which type to propose
// (BOOL for contacts and coils, the pin's type for box pins, the block for an instance).
import type { LibraryEntry, SymbolInfo } from "../../generated/api";
import { locate, type LdBody } from "../model";
import type { OperandField } from "../ops";
import { RESULT_PIN } from "../pins";

import type { VariableDeclaration } from "../../store/declarations";
export type { VariableDeclaration };

const IDENTIFIER = /^[A-Za-z_][A-Za-z0-9_]*$/;
const BOOL_LITERALS = new Set(["TRUE", "FALSE"]);

/**
 * A concrete type for a generic pin family (the backend's families, iec/vocabulary.ts): what a new
 * variable on such a pin most likely is. Each is a member of its family (iec/vocabulary.test.ts).
 */
export const FAMILY_DEFAULT: Readonly<Record<string, string>> = {
  ANY: "INT",
  ANY_ELEMENTARY: "INT",
  ANY_MAGNITUDE: "INT",
  ANY_NUM: "INT",
  ANY_INT: "INT",
  ANY_REAL: "REAL",
  ANY_BIT: "WORD",
  ANY_STRING: "STRING",
  ANY_DATE: "DATE_AND_TIME",
  ANY_DURATION: "TIME",
};

export const concrete = (type: string): string => FAMILY_DEFAULT[type.toUpperCase()] ?? type;

/** Names of `symbols`, upper case (IEC names ignore case). */
export const symbolNames = (symbols: readonly SymbolInfo[]): Set<string> =>
  new Set(symbols.map((s) => s.name.toUpperCase()));

/** The operand when it is a plain identifier no symbol declares (literals, paths, addresses are not offered). */
export function undeclared(text: string, known: ReadonlySet<string>): string | null {
  const name = text.trim();
  if (!IDENTIFIER.test(name) || BOOL_LITERALS.has(name.toUpperCase()) || known.has(name.toUpperCase())) return null;
  return name;
}

/** The type to propose for a new variable in `field` of element `id`; null when it is no variable (a jump target). */
export function guessType(
  body: LdBody,
  id: string,
  field: OperandField,
  library: (call: string) => LibraryEntry | undefined,
  symbols: readonly SymbolInfo[],
): string | null {
  const element = locate(body, id)?.element;
  if (!element) return null;
  switch (element.type) {
    case "contact":
    case "coil":
      return "BOOL";
    case "compare": {
      const other = field.kind === "left" ? element.right : element.left;
      return symbols.find((s) => s.name.toUpperCase() === other.trim().toUpperCase())?.type ?? "INT";
    }
    case "box": {
      if (field.kind === "instance") return element.call;
      const entry = library(element.call);
      if (!entry || (field.kind !== "input" && field.kind !== "output")) return null;
      if (field.kind === "output" && field.pin === RESULT_PIN && entry.return_type) return concrete(entry.return_type);
      const pins = field.kind === "input" ? [...entry.inputs, ...entry.in_outs] : entry.outputs;
      const pin =
        pins.find((p) => p.name === field.pin) ??
        (entry.extensible && field.kind === "input" ? entry.inputs[entry.inputs.length - 1] : undefined);
      return pin ? concrete(pin.type) : null;
    }
    default:
      return null;
  }
}

/** A free instance name for a new FB box: the block's name and the first unused number. */
export function instanceName(call: string, known: ReadonlySet<string>): string {
  let n = 1;
  while (known.has(`${call}_${n}`.toUpperCase())) n += 1;
  return `${call}_${n}`;
}

/** What the declare dialog offers for `text` typed into `field` of element `id`: an undeclared plain name with
 * its guessed type, or null (a declared name, a literal, no variable). After an edit and from the element's menu. */
export function declareOffer(
  body: LdBody,
  id: string,
  field: OperandField,
  text: string,
  known: ReadonlySet<string>,
  library: (call: string) => LibraryEntry | undefined,
  symbols: readonly SymbolInfo[],
): VariableDeclaration | null {
  const name = undeclared(text, known);
  const type = name ? guessType(body, id, field, library, symbols) : null;
  return name && type ? { name, type } : null;
}
