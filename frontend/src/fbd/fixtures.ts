// Test data for the FBD tests: library entries as GET /api/library lists them and a small
// network builder (the `result := (var1 + var2) - var3` network of the browser test).
import type { LibraryEntry, SymbolInfo } from "../generated/api";
import { entry } from "../ld/fixtures";
import { plainSymbol } from "../store/project";
import type { FbdBody, FbdNetwork, Wire } from "./model";

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
    "SUB",
    "function",
    [
      ["IN1", "ANY_NUM"],
      ["IN2", "ANY_NUM"],
    ],
    [],
    { return_type: "ANY_NUM" },
  ),
  entry(
    "AND",
    "function",
    [
      ["IN1", "ANY_BIT"],
      ["IN2", "ANY_BIT"],
    ],
    [],
    { extensible: true, return_type: "ANY_BIT" },
  ),
  entry(
    "MUX",
    "function",
    [
      ["K", "ANY_INT"],
      ["IN0", "ANY"],
      ["IN1", "ANY"],
    ],
    [],
    { extensible: true, return_type: "ANY" },
  ),
  entry(
    "GT",
    "function",
    [
      ["IN1", "ANY"],
      ["IN2", "ANY"],
    ],
    [],
    { extensible: true, return_type: "BOOL" },
  ),
];

export const lookup = (call: string): LibraryEntry | undefined => LIBRARY.find((e) => e.name === call.toUpperCase());

const symbol = plainSymbol;
export const SYMBOLS: SymbolInfo[] = [
  symbol("var1", "INT"),
  symbol("var2", "INT"),
  symbol("var3", "INT"),
  symbol("result", "INT"),
  symbol("flag", "BOOL"),
  symbol("big", "DINT"),
  symbol("t1", "TON"),
];

export const wire = (from: string, fromPin: string, to: string, toPin: string): Wire => ({
  from: { node: from, pin: fromPin },
  to: { node: to, pin: toPin },
});

/** var1 + var2 - var3 -> result, drawn left to right. */
export const arithmetic = (): FbdNetwork => ({
  id: "n1",
  nodes: [
    { type: "input", id: "a", expr: "var1", pos: { x: 0, y: 0 } },
    { type: "input", id: "b", expr: "var2", pos: { x: 0, y: 50 } },
    { type: "input", id: "c", expr: "var3", pos: { x: 0, y: 100 } },
    { type: "block", id: "add", call: "ADD", pos: { x: 200, y: 0 } },
    { type: "block", id: "sub", call: "SUB", pos: { x: 400, y: 0 } },
    { type: "output", id: "r", var: "result", pos: { x: 600, y: 0 } },
  ],
  wires: [
    wire("a", "OUT", "add", "IN1"),
    wire("b", "OUT", "add", "IN2"),
    wire("add", "OUT", "sub", "IN1"),
    wire("c", "OUT", "sub", "IN2"),
    wire("sub", "OUT", "r", "IN"),
  ],
});

export const bodyOf = (...networks: FbdNetwork[]): FbdBody => ({ networks });
