import { CompletionContext } from "@codemirror/autocomplete";
import { EditorState } from "@codemirror/state";
import { describe, expect, it } from "vitest";
import type { LibraryEntry, Pou } from "../generated/api";
import { memberCompletions, stCompletionSource, stCompletions } from "./completion";
import { membersOf, structTypes, typeOfChain, type Scope } from "./members";
import { qualifiers } from "./qualifiers";
import { declaredSymbols, stScope, workingLibrary } from "./scope";
import { symbol } from "../test/symbols";

const pin = (name: string, type: string) => ({ name, type });
const TON: LibraryEntry = {
  name: "TON",
  kind: "function_block",
  source: "standard",
  comment: "on delay",
  extensible: false,
  inputs: [pin("IN", "BOOL"), pin("PT", "TIME")],
  in_outs: [],
  outputs: [pin("Q", "BOOL"), pin("ET", "TIME")],
  return_type: null,
};
const COUNTER: LibraryEntry = {
  name: "Counter",
  kind: "function_block",
  source: "user",
  comment: null,
  extensible: false,
  inputs: [pin("Enable", "BOOL")],
  in_outs: [pin("Total", "DINT")],
  outputs: [pin("Count", "INT")],
  return_type: null,
};
const ABS: LibraryEntry = {
  name: "ABS",
  kind: "function",
  source: "standard",
  comment: null,
  extensible: false,
  inputs: [pin("IN", "ANY_NUM")],
  in_outs: [],
  outputs: [],
  return_type: "ANY_NUM",
};

const TYPES = `TYPE
    Point : STRUCT
        x, y : INT; (* coordinates *)
        label : STRING := 'origin';
        timer : TON;
    END_STRUCT;
    Mode : (Off, On);
    Line : STRUCT a : Point; b : Point; END_STRUCT;
END_TYPE`;

const scope: Scope = {
  symbols: [
    symbol("Start", "BOOL"),
    symbol("Delay", "TON"),
    symbol("C1", "Counter"),
    symbol("p", "Point"),
    symbol("ln", "Line"),
    symbol("Alarm", "BOOL", "VAR_GLOBAL"),
  ],
  library: [TON, COUNTER, ABS],
  structs: structTypes(TYPES),
};

describe("STRUCT types from the TYPE text", () => {
  it("reads every field with its type, skipping comments and initial values", () => {
    expect([...structTypes(TYPES)].map(([name, fields]) => [name, fields.map((f) => `${f.name}:${f.type}`)])).toEqual([
      ["POINT", ["x:INT", "y:INT", "label:STRING", "timer:TON"]],
      ["LINE", ["a:Point", "b:Point"]],
    ]);
  });
});

describe("member resolution", () => {
  it("gives FB pins (inputs, in-outs, outputs) and struct fields; nothing for elementary types", () => {
    expect(membersOf("ton", scope)?.map((m) => `${m.kind} ${m.name}`)).toEqual([
      "VAR_INPUT IN",
      "VAR_INPUT PT",
      "VAR_OUTPUT Q",
      "VAR_OUTPUT ET",
    ]);
    expect(membersOf("Counter", scope)?.map((m) => m.name)).toEqual(["Enable", "Total", "Count"]);
    expect(membersOf("INT", scope)).toBeNull();
    expect(membersOf("ABS", scope)).toBeNull();
  });

  it("gives an instance declared with FB_init arguments its FB's members", () => {
    expect(membersOf("Counter(nStart := 3)", scope)?.map((m) => m.name)).toEqual(["Enable", "Total", "Count"]);
    expect(membersOf("Counter (3, 'a')", scope)?.map((m) => m.name)).toEqual(["Enable", "Total", "Count"]);
    expect(membersOf("STRING(20)", scope)).toBeNull();
  });

  it("follows access chains through instances and structs, case-insensitively", () => {
    expect(typeOfChain(["delay", "q"], scope)).toBe("BOOL");
    expect(typeOfChain(["ln", "A", "timer", "ET"], scope)).toBe("TIME");
    expect(typeOfChain(["ln", "c"], scope)).toBeNull();
    expect(typeOfChain(["Start", "x"], scope)).toBeNull();
    expect(typeOfChain(["nobody"], scope)).toBeNull();
  });

  it("reads a global variable list's variable qualified, also one of a name several lists declare", () => {
    const listed = (name: string, type: string, gvl: string) => ({ ...symbol(name, type, "VAR_GLOBAL"), gvl });
    const lists: Scope = {
      ...scope,
      symbols: [
        listed("bStart", "BOOL", "GVL_IO"),
        listed("GVL_A.n", "INT", "GVL_A"),
        listed("GVL_B.n", "TON", "GVL_B"),
      ],
    };
    expect(typeOfChain(["gvl_io", "bStart"], lists)).toBe("BOOL");
    expect(typeOfChain(["GVL_A", "n"], lists)).toBe("INT");
    expect(typeOfChain(["GVL_B", "N", "Q"], lists)).toBe("BOOL");
    expect(typeOfChain(["GVL_A", "bStart"], lists)).toBeNull();
  });
});

