// Test data shared by the LD tests: the motor example's Main body, the standard blocks it uses as
// the library would list them, and small builders for hand-written rungs.
import main from "../../../examples/motor/pous/Main.ld.json";
import type { LibraryEntry } from "../generated/api";
import type { LdBody, LdElement, LdNetwork } from "./model";

export const motorMain = main.body as LdBody;

/** A library entry as GET /api/library lists it (LD and FBD tests). */
export const entry = (
  name: string,
  kind: LibraryEntry["kind"],
  inputs: [string, string][],
  outputs: [string, string][],
  extra: Partial<LibraryEntry> = {},
): LibraryEntry => ({
  name,
  kind,
  source: "standard",
  inputs: inputs.map(([n, type]) => ({ name: n, type })),
  outputs: outputs.map(([n, type]) => ({ name: n, type })),
  in_outs: [],
  extensible: false,
  return_type: null,
  comment: null,
  ...extra,
});

export const LIBRARY: LibraryEntry[] = [
  entry(
    "TON",
    "function_block",
    [
      ["IN", "BOOL"],
      ["PT", "TIME"],
    ],
    [
      ["Q", "BOOL"],
      ["ET", "TIME"],
    ],
    { comment: "on-delay timer" },
  ),
  entry(
    "CTU",
    "function_block",
    [
      ["CU", "BOOL"],
      ["R", "BOOL"],
      ["PV", "INT"],
    ],
    [
      ["Q", "BOOL"],
      ["CV", "INT"],
    ],
    { comment: "up counter" },
  ),
  entry(
    "ADD",
    "function",
    [
      ["IN1", "ANY_NUM"],
      ["IN2", "ANY_NUM"],
    ],
    [],
    { extensible: true, return_type: "ANY_NUM" },
  ),
  entry(
    "GT",
    "function",
    [
      ["IN1", "ANY_ELEMENTARY"],
      ["IN2", "ANY_ELEMENTARY"],
    ],
    [],
    { return_type: "BOOL" },
  ),
  entry("Blinker", "function_block", [["Period", "TIME"]], [["Q", "BOOL"]], { source: "user" }),
];

export const library = (call: string): LibraryEntry | undefined => LIBRARY.find((e) => e.name === call);

export const c = (id: string, variable = id.toUpperCase(), mode: "no" | "nc" | "p" | "n" = "no"): LdElement => ({
  type: "contact",
  id,
  var: variable,
  mode,
});
export const q = (id: string, variable = id.toUpperCase(), mode: "normal" | "set" | "reset" = "normal"): LdElement => ({
  type: "coil",
  id,
  var: variable,
  mode,
});
export const par = (id: string, ...branches: LdElement[][]): LdElement => ({ type: "parallel", id, branches });
export const net = (id: string, ...elements: LdElement[]): LdNetwork => ({ id, elements });
export const bodyOf = (...networks: LdNetwork[]): LdBody => ({ networks });
