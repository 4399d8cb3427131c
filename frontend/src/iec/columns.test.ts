// The declarations the declare prompt and the table write are aligned like the ST export aligns them
// (tests/fixtures/declaration_columns.json, read by the backend's tests too).
import { readFileSync } from "node:fs";
import { resolve } from "node:path";
import { describe, expect, it } from "vitest";
import { alignDeclarations } from "./declarations";

const fixture = JSON.parse(
  readFileSync(resolve(__dirname, "../../../tests/fixtures/declaration_columns.json"), "utf8"),
) as { cases: { input: string; expected: string }[] };

describe("alignDeclarations", () => {
  it.each(fixture.cases)("aligns like the ST export: $expected", ({ input, expected }) => {
    expect(alignDeclarations(input)).toBe(expected);
  });

  it("keeps lines that are not one whole declaration as they are", () => {
    const text = "VAR\n  a : INT;\n  (* a note between *)\n  bb : BOOL;\nEND_VAR\nVAR_INPUT x : INT; END_VAR";
    expect(alignDeclarations(text)).toBe(
      "VAR\n    a  : INT;\n  (* a note between *)\n    bb : BOOL;\nEND_VAR\nVAR_INPUT x : INT; END_VAR",
    );
    expect(alignDeclarations("VAR\n  b : INT;\nVAR\n  a : BOOL;\nEND_VAR")).toBe(
      "VAR\n  b : INT;\nVAR\n    a : BOOL;\nEND_VAR",
    );
  });
});