describe("member autocomplete (issue 9: FB instance members, struct fields)", () => {
  const source = stCompletionSource(() => ({
    options: stCompletions([...scope.symbols], [...scope.library]),
    members: (chain, separator) => memberCompletions(chain, scope, separator),
  }));
  const at = (doc: string) => source(new CompletionContext(EditorState.create({ doc }), doc.length, false));

  it("offers the pins of a standard FB instance after `inst.`", () => {
    const result = at("x := Delay.");
    expect(result?.from).toBe(11);
    expect(result?.options.map((o) => [o.label, o.detail, o.info])).toEqual([
      ["IN", "BOOL", "VAR_INPUT of TON"],
      ["PT", "TIME", "VAR_INPUT of TON"],
      ["Q", "BOOL", "VAR_OUTPUT of TON"],
      ["ET", "TIME", "VAR_OUTPUT of TON"],
    ]);
  });

  it("offers a user FB's inputs and outputs and completes the word typed after the dot", () => {
    const result = at("IF C1.Co");
    expect(result?.from).toBe(6);
    // not the in-out Total: the checker refuses `C1.Total` (ST-NOT-ACCESSIBLE, it is the caller's during a call only)
    expect(result?.options.map((o) => o.label)).toEqual(["Enable", "Count"]);
  });

  it("offers struct fields, also down a chain", () => {
    expect(at("p.")?.options.map((o) => `${o.label}:${o.detail}`)).toEqual([
      "x:INT",
      "y:INT",
      "label:STRING",
      "timer:TON",
    ]);
    expect(at("ln.b.timer.")?.options.map((o) => o.label)).toEqual(["IN", "PT", "Q", "ET"]);
  });

  it("offers nothing after the dot of a name without members, and words elsewhere", () => {
    expect(at("Start.")).toBeNull();
    expect(at("x := 1.")).toBeNull();
    expect(
      at("x := Sta")
        ?.options.filter((o) => o.type !== "keyword" && o.type !== "type")
        .map((o) => o.label),
    ).toEqual(["Start", "Delay", "C1", "p", "ln", "Alarm", "ABS", "TON", "Counter"]);
  });
});

describe("the working copy's declarations (issue 9: completion before a save)", () => {
  it("reads declarations typed but not saved, and falls back to the saved table when they do not read as a table", () => {
    expect(
      declaredSymbols("VAR_INPUT\n    Enable : BOOL;\nEND_VAR\nVAR CONSTANT\n    Limit : INT := 5;\nEND_VAR"),
    ).toEqual([
      {
        name: "Enable",
        var_class: "VAR_INPUT",
        type: "BOOL",
        initial: null,
        address: null,
        comment: null,
        retain: false,
        constant: false,
      },
      {
        name: "Limit",
        var_class: "VAR",
        type: "INT",
        initial: "5",
        address: null,
        comment: null,
        retain: false,
        constant: true,
      },
    ]);
    const table = {
      pou: "Main",
      symbols: [symbol("Saved", "INT")],
      globals: [symbol("Alarm", "BOOL", "VAR_GLOBAL")],
      diagnostics: [],
    };
    expect(stScope(table, "VAR\n    c : Counter;\nEND_VAR", "", []).symbols.map((s) => s.name)).toEqual(["c", "Alarm"]);
    expect(stScope(table, "VAR\n    c : Counter;", "", []).symbols.map((s) => s.name)).toEqual(["Saved", "Alarm"]);
  });
});

