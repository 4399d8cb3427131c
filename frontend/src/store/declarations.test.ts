import { describe, expect, it } from "vitest";
import { addDeclaration } from "./declarations";

describe("addDeclaration", () => {
  it("adds to the first plain VAR block and aligns the declarations in columns (issue 28)", () => {
    const text = "VAR_INPUT\n  Go : BOOL;\nEND_VAR\nVAR\n\tT1 : TON;  (* timer *)\nEND_VAR";
    expect(addDeclaration(text, { name: "Pump", type: "BOOL" })).toBe(
      "VAR_INPUT\n    Go : BOOL;\nEND_VAR\nVAR\n    T1   : TON;     (* timer *)\n    Pump : BOOL;\nEND_VAR",
    );
  });

  it("leaves lines it cannot align as they are", () => {
    const text = "VAR\n  a, b : INT; c : BOOL;\n  (* note *)\n  Long_name : TIME;\nEND_VAR";
    expect(addDeclaration(text, { name: "X", type: "INT" })).toBe(
      "VAR\n  a, b : INT; c : BOOL;\n  (* note *)\n    Long_name : TIME;\n    X         : INT;\nEND_VAR",
    );
  });

  it("appends a VAR block when there is none, or to an empty text", () => {
    expect(addDeclaration("VAR_INPUT\n  Go : BOOL;\nEND_VAR\n\n", { name: "X", type: "INT" })).toBe(
      "VAR_INPUT\n    Go : BOOL;\nEND_VAR\nVAR\n    X : INT;\nEND_VAR",
    );
    expect(addDeclaration("", { name: "X", type: "INT" })).toBe("VAR\n    X : INT;\nEND_VAR");
  });

  it("fills an empty VAR block and ignores VAR_GLOBAL or a VAR without END_VAR", () => {
    expect(addDeclaration("VAR\nEND_VAR", { name: "A", type: "BOOL" })).toBe("VAR\n    A : BOOL;\nEND_VAR");
    expect(addDeclaration("VAR_GLOBAL\nEND_VAR", { name: "A", type: "BOOL" })).toBe(
      "VAR_GLOBAL\nEND_VAR\nVAR\n    A : BOOL;\nEND_VAR",
    );
    expect(addDeclaration("VAR\n  B : INT;", { name: "A", type: "BOOL" })).toBe(
      "VAR\n  B : INT;\nVAR\n    A : BOOL;\nEND_VAR",
    );
  });

  it("puts a variable into a block of the chosen class, with its initial value and comment (issue 22)", () => {
    const text = "VAR_INPUT\n    Go : BOOL;\nEND_VAR\nVAR\n    T1 : TON;\nEND_VAR";
    expect(
      addDeclaration(text, { name: "Speed", type: "INT", varClass: "VAR_INPUT", initial: "5", comment: "rpm" }),
    ).toBe("VAR_INPUT\n    Go    : BOOL;\n    Speed : INT := 5;    (* rpm *)\nEND_VAR\nVAR\n    T1 : TON;\nEND_VAR");
    expect(addDeclaration(text, { name: "Done", type: "BOOL", varClass: "VAR_OUTPUT" })).toBe(
      `${text}\nVAR_OUTPUT\n    Done : BOOL;\nEND_VAR`,
    );
    expect(
      addDeclaration("VAR CONSTANT\nEND_VAR", { name: "N", type: "INT", varClass: "VAR CONSTANT", initial: "3" }),
    ).toBe("VAR CONSTANT\n    N : INT := 3;\nEND_VAR");
  });

  it("adds a global to the global variable list's VAR_GLOBAL block; a comment cannot end early", () => {
    expect(
      addDeclaration("VAR_GLOBAL\n    A : BOOL;\nEND_VAR", {
        name: "B",
        type: "WORD",
        varClass: "VAR_GLOBAL",
        comment: "x *) y",
      }),
    ).toBe("VAR_GLOBAL\n    A : BOOL;\n    B : WORD;    (* x * ) y *)\nEND_VAR");
  });
});
