import { describe, expect, it } from "vitest";
import { declareProblem, isGlobalClass } from "./newVariable";

describe("declareProblem", () => {
  it("accepts an identifier with a type", () => {
    expect(declareProblem({ name: "Pump_1", type: "BOOL" })).toBeNull();
    expect(declareProblem({ name: "N", type: "INT", varClass: "VAR CONSTANT", initial: "3" })).toBeNull();
  });

  it("says what is wrong in the user's words", () => {
    expect(declareProblem({ name: "1st", type: "BOOL" })).toBe(
      "1st is not an IEC identifier (letters, digits and _, not starting with a digit).",
    );
    expect(declareProblem({ name: "", type: "BOOL" })).toMatch(/^An empty name is not/);
    expect(declareProblem({ name: "Speed", type: "  " })).toBe("Speed needs a type, e.g. BOOL, INT or TIME.");
    expect(declareProblem({ name: "N", type: "INT", varClass: "VAR_GLOBAL CONSTANT" })).toBe(
      "A constant needs an initial value: N : INT := ...",
    );
  });
});

describe("isGlobalClass", () => {
  it("sends VAR_GLOBAL and its qualified forms to the global variable list only", () => {
    expect(["VAR_GLOBAL", "VAR_GLOBAL RETAIN", "var_global constant"].map(isGlobalClass)).toEqual([true, true, true]);
    expect(["VAR", "VAR_INPUT", "VAR_EXTERNAL", undefined].map(isGlobalClass)).toEqual([false, false, false, false]);
  });
});
