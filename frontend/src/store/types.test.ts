import { describe, expect, it } from "vitest";
import { structMembers, typeRows, withNewType, withStructMembers } from "./types";

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

describe("a STRUCT's members as a table (issue 22 item 2)", () => {
  const text = [
    "TYPE",
    "    Mode : (Idle, Run);",
    "    Point : STRUCT",
    "        x : INT := 1;  (* across *)",
    "        y : INT;",
    "    END_STRUCT;",
    "END_TYPE",
  ].join("\n");
  const row = (name: string, type: string, initial = "", comment = "") => ({
    name,
    varClass: "VAR",
    type,
    initial,
    address: "",
    comment,
  });

  it("reads the members with their types, initial values and comments; no STRUCT, no table", () => {
    expect(structMembers(text, "point")).toEqual([
      { ...row("x", "INT", "1", "across"), line: undefined },
      { ...row("y", "INT"), line: undefined },
    ]);
    expect(structMembers(text, "Mode")).toBeNull();
    expect(structMembers(text, "Missing")).toBeNull();
  });

  it("writes edited members back in columns, leaving the other types as they were", () => {
    const edited = withStructMembers(text, "Point", [row("x", "REAL", "1.5", "across"), row("Label", "STRING")]);
    expect(edited).toBe(
      [
        "TYPE",
        "    Mode : (Idle, Run);",
        "    Point : STRUCT",
        "        x     : REAL := 1.5;    (* across *)",
        "        Label : STRING;",
        "    END_STRUCT;",
        "END_TYPE",
      ].join("\n"),
    );
    expect(structMembers(edited, "Point")?.map((m) => m.name)).toEqual(["x", "Label"]);
    expect(withStructMembers(text, "Point", [])).toContain("Point : STRUCT\n    END_STRUCT;");
  });
});
