import { describe, expect, it } from "vitest";
import { defaultSuggestion, suggest } from "./OperandEditor";
import { symbol } from "../test/symbols";

const sym = (name: string) => symbol(name, "BOOL");
const symbols = [sym("Motor"), sym("Start"), sym("StartCount"), sym("Remote")];

describe("operand autocomplete: what Enter and Tab take", () => {
  it("highlights the first suggestion that starts with the typed text", () => {
    const list = suggest("Mo", symbols);
    expect(list.map((s) => s.name)).toEqual(["Motor", "Remote"]);
    expect(defaultSuggestion("Mo", list, symbols)).toBe(0);
  });

  it("highlights nothing for a text that names a symbol, only contains one, or is empty", () => {
    expect(defaultSuggestion("Start", suggest("Start", symbols), symbols)).toBe(-1);
    expect(defaultSuggestion("mot", suggest("mot", [sym("Remote")]), [sym("Remote")])).toBe(-1);
    expect(defaultSuggestion("", suggest("", symbols), symbols)).toBe(-1);
  });
});
