import { describe, expect, it } from "vitest";
import type { LibraryEntry, Pou } from "../generated/api";
import { variableOccurrences } from "./inlineValues";
import { structTypes, type Scope } from "./members";
import { ownNames } from "./methodScope";
import { withInherited } from "./scope";
import { symbol } from "../test/symbols";

const base: Pou = {
  name: "Base",
  kind: "function_block",
  language: "st",
  declarations: "VAR\n    Total : INT;\n    Count : INT;\nEND_VAR",
  body: "",
};
const counter: Pou = {
  name: "Counter",
  kind: "function_block",
  language: "st",
  extends: "Base",
  declarations: "VAR\n    Count : INT;\n    Limit : INT;\nEND_VAR",
  body: "",
};
const scope: Scope = {
  symbols: [symbol("Count", "INT", "VAR"), symbol("Limit", "INT", "VAR"), symbol("Total", "BOOL", "VAR_GLOBAL")],
  library: [] as LibraryEntry[],
  structs: structTypes(""),
};
const paths = (text: string, hidden: ReadonlySet<string>) =>
  variableOccurrences(text, withInherited(scope, counter, [base, counter]), "MAIN.C1", hidden).map((o) => [
    o.text,
    o.path,
  ]);

describe("a method's names online (issue 25 item 6; ON-03, ON-09)", () => {
  it("takes the own variables and the result (named as the method) as hiding the instance's", () => {
    expect([...ownNames("Bump", "VAR_INPUT\n    Inc : INT;\nEND_VAR\nVAR\n    Limit : INT;\nEND_VAR")]).toEqual([
      "BUMP",
      "INC",
      "LIMIT",
    ]);
  });

  it("shows the instance's variables; an own variable of the same name is not the instance's", () => {
    const hidden = ownNames("Bump", "VAR_INPUT\n    Inc : INT;\nEND_VAR\nVAR\n    Limit : INT;\nEND_VAR");
    expect(paths("Count := Count + Inc;\nIF Count > Limit THEN Bump := TRUE; END_IF;", hidden)).toEqual([
      ["Count", "MAIN.C1.COUNT"],
      ["Count", "MAIN.C1.COUNT"],
      ["Count", "MAIN.C1.COUNT"],
    ]);
  });

  it("takes a base FB's variable (EXTENDS) as the instance's, before a global of the same name", () => {
    expect(paths("Total := Total + Count;", new Set())).toEqual([
      ["Total", "MAIN.C1.TOTAL"],
      ["Total", "MAIN.C1.TOTAL"],
      ["Count", "MAIN.C1.COUNT"],
    ]);
  });

  it("takes THIS^.x and SUPER^.x as the instance's even where an own variable hides x", () => {
    const hidden = ownNames("Bump", "VAR\n    Limit : INT;\nEND_VAR");
    expect(paths("Limit := THIS^.Limit + SUPER^.Total;\nSUPER^.Bump();", hidden)).toEqual([
      ["THIS^.Limit", "MAIN.C1.LIMIT"],
      ["SUPER^.Total", "MAIN.C1.TOTAL"],
    ]);
  });

  it("stops at an unknown base or a cycle of EXTENDS", () => {
    const looped: Pou = { ...base, extends: "Counter" };
    expect(withInherited(scope, counter, [looped, counter]).symbols.map((s) => s.name)).toEqual([
      "Total",
      "Count",
      "Limit",
      "Total",
    ]);
    expect(withInherited(scope, counter, [counter])).toBe(scope);
  });
});
