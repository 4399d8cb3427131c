// IEC 61131-3 Instruction List for CodeMirror 6 (docs/il.md): the ST tokens (comments, strings,
// literals, names), plus IL's layout: a label (`name:`) and then the operator, the first word of an
// instruction, are marked as such; the words after it are operands. Completion offers the operators
// of the seeds' tables where an operator stands (the operand position keeps the ST completions).
import type { Completion } from "@codemirror/autocomplete";
import { StreamLanguage, type StreamParser } from "@codemirror/language";
import { stParser, type StState } from "./language";

/** Every IL operator with its meaning (IL-03, IL-20..IL-24), as completion entries show it. */
export const IL_OPERATORS: Record<string, string> = {
  LD: "load the operand into the accumulator",
  LDN: "load the negated operand",
  ST: "store the accumulator in the operand",
  STN: "store the negated accumulator",
  S: "set the BOOL operand when the accumulator is TRUE",
  R: "reset the BOOL operand when the accumulator is TRUE",
  AND: "accumulator AND operand",
  ANDN: "accumulator AND NOT operand",
  OR: "accumulator OR operand",
  ORN: "accumulator OR NOT operand",
  XOR: "accumulator XOR operand",
  XORN: "accumulator XOR NOT operand",
  NOT: "negate the accumulator",
  ADD: "accumulator + operand",
  SUB: "accumulator - operand",
  MUL: "accumulator * operand",
  DIV: "accumulator / operand",
  MOD: "accumulator MOD operand",
  GT: "accumulator > operand (BOOL)",
  GE: "accumulator >= operand (BOOL)",
  EQ: "accumulator = operand (BOOL)",
  NE: "accumulator <> operand (BOOL)",
  LE: "accumulator <= operand (BOOL)",
  LT: "accumulator < operand (BOOL)",
  JMP: "jump to a label",
  JMPC: "jump when the accumulator is TRUE",
  JMPCN: "jump when the accumulator is FALSE",
  CAL: "call a function block instance",
  CALC: "call when the accumulator is TRUE",
  CALCN: "call when the accumulator is FALSE",
  RET: "return",
  RETC: "return when the accumulator is TRUE",
  RETCN: "return when the accumulator is FALSE",
  S1: "call an SR with S1 := accumulator",
  R1: "call an RS with R1 := accumulator",
  CLK: "call a trigger with CLK := accumulator",
  CU: "call a counter with CU := accumulator",
  CD: "call a counter with CD := accumulator",
  PV: "call a counter with PV := accumulator",
  IN: "call a timer with IN := accumulator",
  PT: "call a timer with PT := accumulator",
};

/** The completion entries of the operators (shown first at an operator position). */
export const IL_OPERATOR_COMPLETIONS: readonly Completion[] = Object.entries(IL_OPERATORS).map(([label, info]) => ({
  label,
  type: "keyword",
  detail: "IL",
  info,
  boost: 10,
}));

interface IlState extends StState {
  /** No operator on this line yet: the next word is the operator (or a label). */
  operator: boolean;
}

export const ilParser: StreamParser<IlState> = {
  name: "iec-il",
  startState: () => ({ open: null, sfc: false, operator: true }),
  copyState: (s) => ({ open: s.open, sfc: s.sfc, operator: s.operator }),
  token(stream, state) {
    if (stream.sol()) state.operator = true;
    if (!state.open && state.operator) {
      if (stream.match(/^[A-Za-z_][A-Za-z0-9_]*[ \t]*:(?!=)/)) return "labelName";
      const word = stream.match(/^([A-Za-z_][A-Za-z0-9_]*|&N?|\))/) as RegExpMatchArray | null;
      if (word) {
        state.operator = false;
        return word[0].toUpperCase() in IL_OPERATORS || word[0] === ")" || word[0].startsWith("&")
          ? "keyword"
          : "function(variableName)";
      }
    }
    return stParser.token(stream, state);
  },
  languageData: stParser.languageData,
};

export const ilLanguage = StreamLanguage.define(ilParser);
