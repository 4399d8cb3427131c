// Completion after qualified names (issue 25): a program's variables (`Prog.x`), an enumeration's values
// (CODESYS `Color.Red`, IEC `Color#Red`), `THIS^.` / `SUPER^.`, an FB with EXTENDS, `r^.` of a reference, an
// interface variable.
// What is offered is what the checker accepts (backend/ladderlab/st/body.py `_member`, `_fb_member`,
// `_qualified_enum_value`, `_typed_literal`).
import { CompletionContext } from "@codemirror/autocomplete";
import { EditorState } from "@codemirror/state";
import { describe, expect, it } from "vitest";
import type { LibraryEntry, Pou } from "../generated/api";
import { memberCompletions, stCompletionSource, stCompletions } from "./completion";
import { membersAfter, structTypes, type Scope } from "./members";
import { interfaceTypes } from "./interfaces";
import { enumTypes, projectScope, qualifiers, withSelf } from "./qualifiers";
import { chartSymbols, withInherited, workingLibrary } from "./scope";
import { symbol } from "../test/symbols";

const TYPES = `TYPE
    Color : (Red, Green := 5, Blue); (* a comment (x, y) *)
    Level : (Low, High) INT := Low;
    Speed : INT (Slow := 1, Fast := 9); (* IEC's base type first *)
    Point : STRUCT x, y : INT; mode : (Fast, Slow); END_STRUCT;
    Small : INT (0..10);
END_TYPE`;

const pou = (name: string, kind: Pou["kind"], declarations: string, more: Partial<Pou> = {}): Pou => ({
  name,
  kind,
  language: "st",
  declarations,
  body: "",
  ...more,
});
const OTHER = pou(
  "Other",
  "program",
  `VAR_INPUT k : INT; END_VAR
VAR_OUTPUT done : BOOL; at : Point; END_VAR
VAR_IN_OUT io : INT; END_VAR
VAR hidden : INT; END_VAR
VAR_TEMP t : INT; END_VAR`,
  { methods: [{ name: "Reset" }, { name: "Log", access: "PRIVATE", declarations: "VAR_INPUT m : INT; END_VAR" }] },
);
const BASE = pou(
  "Base",
  "function_block",
  "VAR_INPUT bi : INT; END_VAR\nVAR_OUTPUT bo : INT; END_VAR\nVAR bv : INT; END_VAR",
  {
    methods: [
      { name: "Describe", return_type: "INT" },
      { name: "Check", access: "PROTECTED" },
      { name: "Secret", access: "PRIVATE" },
    ],
  },
);
const DER = pou("Der", "function_block", "VAR_INPUT di : INT; END_VAR\nVAR dv : INT; END_VAR", {
  extends: "Base",
  methods: [{ name: "Grow" }, { name: "Describe", return_type: "INT" }],
});
const POUS = [OTHER, BASE, DER, pou("Twice", "function", "VAR_INPUT a : INT; END_VAR", { return_type: "INT" })];

const method = (name: string): LibraryEntry => ({
  name,
  kind: "function",
  source: "user",
  comment: null,
  extensible: false,
  inputs: [],
  in_outs: [],
  outputs: [],
  return_type: null,
});
const SAVED: LibraryEntry[] = [
  { ...method("Base"), kind: "function_block", methods: [method("Describe")] },
  { ...method("Der"), kind: "function_block", methods: [method("Grow"), method("Describe")] },
  method("Other.Reset"),
];

const scopeIn = (self: Pou | null, symbols = [symbol("p", "Point")]): Scope => {
  const project = qualifiers(POUS, TYPES);
  const scope = { symbols, library: workingLibrary(SAVED, POUS), structs: structTypes(TYPES) };
  return self
    ? { ...withInherited(scope, self, POUS), qualifiers: withSelf(project, self, POUS) }
    : { ...scope, qualifiers: project };
};
const completer = (scope: Scope) => {
  const source = stCompletionSource(() => ({
    options: stCompletions([...scope.symbols], [...scope.library], scope),
    members: (chain, separator) => memberCompletions(chain, scope, separator),
  }));
  return (doc: string) => source(new CompletionContext(EditorState.create({ doc }), doc.length, false));
};
const labels = (scope: Scope, doc: string) => completer(scope)(doc)?.options.map((o) => o.label) ?? null;

describe("enumeration types from the TYPE text", () => {
  it("reads each enumeration's values in order, with or without values and a base type; not a STRUCT field's", () => {
    expect([...enumTypes(TYPES)].map(([name, values]) => [name, values.map((v) => `${v.name}:${v.type}`)])).toEqual([
      ["COLOR", ["Red:Color", "Green:Color", "Blue:Color"]],
      ["LEVEL", ["Low:Level", "High:Level"]],
      ["SPEED", ["Slow:Speed", "Fast:Speed"]],
    ]);
  });
});

