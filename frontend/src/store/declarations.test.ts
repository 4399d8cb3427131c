import { describe, expect, it } from "vitest";
import { addDeclaration } from "./declarations";

describe("addDeclaration", () => {
  it("adds to the first plain VAR block and aligns the declarations in columns (issue 28)", () => {
    const text = "VAR_INPUT\n  Go : BOOL;\nEND_VAR\nVAR\n\tT1 : TON;  (* timer *)\nEND_VAR";
    expect(addDeclaration(text, "Pump", "BOOL")).toBe(
      "VAR_INPUT\n    Go : BOOL;\nEND_VAR\nVAR\n    T1   : TON;     (* timer *)\n    Pump : BOOL;\nEND_VAR",
    );
  });

  it("leaves lines it cannot align as they are", () => {
    const text = "VAR\n  a, b : INT; c : BOOL;\n  (* note *)\n  Long_name : TIME;\nEND_VAR";
    expect(addDeclaration(text, "X", "INT")).toBe(
      "VAR\n  a, b : INT; c : BOOL;\n  (* note *)\n    Long_name : TIME;\n    X         : INT;\nEND_VAR",
    );
  });

  it("appends a VAR block when there is none, or to an empty text", () => {
    expect(addDeclaration("VAR_INPUT\n  Go : BOOL;\nEND_VAR\n\n", "X", "INT")).toBe(
      "VAR_INPUT\n    Go : BOOL;\nEND_VAR\nVAR\n    X : INT;\nEND_VAR",
    );
    expect(addDeclaration("", "X", "INT")).toBe("VAR\n    X : INT;\nEND_VAR");
  });

  it("fills an empty VAR block and ignores VAR_GLOBAL or a VAR without END_VAR", () => {
    expect(addDeclaration("VAR\nEND_VAR", "A", "BOOL")).toBe("VAR\n    A : BOOL;\nEND_VAR");
    expect(addDeclaration("VAR_GLOBAL\nEND_VAR", "A", "BOOL")).toBe("VAR_GLOBAL\nEND_VAR\nVAR\n    A : BOOL;\nEND_VAR");
    expect(addDeclaration("VAR\n  B : INT;", "A", "BOOL")).toBe("VAR\n  B : INT;\nVAR\n    A : BOOL;\nEND_VAR");
  });
});