describe("methods after `inst.` and `Prog.` (issue 25: CODESYS calls a program's method as Prog.M)", () => {
  const fn = (name: string, inputs: string[], outputs: string[], result: string | null): LibraryEntry => ({
    name,
    kind: "function",
    source: "user",
    comment: null,
    extensible: false,
    inputs: inputs.map((p) => pin(p, "INT")),
    in_outs: [],
    outputs: outputs.map((p) => pin(p, "INT")),
    return_type: result,
  });
  const library = [
    { ...COUNTER, methods: [fn("Reset", [], [], null)] },
    fn("Tally.Add", ["k"], ["twice"], "INT"),
    fn("Tally.Clear", [], [], null),
    fn("Tallyho.Other", [], [], null), // another program's, whose name only starts like it
    ABS,
  ];
  const tally: Pou = { name: "Tally", kind: "program", language: "st", declarations: "", body: "" };
  const methodScope: Scope = {
    symbols: [symbol("C1", "Counter")],
    library,
    structs: new Map(),
    qualifiers: qualifiers([tally], ""),
  };
  const source = stCompletionSource(() => ({
    options: stCompletions([...methodScope.symbols], library),
    members: (chain, separator) => memberCompletions(chain, methodScope, separator),
  }));
  const at = (doc: string) => source(new CompletionContext(EditorState.create({ doc }), doc.length, false));

  it("offers a program's methods after its name, each inserting its formal call", () => {
    const result = at("x := tally.");
    expect(result?.from).toBe(11);
    expect(result?.options.map((o) => [o.label, o.type, o.detail, o.apply, o.info])).toEqual([
      ["Add", "method", "(k: INT) : INT", "Add(k := , twice => )", "METHOD of Tally"],
      ["Clear", "method", "()", "Clear()", "METHOD of Tally"],
    ]);
  });

  it("offers an FB instance's methods after its pins", () => {
    expect(at("C1.")?.options.map((o) => [o.label, o.type])).toEqual([
      ["Enable", "property"],
      ["Count", "property"],
      ["Reset", "method"],
    ]);
  });

  it("keeps `Prog.M` out of the plain words, and offers nothing after a name with neither members nor methods", () => {
    expect(
      at("x := Ta")
        ?.options.filter((o) => o.type === "function")
        .map((o) => o.label),
    ).toEqual(["ABS"]);
    expect(at("x := Nobody.")).toBeNull();
    expect(at("x := Tally.Add.")).toBeNull();
  });
});

describe("the working copy's function blocks (issue 9: user FB members before a save)", () => {
  const fb = (name: string, declarations: string) => ({
    name,
    kind: "function_block" as const,
    language: "st" as const,
    declarations,
    body: "",
  });

  it("describes an unsaved or changed FB by its current declarations, keeping the saved entry when they do not read", () => {
    const library = workingLibrary(
      [TON, COUNTER],
      [
        fb("Counter", "VAR_INPUT\n    Enable : BOOL;\n    Step : INT;\nEND_VAR\nVAR_OUTPUT\n    Count : INT;\nEND_VAR"),
        fb("Valve", "VAR_IN_OUT\n    Pos : REAL;\nEND_VAR\nVAR\n    hidden : INT;\nEND_VAR"),
        fb("Broken", "VAR\n    x : INT;"),
        { name: "Main", kind: "program", language: "st", declarations: "VAR\n    c : Counter;\nEND_VAR", body: "" },
      ],
    );
    expect(
      library.map((e) => [e.name, e.source, [...e.inputs, ...e.in_outs, ...e.outputs].map((p) => p.name)]),
    ).toEqual([
      ["TON", "standard", ["IN", "PT", "Q", "ET"]],
      ["Counter", "user", ["Enable", "Step", "Count"]],
      ["Valve", "user", ["Pos"]],
    ]);
    const members = memberCompletions(["c"], { symbols: [symbol("c", "counter")], library, structs: new Map() });
    expect(members?.map((m) => m.label)).toEqual(["Enable", "Step", "Count"]);
    // the saved methods stay: the declarations do not declare them
    const saved = workingLibrary(
      [{ ...COUNTER, methods: [ABS] }],
      [fb("Counter", "VAR_INPUT\n    On : BOOL;\nEND_VAR")],
    );
    expect(saved.map((e) => [e.name, e.inputs.map((p) => p.name), e.methods?.map((m) => m.name)])).toEqual([
      ["Counter", ["On"], ["ABS"]],
    ]);
  });
});