describe("after a program's name (issue 25: Prog.x from another POU)", () => {
  const at = completer(scopeIn(null));

  it("offers its inputs and outputs, then its methods; not its in-outs, internal or temporary variables", () => {
    // The checker: `Other.io` is ST-NOT-ACCESSIBLE (an in-out), `Other.hidden` / `Other.t` are internal.
    const result = at("x := Other.");
    expect(result?.from).toBe(11);
    expect(result?.options.map((o) => [o.label, o.type, o.detail, o.info])).toEqual([
      ["k", "property", "INT", "VAR_INPUT of Other"],
      ["done", "property", "BOOL", "VAR_OUTPUT of Other"],
      ["at", "property", "Point", "VAR_OUTPUT of Other"],
      ["Reset", "method", "()", "METHOD of Other"],
    ]);
  });

  it("follows a program's output down its type, and completes the word after the dot", () => {
    expect(labels(scopeIn(null), "Other.at.")).toEqual(["x", "y", "mode"]);
    expect(completer(scopeIn(null))("IF other.DO")?.from).toBe(9);
    expect(labels(scopeIn(null), "Other.hidden.")).toBeNull();
  });

  it("offers a plant's inputs and outputs, not its properties and methods (ST-PLANT)", () => {
    const plant = pou("Tank", "plant", "VAR_INPUT i : INT; END_VAR\nVAR_OUTPUT level : INT; END_VAR", {
      properties: [{ name: "Full", type: "BOOL", get: { declarations: "", body: "" } }],
    });
    const scope = { ...scopeIn(null), qualifiers: qualifiers([plant], ""), library: [method("Tank.Drain")] };
    expect(completer(scope)("x := Tank.")?.options.map((o) => [o.label, o.info])).toEqual([
      ["i", "VAR_INPUT of Tank"],
      ["level", "VAR_OUTPUT of Tank"],
    ]);
  });

  it("is hidden by a variable of its name, as in the checker", () => {
    expect(labels(scopeIn(null, [symbol("Other", "INT")]), "Other.")).toBeNull();
  });
});

describe("the names that qualify (issue 25: Prog and Color are words to complete too)", () => {
  it("offers the programs and enumeration types as words after the variables, but those a variable hides", () => {
    const words = (scope: Scope) =>
      completer(scope)("x := C")
        ?.options.filter((o) => o.type === "namespace" || (o.type === "type" && o.detail === "enumeration"))
        .map((o) => [o.label, o.type, o.detail, o.info]);
    expect(words(scopeIn(null))).toEqual([
      ["Color", "type", "enumeration", "(Red, Green, Blue)"],
      ["Level", "type", "enumeration", "(Low, High)"],
      ["Speed", "type", "enumeration", "(Slow, Fast)"],
      ["Other", "namespace", "PROGRAM", undefined],
    ]);
    expect(words(scopeIn(null, [symbol("other", "INT")]))?.map((w) => w[0])).toEqual(["Color", "Level", "Speed"]);
  });
});

describe("after an enumeration type's name (issue 25: CODESYS Color.Red, IEC Color#Red)", () => {
  it("offers its values after `Color.` and after `Color#`", () => {
    const at = completer(scopeIn(null));
    for (const doc of ["c := Color.", "c := color#"]) {
      const result = at(doc);
      expect(result?.from).toBe(11);
      expect(result?.options.map((o) => [o.label, o.type, o.detail, o.info])).toEqual([
        ["Red", "enum", "Color", "value of Color"],
        ["Green", "enum", "Color", "value of Color"],
        ["Blue", "enum", "Color", "value of Color"],
      ]);
    }
    expect(at("CASE c OF Level#H")?.options.map((o) => o.label)).toEqual(["Low", "High"]);
  });

  it("offers nothing after a typed literal's elementary type, a based number, or a value", () => {
    const at = completer(scopeIn(null));
    expect(at("t := T#")).toBeNull();
    expect(at("i := INT#")).toBeNull();
    expect(at("w := 16#")).toBeNull();
    expect(at("c := Color.Red.")).toBeNull();
    expect(at("p := Point#")).toBeNull(); // a STRUCT has no typed literal
  });

  it("is hidden by a variable or a program of its name after the dot; `#` still names the type", () => {
    const shadowed = scopeIn(null, [symbol("Color", "Point")]);
    expect(labels(shadowed, "Color.")).toEqual(["x", "y", "mode"]);
    expect(labels(shadowed, "Color#")).toEqual(["Red", "Green", "Blue"]);
    const program = qualifiers([pou("Color", "program", "VAR_OUTPUT q : BOOL; END_VAR")], TYPES);
    expect(membersAfter(["Color"], { ...scopeIn(null), qualifiers: program })?.map((m) => m.name)).toEqual(["q"]);
  });
});

