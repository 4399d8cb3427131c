import { describe, expect, it } from "vitest";
import { typeRows, withNewType } from "./types";

describe("the Types editor's list", () => {
  it("lists every top-level type with its kind and line, not STRUCT members or comments", () => {
    const text = [
      "TYPE",
      "    Point : STRUCT",
      "        x : INT;",
      "        y : INT;",
      "    END_STRUCT;",
      "    (* Old : INT; *)",
      "    Mode : (Idle, Run);",
      "END_TYPE",
      "TYPE Row : ARRAY[1..3] OF REAL; Percent : INT (0..100); Speed : REAL; END_TYPE",
    ].join("\n");
    expect(typeRows(text)).toEqual([
      { name: "Point", kind: "struct", line: 2 },
      { name: "Mode", kind: "enum", line: 7 },
      { name: "Row", kind: "array", line: 9 },
      { name: "Percent", kind: "subrange", line: 9 },
      { name: "Speed", kind: "alias", line: 9 },
    ]);
  });

  it("adds a type as a block of its own that lists again", () => {
    const text = withNewType(withNewType("", "Cell", "struct"), "State", "enum");
    expect(typeRows(text).map((r) => [r.name, r.kind])).toEqual([
      ["Cell", "struct"],
      ["State", "enum"],
    ]);
  });
});
