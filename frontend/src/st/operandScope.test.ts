// The LD/FBD operand editor's suggestions after a qualifier (issue 25): the members ST completion offers, as
// whole operands.
import { describe, expect, it } from "vitest";
import type { LibraryEntry, Pou } from "../generated/api";
import { defaultSuggestion } from "../ui/OperandEditor";
import type { Scope } from "./members";
import { operandMembers, qualifiedSuggestions } from "./operandScope";
import { qualifiers } from "./qualifiers";
import { symbol } from "../test/symbols";

const sym = (name: string) => symbol(name, "BOOL");

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
  const offered = (text: string) => (qualifiedSuggestions(text, scope) ?? []).map((s) => `${s.name}:${s.type}`);

  it("offers an enumeration's values as whole operands after `Color.` and `Color#`, narrowed by what follows", () => {
    expect(offered("Color.")).toEqual(["Color.Red:Color", "Color.Green:Color", "Color.Blue:Color"]);
    expect(offered("color#g")).toEqual(["color#Green:Color"]);
    expect(offered("Color.Red")).toEqual([]); // typed in full
  });

  it("offers a program's inputs and outputs and an FB instance's pins", () => {
    expect(offered("Other.")).toEqual(["Other.k:INT", "Other.done:BOOL"]);
    expect(offered("T1.")).toEqual(["T1.IN:BOOL", "T1.PT:TIME", "T1.Q:BOOL", "T1.ET:TIME"]);
  });

  it("highlights the first member; a plain name is no qualified operand, a literal or a member of nothing none", () => {
    expect(defaultSuggestion("Color.", qualifiedSuggestions("Color.", scope)!, names)).toBe(0);
    expect(qualifiedSuggestions("Mo", scope)).toBeNull();
    expect(offered("T#5s")).toEqual([]);
    expect(offered("Motor.")).toEqual([]);
  });

  it("builds the scope from the working copy (operandMembers)", () => {
    const members = operandMembers(names, [ton], [other], types);
    expect(members("Other.d")?.map((s) => s.name)).toEqual(["Other.done"]);
    expect(members("Col")).toBeNull();
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
    expect(qualifiedSuggestions("a[2].", scope)?.map((s) => s.name)).toEqual(["a[2].IN", "a[2].Q"]);
  });
});