describe("THIS^. and SUPER^. in a function block (issue 25)", () => {
  it("offers all the instance's variables (inherited ones too) and its methods after THIS^.", () => {
    // the methods of the working copy: its own (PRIVATE ones too), the inherited but PRIVATE (check_access)
    const result = completer(scopeIn(DER))("THIS^.");
    expect(result?.options.map((o) => [o.label, o.detail, o.info])).toEqual([
      ["bi", "INT", "VAR_INPUT of THIS^"],
      ["bo", "INT", "VAR_OUTPUT of THIS^"],
      ["bv", "INT", "VAR of THIS^"],
      ["di", "INT", "VAR_INPUT of THIS^"],
      ["dv", "INT", "VAR of THIS^"],
      ["Grow", "()", "METHOD of THIS^"],
      ["Describe", "() : INT", "METHOD of THIS^"],
      ["Check", "()", "METHOD of THIS^"],
    ]);
    expect(labels(scopeIn(BASE), "THIS^.")).toEqual(["bi", "bo", "bv", "Describe", "Check", "Secret"]);
  });

  it("offers the base's variables and methods after SUPER^., and neither outside a function block or program", () => {
    expect(labels(scopeIn(DER), "x := SUPER^.")).toEqual(["bi", "bo", "bv", "Describe", "Check"]);
    expect(labels(scopeIn(BASE), "SUPER^.")).toBeNull(); // Base extends nothing
    expect(labels(scopeIn(POUS[3]!), "THIS^.")).toBeNull(); // a function
    // the checker: `THIS^.io` is ST-NOT-ACCESSIBLE (an in-out), `THIS^.hidden` and `THIS^.t` are accepted
    expect(labels(scopeIn(OTHER), "THIS^.")).toEqual(["k", "done", "at", "hidden", "t", "Reset", "Log"]);
    expect(completer(scopeIn(OTHER))("THIS^.")?.options.at(-1)?.apply).toBe("Log(m := )");
  });
});

describe("an instance of a function block with EXTENDS (issue 25)", () => {
  it("offers the base's inputs and outputs before its own, and the methods it inherits", () => {
    const scope = scopeIn(null, [symbol("d", "Der")]);
    expect(labels(scope, "d.")).toEqual(["bi", "di", "bo", "Grow", "Describe"]);
    expect(workingLibrary([], POUS).map((e) => [e.name, e.inputs.map((p) => p.name)])).toEqual([
      ["Base", ["bi"]],
      ["Der", ["bi", "di"]],
    ]);
  });
});

describe("through a reference (issue 25: r^. of REF_TO a STRUCT)", () => {
  const scope = scopeIn(null, [
    symbol("r", "REF_TO Point"),
    symbol("pp", "POINTER TO Point"),
    symbol("rr", "REFERENCE TO Point"),
    symbol("rd", "REF_TO Der"),
  ]);

  it("offers the target's members after `r^.` and `p^.`, and after a REFERENCE TO's own dot (CODESYS)", () => {
    expect(labels(scope, "x := r^.")).toEqual(["x", "y", "mode"]);
    expect(labels(scope, "x := pp^.")).toEqual(["x", "y", "mode"]);
    expect(labels(scope, "x := rr.")).toEqual(["x", "y", "mode"]);
    expect(labels(scope, "rr^.")).toEqual(["x", "y", "mode"]);
    expect(labels(scope, "rd^.")).toEqual(["bi", "di", "bo", "Grow", "Describe"]);
  });

  it("offers nothing after the dot of a REF_TO not dereferenced", () => {
    expect(labels(scope, "x := r.")).toBeNull();
  });
});

