import { StringStream } from "@codemirror/language";
import { describe, expect, it } from "vitest";
import { IL_OPERATORS, ilParser } from "./ilLanguage";

/** [text, style] of every non-space token of `text` (docs/il.md). */
function tokens(text: string): [string, string | null][] {
  const state = ilParser.startState!(2);
  const out: [string, string | null][] = [];
  for (const line of text.split("\n")) {
    const stream = new StringStream(line, 4, 2);
    while (!stream.eol()) {
      stream.start = stream.pos;
      const style = ilParser.token(stream, state);
      if (stream.current().trim()) out.push([stream.current().trim(), style]);
    }
  }
  return out;
}

describe("IL highlighting", () => {
  it("marks labels, the operator of each line and its operands (IL-01, IL-02, IL-03)", () => {
    expect(tokens("Step1: LD in1 // load\n  ST out (* c *)\nnext:\n  UserFun 100, T#5s\n)")).toEqual([
      ["Step1:", "labelName"],
      ["LD", "keyword"],
      ["in1", "variableName"],
      ["// load", "lineComment"],
      ["ST", "keyword"],
      ["out", "variableName"],
      ["(* c *)", "comment"],
      ["next:", "labelName"],
      ["UserFun", "function(variableName)"],
      ["100", "number"],
      [",", "punctuation"],
      ["T#5s", "number"],
      [")", "keyword"],
    ]);
  });

  it("reads an operator word in the operand position as a name (ST x, LD ST)", () => {
    expect(tokens("LD ST")).toEqual([
      ["LD", "keyword"],
      ["ST", "variableName"],
    ]);
  });

  it("knows every operator of the seeds' tables (IL-03) and IL-24's extras", () => {
    const table =
      "LD LDN ST STN S R AND ANDN OR ORN XOR XORN ADD SUB MUL DIV GT GE EQ NE LE LT JMP JMPC JMPCN CAL CALC CALCN " +
      "RET RETC RETCN MOD NOT S1 R1 CLK CU CD PV IN PT";
    expect(table.split(" ").filter((word) => !(word in IL_OPERATORS))).toEqual([]);
  });
});
