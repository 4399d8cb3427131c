import fc from "fast-check";
import { describe, expect, it } from "vitest";
import main from "../../../examples/motor/pous/Main.ld.json";
import {
  freeName,
  parseDeclarations,
  printDeclarations,
  userTypeNames,
  VAR_CLASSES,
  type DeclRow,
} from "./declarations";

const row = (name: string, type: string, extra: Partial<DeclRow> = {}): DeclRow => ({
  name,
  varClass: "VAR",
  type,
  initial: "",
  address: "",
  comment: "",
  ...extra,
});
const rowsOf = (text: string) => {
  const r = parseDeclarations(text);
  if (!r.ok) throw new Error(`${r.line}: ${r.error}`);
  return r.rows.map(({ line: _line, ...rest }) => rest);
};

describe("declarations as table rows", () => {
  it("reads the motor example's declarations with their comments and lines", () => {
    const r = parseDeclarations(main.declarations);
    expect(r.ok && r.rows.map((x) => [x.name, x.varClass, x.type, x.comment, x.line])).toEqual([
      ["RunTimer", "VAR", "TON", "motor has been running for 5 s", 2],
      ["StartCounter", "VAR", "CTU", "counts motor starts", 3],
      ["Blink", "VAR", "Blinker", "ST function block used from LD", 4],
      ["MotorRunning", "VAR", "BOOL", "", 5],
      ["Lamp", "VAR", "BOOL", "", 6],
    ]);
  });

  it("reads classes with qualifiers, addresses, initial values with nesting and strings, and name lists", () => {
    const text = [
      "VAR_INPUT",
      "    Period : TIME := T#1s;    // full cycle",
      "END_VAR",
      "VAR_GLOBAL RETAIN",
      "    Start AT %IX0.0 : BOOL;",
      "    a, b : ARRAY[1..3] OF INT := [1, 2, 3];",
      "    s : STRING[20] := 'x;y';",
      "END_VAR",
    ].join("\n");
    expect(rowsOf(text)).toEqual([
      row("Period", "TIME", { varClass: "VAR_INPUT", initial: "T#1s", comment: "full cycle" }),
      row("Start", "BOOL", { varClass: "VAR_GLOBAL RETAIN", address: "%IX0.0" }),
      row("a", "ARRAY[1..3] OF INT", { varClass: "VAR_GLOBAL RETAIN", initial: "[1, 2, 3]" }),
      row("b", "ARRAY[1..3] OF INT", { varClass: "VAR_GLOBAL RETAIN", initial: "[1, 2, 3]" }),
      row("s", "STRING[20]", { varClass: "VAR_GLOBAL RETAIN", initial: "'x;y'" }),
    ]);
    expect(rowsOf("")).toEqual([]);
  });

  it("says where the table cannot follow the text (and keeps it read-only)", () => {
    expect(parseDeclarations("VAR\n  (* heading *)\n  x : INT;\nEND_VAR")).toEqual({
      ok: false,
      error: "a comment between declarations",
      line: 2,
    });
    expect(parseDeclarations("VAR\n  x : INT;\n")).toEqual({ ok: false, error: "VAR has no END_VAR", line: 3 });
    expect(parseDeclarations("VAR\n  x INT;\nEND_VAR")).toMatchObject({ ok: false, line: 2 });
    expect(parseDeclarations("x : INT;")).toEqual({
      ok: false,
      error: "text outside a VAR ... END_VAR block",
      line: 1,
    });
  });

  it("prints rows as aligned blocks, one per run of a class", () => {
    const text = printDeclarations([
      row("Start", "BOOL", { address: "%IX0.0", comment: "push button" }),
      row("Count", "INT", { initial: "5" }),
      row("Out", "BOOL", { varClass: "VAR_OUTPUT" }),
    ]);
    expect(text).toBe(
      [
        "VAR",
        "    Start AT %IX0.0 : BOOL;        (* push button *)",
        "    Count           : INT := 5;",
        "END_VAR",
        "VAR_OUTPUT",
        "    Out : BOOL;",
        "END_VAR",
      ].join("\n"),
    );
  });

  it("reads back what it prints (property)", () => {
    const ident = fc.stringMatching(/^[A-Za-z_][A-Za-z0-9_]{0,8}$/).filter((n) => !/^(END_VAR|AT|VAR\w*)$/i.test(n));
    const arbRow = fc.record({
      name: ident,
      varClass: fc.constantFrom(...VAR_CLASSES),
      type: fc.constantFrom("BOOL", "INT", "TON", "ARRAY[0..3] OF REAL", "STRING[10]"),
      initial: fc.constantFrom("", "0", "T#5s", "'a;b'", "[1, 2]"),
      address: fc.constantFrom("", "%IX0.1", "%QW4"),
      comment: fc.constantFrom("", "a note", "x := 1; (nested)"),
    });
    fc.assert(
      fc.property(fc.array(arbRow, { maxLength: 6 }), (rows) => {
        expect(rowsOf(printDeclarations(rows))).toEqual(rows);
      }),
    );
  });
});

describe("helpers of the table", () => {
  it("finds a free name ignoring case", () => {
    expect(freeName([row("newvar", "BOOL"), row("NewVar1", "BOOL")])).toBe("NewVar2");
    expect(freeName([])).toBe("NewVar");
  });

  it("lists the user types of the TYPE text, not their members", () => {
    const types =
      "TYPE\n  Mode : (Off, Auto, Manual);\n  Recipe : STRUCT\n    Speed : INT;\n  END_STRUCT;\n  Level : INT (0..100);\nEND_TYPE";
    expect(userTypeNames(types)).toEqual(["Mode", "Recipe", "Level"]);
  });
});
