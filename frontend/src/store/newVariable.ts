// What the declare dialog (LD, FBD and ST alike) asks of a new variable, and whether the answers make a
// declaration. Pure, so the dialog and the store share one notion of a "new variable".
import { identifierProblem } from "../iec/identifier";

/** A variable the user declares from an editor: `varClass` is the block keyword (VAR when absent). */
export interface NewVariable {
  name: string;
  type: string;
  varClass?: string;
  initial?: string;
  comment?: string;
}

/** The classes the dialog offers, in CODESYS's Auto Declare order; VAR_GLOBAL goes to the global variable list. */
export const DECLARE_CLASSES: readonly string[] = [
  "VAR",
  "VAR_INPUT",
  "VAR_OUTPUT",
  "VAR_IN_OUT",
  "VAR_TEMP",
  "VAR CONSTANT",
  "VAR RETAIN",
  "VAR_GLOBAL",
  "VAR_GLOBAL CONSTANT",
  "VAR_GLOBAL RETAIN",
];

/** Whether a variable of `varClass` belongs in the global variable list rather than the POU. */
export const isGlobalClass = (varClass: string | undefined): boolean => /^VAR_GLOBAL\b/i.test(varClass?.trim() ?? "");

/** Why `v` cannot be declared (in the user's words), or null when it can. */
export function declareProblem(v: NewVariable): string | null {
  const notIdentifier = identifierProblem(v.name);
  if (notIdentifier) return notIdentifier;
  if (!v.type.trim()) return `${v.name.trim()} needs a type, e.g. BOOL, INT or TIME.`;
  if (/^VAR(_GLOBAL)? CONSTANT$/i.test(v.varClass?.trim() ?? "") && !v.initial?.trim())
    return `A constant needs an initial value: ${v.name.trim()} : ${v.type.trim()} := ...`;
  return null;
}
