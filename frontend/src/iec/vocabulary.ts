// The IEC 61131-3 words and type rules the browser uses, all read from the backend's vocabulary
// (src/generated/iec.ts, written by `make schema` from backend/ladderlab/st/vocabulary.py), so the
// declarations table, the FBD wire check, the ST highlighters and the LD declare offer cannot
// disagree with the checker (issue 19 item 2, issue 22 item 3). Nothing here is typed by hand.
import { IEC } from "../generated/iec";

/** The elementary types in the backend's order (BOOL, SINT ... STRING). */
export const ELEMENTARY: readonly string[] = IEC.elementary.map((e) => e.name);

/** The width in bits of an integer or bit string type (BYTE 8, INT 16 ...), whose bits and parts ST selects
 * (`w.%X3`, `d.%B1`); null for any other type. */
export function partBits(type: string): number | null {
  const name = type.trim().toUpperCase();
  const found = IEC.elementary.find((e) => e.name === name && (e.category === "int" || e.category === "bits"));
  return found ? found.bits : null;
}

/** Every type name a declaration may use without defining it: the elementary types and WSTRING. */
export const DECLARABLE_TYPES: readonly string[] = [...new Set([...ELEMENTARY, ...IEC.strings])];

/** Short spellings of type names (TOD, DT) -> the full name. */
export const ALIASES: Readonly<Record<string, string>> = IEC.aliases;

/** Generic families (ANY_NUM ...) -> their elementary members. */
export const FAMILIES: Readonly<Record<string, readonly string[]>> = IEC.generic;

const WIDENING: Readonly<Record<string, readonly string[]>> = IEC.widening;

/** Lossless implicit conversion of one elementary type into another (the checker's `assignable`). */
export const widens = (source: string, target: string): boolean => WIDENING[source]?.includes(target) ?? false;

/** The standard function blocks' type names (TON, CTU, R_TRIG ...). */
export const STANDARD_FBS: readonly string[] = IEC.function_blocks.map((fb) => fb.name);

/** The keywords of the ST grammar, upper case (TRUE and FALSE among them). */
export const KEYWORDS: ReadonlySet<string> = new Set(IEC.keywords);
/** Textual SFC's words (STEP, TRANSITION, ACTION, ...): keywords only inside an SFC body, which starts with
 * INITIAL_STEP; elsewhere names (OSCAT's `step`), as the backend's grammar reads them. */
export const SFC_WORDS: ReadonlySet<string> = new Set(IEC.sfc_words);
/** What a test file (tests/<name>.st) adds to the keywords: TEST, SETUP, MOCK, ... and the test verbs. */
export const TEST_FILE_KEYWORDS: ReadonlySet<string> = new Set([
  ...IEC.keywords,
  ...IEC.test_keywords,
  ...IEC.test_verbs.map((v) => v.name),
]);

/** Words shown as type names: elementary and string types, their short spellings and the standard FBs. */
export const TYPE_WORDS: ReadonlySet<string> = new Set([...DECLARABLE_TYPES, ...Object.keys(ALIASES), ...STANDARD_FBS]);