describe("an interface variable (issue 25: itf. offers the interface's properties and methods)", () => {
  const types = `TYPE
    Point : STRUCT x : INT; END_STRUCT;
END_TYPE
INTERFACE ILevel
PROPERTY Level : INT
GET
END_GET
SET
END_SET
END_PROPERTY
METHOD Fill : BOOL
VAR_INPUT amount : INT; END_VAR
VAR_OUTPUT spilled : INT; END_VAR
END_METHOD
END_INTERFACE
INTERFACE ILimited EXTENDS ILevel (* a comment: METHOD Nope *)
METHOD Room : INT
END_METHOD
END_INTERFACE`;

  it("reads each interface with what it extends", () => {
    const found = interfaceTypes(types);
    expect(
      [...found].map(([key, i]) => [key, i.properties.map((p) => `${p.name}:${p.type}`), i.methods.map((m) => m.name)]),
    ).toEqual([
      ["ILEVEL", ["Level:INT"], ["Fill"]],
      ["ILIMITED", ["Level:INT"], ["Room", "Fill"]],
    ]);
    expect(found.get("ILEVEL")?.methods[0]).toMatchObject({
      inputs: [{ name: "amount", type: "INT" }],
      outputs: [{ name: "spilled", type: "INT" }],
      return_type: "BOOL",
    });
  });

  it("offers the properties, then the methods with their formal call", () => {
    const scope: Scope = {
      symbols: [symbol("itf", "ILimited"), symbol("r", "REFERENCE TO ILevel")],
      library: [],
      ...projectScope([], types),
    };
    expect(completer(scope)("itf.")?.options.map((o) => [o.label, o.type, o.detail, o.apply, o.info])).toEqual([
      ["Level", "property", "INT", undefined, "PROPERTY of ILimited"],
      ["Room", "method", "() : INT", "Room()", "METHOD of ILimited"],
      ["Fill", "method", "(amount: INT) : BOOL", "Fill(amount := , spilled => )", "METHOD of ILimited"],
    ]);
    expect(labels(scope, "x := itf.Level.")).toBeNull();
  });
});

describe("PROPERTYs after an instance, a program, THIS^. and SUPER^. (issue 25)", () => {
  const property = (name: string, access: "PUBLIC" | "PRIVATE" | "PROTECTED") => ({
    name,
    type: "INT",
    access,
    get: { declarations: "", body: "" },
  });
  const tank = pou("Tank", "function_block", "VAR_INPUT fill : INT; END_VAR", {
    properties: [property("Level", "PUBLIC"), property("Secret", "PRIVATE"), property("Guarded", "PROTECTED")],
  });
  const big = pou("BigTank", "function_block", "VAR extra : INT; END_VAR", {
    extends: "Tank",
    properties: [property("Room", "PRIVATE")],
  });
  const plant = pou("Plant", "program", "VAR_OUTPUT q : BOOL; END_VAR", {
    properties: [property("Mode", "PUBLIC"), property("Hidden", "PRIVATE")],
  });
  const pous = [tank, big, plant];
  const scopeOf = (self: Pou | null): Scope => {
    const project = projectScope(pous, "");
    const scope = { symbols: [symbol("t", "BigTank")], library: workingLibrary([], pous), ...project };
    return self ? { ...scope, qualifiers: withSelf(project.qualifiers, self, pous) } : scope;
  };

  it("offers only the PUBLIC ones from another POU (the checker's check_access), inherited ones too", () => {
    expect(labels(scopeOf(null), "t.")).toEqual(["fill", "Level"]);
    expect(labels(scopeOf(null), "Plant.")).toEqual(["q", "Mode"]);
    expect(completer(scopeOf(null))("t.")?.options.at(-1)?.info).toBe("PROPERTY of BigTank");
  });

  it("offers own PRIVATE and inherited PROTECTED ones after THIS^., the base's non-PRIVATE after SUPER^.", () => {
    expect(labels(scopeOf(big), "THIS^.")).toEqual(["fill", "extra", "Room", "Level", "Guarded"]);
    expect(labels(scopeOf(big), "SUPER^.")).toEqual(["fill", "Level", "Guarded"]);
    expect(labels(scopeOf(tank), "THIS^.")).toEqual(["fill", "Level", "Secret", "Guarded"]);
  });
});

describe("through an array element (issue 25: a[i]. of an ARRAY OF a STRUCT)", () => {
  const scope = scopeIn(null, [
    symbol("a", "ARRAY [1..3] OF Point"),
    symbol("m", "ARRAY [1..2, 0..K] OF Point"),
    symbol("refs", "ARRAY [0..1] OF REF_TO Point"),
    symbol("nested", "ARRAY [0..1] OF ARRAY [0..1] OF Der"),
    symbol("i", "INT"),
  ]);

  it("offers the element's members after each index, as many as the array has dimensions in one `[...]`", () => {
    expect(labels(scope, "x := a[1].")).toEqual(["x", "y", "mode"]);
    expect(labels(scope, "x := a[i].")).toEqual(["x", "y", "mode"]);
    expect(labels(scope, "x := m[1, i].")).toEqual(["x", "y", "mode"]);
    expect(labels(scope, "x := refs[0]^.")).toEqual(["x", "y", "mode"]);
    expect(labels(scope, "nested[0][1].")).toEqual(["bi", "di", "bo", "Grow", "Describe"]);
  });

  it("offers nothing after the array itself or one index too many", () => {
    expect(labels(scope, "x := a.")).toBeNull();
    expect(labels(scope, "x := a[1][2].")).toBeNull();
  });
});

