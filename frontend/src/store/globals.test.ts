import { describe, expect, it } from "vitest";
import { globalLine, withoutGlobalIn } from "./globals";

const GLOBALS =
  "VAR_GLOBAL\n    Start : BOOL;\n    Level : INT := 5;    (* tank *)\nEND_VAR\nVAR_GLOBAL CONSTANT\n    Max : INT := 10;\nEND_VAR";

describe("the global variables as the table has them (issue 22 item 1)", () => {
  it("finds the line a global is declared on, in any case", () => {
    expect(globalLine(GLOBALS, "level")).toBe(3);
    expect(globalLine(GLOBALS, "MAX")).toBe(6);
    expect(globalLine(GLOBALS, "Missing")).toBeNull();
    expect(globalLine("VAR_GLOBAL (* a *) x : BOOL; END_VAR y", "x")).toBeNull(); // no table for this text
  });

  it("deletes one row and keeps the others with their blocks, qualifiers, values and comments", () => {
    const project = { name: "p", globals: GLOBALS };
    expect(withoutGlobalIn(project, "start").globals).toBe(
      "VAR_GLOBAL\n    Level : INT := 5;    (* tank *)\nEND_VAR\nVAR_GLOBAL CONSTANT\n    Max : INT := 10;\nEND_VAR",
    );
    // the last one of a block takes its block along
    expect(withoutGlobalIn(project, "Max").globals).toBe(
      "VAR_GLOBAL\n    Start : BOOL;\n    Level : INT := 5;    (* tank *)\nEND_VAR",
    );
    expect(withoutGlobalIn({ name: "p", globals: "VAR_GLOBAL\n    x : BOOL;\nEND_VAR" }, "x").globals).toBe("");
  });
});
