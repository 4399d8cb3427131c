import { describe, expect, it } from "vitest";
import type { Project } from "../generated/api";
import { typeCopyName, withoutTypeIn, withTypeCopyIn } from "./types";
import { structMembers, typeLines, typeRows, withNewType, withoutType, withStructMembers, withTypeCopy } from "./types";

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

  it("lists no enumeration value with an explicit value and no initial value as a type; an enumeration with its base type first is one", () => {
    const text = [
      "TYPE",
      "    Mode : (Idle, Run := 5, Halt) := Idle;",
      "    Speed : INT (Slow := 1, Fast := 9);",
      "    Level : (Low, High) DWORD := High;",
      "END_TYPE",
    ].join("\n");
    expect(typeRows(text).map((r) => [r.name, r.kind])).toEqual([
      ["Mode", "enum"],
      ["Speed", "enum"],
      ["Level", "enum"],
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

describe("deleting and duplicating a type (issue 22 item 1)", () => {
  const text = [
    "TYPE",
    "    Point : STRUCT",
    "        x : INT; (* ; in a comment *)",
    "        y : INT;",
    "    END_STRUCT;",
    "    Mode : (Idle, Run) := Idle;",
    "END_TYPE",
    "",
    "TYPE",
    "    Speed : INT;",
    "END_TYPE",
    "",
  ].join("\n");

  it("removes a STRUCT from its name to the ';' after END_STRUCT, and the others stay as they were", () => {
    expect(withoutType(text, "point")).toBe(
      ["TYPE", "    Mode : (Idle, Run) := Idle;", "END_TYPE", "", "TYPE", "    Speed : INT;", "END_TYPE", ""].join(
        "\n",
      ),
    );
  });

  it("removes a TYPE block left empty", () => {
    expect(withoutType(text, "Speed")).toBe(text.split("\n").slice(0, 7).join("\n") + "\n");
    expect(withoutType(withoutType(withoutType(text, "Speed"), "Mode"), "Point")).toBe("");
    expect(withoutType(text, "Nothing")).toBe(text);
  });

  it("knows the lines of a declaration (its own name there is no use of it)", () => {
    expect(typeLines(text, "Point")).toEqual({ first: 2, last: 5 });
    expect(typeLines(text, "Speed")).toEqual({ first: 10, last: 10 });
    expect(typeLines(text, "Nothing")).toBeNull();
  });

  it("declares a copy right after the original, under the new name, with the same members", () => {
    const copied = withTypeCopy(text, "Point", "Point_copy")!;
    expect(copied.split("\n").slice(1, 9)).toEqual([
      "    Point : STRUCT",
      "        x : INT; (* ; in a comment *)",
      "        y : INT;",
      "    END_STRUCT;",
      "    Point_copy : STRUCT",
      "        x : INT; (* ; in a comment *)",
      "        y : INT;",
      "    END_STRUCT;",
    ]);
    expect(typeRows(copied).map((r) => [r.name, r.kind])).toEqual([
      ["Point", "struct"],
      ["Point_copy", "struct"],
      ["Mode", "enum"],
      ["Speed", "alias"],
    ]);
    expect(withTypeCopy(text, "Mode", "Mode2")!.split("\n")[6]).toBe("    Mode2 : (Idle, Run) := Idle;");
    expect(withTypeCopy(text, "Nothing", "X")).toBeNull();
  });
});

describe("a type's CODESYS pack_mode pragma goes and comes with it (issue 25 item 1)", () => {
  const text = [
    "{attribute 'pack_mode' := '1'}",
    "TYPE",
    "    Packed : STRUCT a : BYTE; b : DINT; END_STRUCT;",
    "    {attribute 'pack_mode' := '2'}",
    "    Half : STRUCT a : BYTE; b : DINT; END_STRUCT;",
    "    Plain : STRUCT a : BYTE; b : DINT; END_STRUCT;",
    "END_TYPE",
    "",
  ].join("\n");

  it("deletes the pragma above a type with it, so the next type is not packed instead", () => {
    expect(withoutType(text, "Packed").split("\n").slice(0, 4)).toEqual([
      "TYPE",
      "    {attribute 'pack_mode' := '2'}",
      "    Half : STRUCT a : BYTE; b : DINT; END_STRUCT;",
      "    Plain : STRUCT a : BYTE; b : DINT; END_STRUCT;",
    ]);
    expect(withoutType(text, "Half").split("\n").slice(2, 5)).toEqual([
      "    Packed : STRUCT a : BYTE; b : DINT; END_STRUCT;",
      "    Plain : STRUCT a : BYTE; b : DINT; END_STRUCT;",
      "END_TYPE",
    ]);
    expect(withoutType(withoutType(withoutType(text, "Half"), "Plain"), "Packed")).toBe("");
  });

  it("copies the pragma with the type, above the copy", () => {
    expect(withTypeCopy(text, "Half", "Half2")!.split("\n").slice(4, 8)).toEqual([
      "    Half : STRUCT a : BYTE; b : DINT; END_STRUCT;",
      "    {attribute 'pack_mode' := '2'}",
      "    Half2 : STRUCT a : BYTE; b : DINT; END_STRUCT;",
      "    Plain : STRUCT a : BYTE; b : DINT; END_STRUCT;",
    ]);
    expect(withTypeCopy(text, "Packed", "P2")!.split("\n").slice(2, 5)).toEqual([
      "    Packed : STRUCT a : BYTE; b : DINT; END_STRUCT;",
      "    {attribute 'pack_mode' := '1'}",
      "    P2 : STRUCT a : BYTE; b : DINT; END_STRUCT;",
    ]);
  });
});

describe("a type deleted or copied in the project (issue 22 item 1)", () => {
  const project: Project = {
    name: "p",
    types: "TYPE\n    Valve : (Shut, Open);\nEND_TYPE\n",
    pous: [{ name: "Valve_copy", kind: "program", language: "st", body: "" }],
  };

  it("names the copy after the types and POUs there are, and refuses a taken name", () => {
    expect(typeCopyName(project, "Valve")).toBe("Valve_copy2");
    expect(withTypeCopyIn(project, "Valve", "valve_COPY")).toBe("There is already a type or POU called Valve_copy.");
    expect(withTypeCopyIn(project, "Valve", "VALVE")).toBe("There is already a type or POU called Valve.");
    expect(withTypeCopyIn(project, "Nothing", "X")).toBe("There is no type Nothing.");
    expect((withTypeCopyIn(project, "Valve", "Flap") as Project).types).toBe(
      "TYPE\n    Valve : (Shut, Open);\n    Flap : (Shut, Open);\nEND_TYPE\n",
    );
  });

  it("deletes the type's declaration and its emptied TYPE block", () => {
    expect(withoutTypeIn(project, "Valve")).toEqual({ ...project, types: "" });
  });
});