describe("an SFC's steps and actions (issue 25; SFC-06: Wash.Idle.X, counter.Start.X, Fill.Q)", () => {
  const stdFb = (name: string, input: [string, string], output: [string, string]): LibraryEntry => ({
    ...method(name),
    kind: "function_block",
    source: "standard",
    inputs: [{ name: input[0], type: input[1] }],
    outputs: [{ name: output[0], type: output[1] }],
  });
  const library = [
    stdFb("SFC_STEP", ["X", "BOOL"], ["T", "TIME"]),
    stdFb("ACTION_CONTROL", ["Q", "BOOL"], ["A", "BOOL"]),
  ];
  const chart = (names: string[]) => ({
    elements: names.flatMap((name, i) => [
      { type: "step" as const, id: `s${i}`, name },
      { type: "transition" as const, id: `t${i}`, condition: "TRUE" },
    ]),
  });
  const wash: Pou = {
    ...pou("Wash", "program", "VAR_OUTPUT q : BOOL; END_VAR\nVAR n : INT; END_VAR"),
    language: "sfc",
    body: { chart: chart(["Idle", "Run"]), actions: [{ name: "Fill", language: "st", body: "n := n + 1;" }] },
  };
  const seq: Pou = {
    ...pou("Seq", "function_block", "VAR_OUTPUT done : BOOL; END_VAR"),
    language: "sfc",
    body: { chart: chart(["Start", "Stop"]) },
  };
  const scope: Scope = {
    symbols: [symbol("s", "Seq"), ...chartSymbols(wash)],
    library: [...library, ...workingLibrary([], [wash, seq])],
    ...projectScope([wash, seq], ""),
  };

  it("reads the working chart's steps and actions as variables of the SFC POU", () => {
    expect(chartSymbols(wash).map((s) => `${s.name}:${s.type}`)).toEqual([
      "Idle:SFC_STEP",
      "Run:SFC_STEP",
      "Fill:ACTION_CONTROL",
    ]);
    expect(chartSymbols(OTHER)).toEqual([]);
    expect(labels(scope, "IF Idle.")).toEqual(["X", "T"]);
    expect(labels(scope, "IF Fill.")).toEqual(["Q", "A"]);
  });

  it("offers them after a program's name and an FB instance, then their flags", () => {
    const at = completer(scope);
    expect(at("b := Wash.")?.options.map((o) => [o.label, o.info])).toEqual([
      ["q", "VAR_OUTPUT of Wash"],
      ["Idle", "STEP of Wash"],
      ["Run", "STEP of Wash"],
      ["Fill", "ACTION of Wash"],
    ]);
    expect(labels(scope, "b := Wash.Idle.")).toEqual(["X", "T"]);
    expect(labels(scope, "b := s.")).toEqual(["done", "Start", "Stop"]);
    expect(labels(scope, "b := s.Start.")).toEqual(["X", "T"]);
  });
});

describe("a named global variable list's variables after its name (GVL_IO.x, issue 25)", () => {
  const gvls = [
    { name: "GVL_IO", qualified_only: true, text: "VAR_GLOBAL\n    bStart : BOOL;\n    tOn : TON;\nEND_VAR" },
  ];
  const ton: LibraryEntry = {
    ...method("TON"),
    kind: "function_block",
    inputs: [
      { name: "IN", type: "BOOL" },
      { name: "PT", type: "TIME" },
    ],
    outputs: [
      { name: "Q", type: "BOOL" },
      { name: "ET", type: "TIME" },
    ],
  };

  it("offers the list's variables, and the pins of an instance in it", () => {
    const scope: Scope = { symbols: [], library: [ton], ...projectScope([], "", gvls) };
    expect(labels(scope, "x := GVL_IO.")).toEqual(["bStart", "tOn"]);
    expect(labels(scope, "x := GVL_IO.tOn.")).toEqual(["IN", "PT", "Q", "ET"]);
  });

  it("lets a variable of the list's name hide it, as the checker does", () => {
    const scope: Scope = { symbols: [symbol("GVL_IO", "TON")], library: [ton], ...projectScope([], "", gvls) };
    expect(labels(scope, "x := GVL_IO.")).toEqual(["IN", "PT", "Q", "ET"]);
  });
});
