import { describe, expect, it } from "vitest";
import type { LibraryEntry, Pou } from "../generated/api";
import { membersAfter, type Scope } from "../st/members";
import { qualifiers } from "../st/qualifiers";
import { defaultSuggestion, operandSuggestions, suggest, type MembersAfter } from "./OperandEditor";
import { symbol } from "../test/symbols";

const sym = (name: string) => symbol(name, "BOOL");
const symbols = [sym("Motor"), sym("Start"), sym("StartCount"), sym("Remote")];

describe("operand autocomplete: what Enter and Tab take", () => {
  it("highlights the first suggestion that starts with the typed text", () => {
    const list = suggest("Mo", symbols);
    expect(list.map((s) => s.name)).toEqual(["Motor", "Remote"]);
    expect(defaultSuggestion("Mo", list, symbols)).toBe(0);
  });

  it("highlights nothing for a text that names a symbol, only contains one, or is empty", () => {
    expect(defaultSuggestion("Start", suggest("Start", symbols), symbols)).toBe(-1);
    expect(defaultSuggestion("mot", suggest("mot", [sym("Remote")]), [sym("Remote")])).toBe(-1);
    expect(defaultSuggestion("", suggest("", symbols), symbols)).toBe(-1);
  });
});

describe("operand autocomplete after a qualifier (issue 25: T1., Prog., Color., Color#)", () => {
  const types = "TYPE Color : (Red, Green, Blue); END_TYPE";
  const other: Pou = {
    name: "Other",
    kind: "program",
    language: "st",
    declarations: "VAR_INPUT k : INT; END_VAR\nVAR_OUTPUT done : BOOL; END_VAR\nVAR hidden : INT; END_VAR",
    body: "",
  };
  const ton: LibraryEntry = {
    name: "TON",
    kind: "function_block",
    source: "standard",
    comment: null,
    extensible: false,
    inputs: [
      { name: "IN", type: "BOOL" },
      { name: "PT", type: "TIME" },
    ],
    in_outs: [],
    outputs: [
      { name: "Q", type: "BOOL" },
      { name: "ET", type: "TIME" },
    ],
    return_type: null,
  };
  const names = [symbol("T1", "TON"), sym("Motor")];
  const scope: Scope = { symbols: names, library: [ton], structs: new Map(), qualifiers: qualifiers([other], types) };
  const members: MembersAfter = (chain, separator) => membersAfter(chain, scope, separator);
  const offered = (text: string) => operandSuggestions(text, names, members).map((s) => `${s.name}:${s.type}`);

  it("offers an enumeration's values as whole operands after `Color.` and `Color#`, narrowed by what follows", () => {
    expect(offered("Color.")).toEqual(["Color.Red:Color", "Color.Green:Color", "Color.Blue:Color"]);
    expect(offered("color#g")).toEqual(["color#Green:Color"]);
    expect(offered("Color.Red")).toEqual([]); // typed in full
  });

  it("offers a program's inputs and outputs and an FB instance's pins", () => {
    expect(offered("Other.")).toEqual(["Other.k:INT", "Other.done:BOOL"]);
    expect(offered("T1.")).toEqual(["T1.IN:BOOL", "T1.PT:TIME", "T1.Q:BOOL", "T1.ET:TIME"]);
  });

  it("highlights the first member, and keeps plain names and literals as before", () => {
    expect(defaultSuggestion("Color.", operandSuggestions("Color.", names, members), names)).toBe(0);
    expect(offered("Mo")).toEqual(["Motor:BOOL"]);
    expect(offered("T#5s")).toEqual([]);
    expect(offered("Motor.")).toEqual([]);
    expect(operandSuggestions("Color.", names).map((s) => s.name)).toEqual([]); // no `members`: plain names only
  });
});

describe("operand autocomplete after an array element (issue 25)", () => {
  it("offers the element's members as whole operands", () => {
    const scope: Scope = {
      symbols: [symbol("a", "ARRAY [1..3] OF TON")],
      library: [
        {
          name: "TON",
          kind: "function_block",
          source: "standard",
          comment: null,
          extensible: false,
          inputs: [{ name: "IN", type: "BOOL" }],
          in_outs: [],
          outputs: [{ name: "Q", type: "BOOL" }],
          return_type: null,
        },
      ],
      structs: new Map(),
    };
    const members: MembersAfter = (chain, separator) => membersAfter(chain, scope, separator);
    expect(operandSuggestions("a[2].", [], members).map((s) => s.name)).toEqual(["a[2].IN", "a[2].Q"]);
  });
});
