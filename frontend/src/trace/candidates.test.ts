import { describe, expect, it } from "vitest";
import type { LibraryEntry, SymbolTable } from "../generated/api";
import { traceCandidates } from "./candidates";
import { symbol } from "../test/symbols";

const ton: LibraryEntry = {
  name: "TON",
  kind: "function_block",
  source: "standard",
  comment: null,
  extensible: false,
  return_type: null,
  in_outs: [],
  inputs: [
    { name: "IN", type: "BOOL" },
    { name: "PT", type: "TIME" },
  ],
  outputs: [
    { name: "Q", type: "BOOL" },
    { name: "ET", type: "TIME" },
  ],
};

describe("traceCandidates", () => {
  it("offers BOOL and numeric variables, FB pins and globals, not strings, arrays or externals", () => {
    const main: SymbolTable = {
      pou: "Main",
      diagnostics: [],
      symbols: [
        symbol("Go", "BOOL"),
        symbol("Timer", "TON"),
        symbol("Name", "STRING[20]"),
        symbol("Grid", "ARRAY[1..3] OF INT"),
        symbol("Speed", "lreal"),
        symbol("Start", "BOOL", "VAR_EXTERNAL"),
      ],
      globals: [symbol("Start", "BOOL", "VAR_GLOBAL"), symbol("Label", "STRING", "VAR_GLOBAL")],
    };
    const other: SymbolTable = { pou: "Aux", diagnostics: [], symbols: [symbol("N", "DINT")], globals: main.globals };
    expect(traceCandidates([main, other], [ton])).toEqual([
      "Main.Go",
      "Main.Timer.IN",
      "Main.Timer.PT",
      "Main.Timer.Q",
      "Main.Timer.ET",
      "Main.Speed",
      "Aux.N",
      "Start",
    ]);
  });
});
