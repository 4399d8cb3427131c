import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { tokenize } from "./highlight";

const kinds = (line: string) => tokenize(line).map((t) => [t.kind, t.text]);

describe("ST highlighting of the exported text", () => {
  it("marks keywords, names, operators and the statement of the motor rung", () => {
    expect(kinds("Motor := (Start OR Motor) AND NOT Stop;")).toEqual([
      ["name", "Motor"],
      ["plain", " := ("],
      ["name", "Start"],
      ["plain", " "],
      ["keyword", "OR"],
      ["plain", " "],
      ["name", "Motor"],
      ["plain", ") "],
      ["keyword", "AND"],
      ["plain", " "],
      ["keyword", "NOT"],
      ["plain", " "],
      ["name", "Stop"],
      ["plain", ";"],
    ]);
  });

  it("marks comments, typed literals, numbers, strings and types", () => {
    expect(kinds("RunTimer(IN := Motor, PT := T#5s); (* 5 s *)").filter(([k]) => k !== "plain")).toEqual([
      ["name", "RunTimer"],
      ["name", "IN"],
      ["name", "Motor"],
      ["name", "PT"],
      ["literal", "T#5s"],
      ["comment", "(* 5 s *)"],
    ]);
    expect(kinds("x : INT := 16#FF + 2.5e3; s := 'it''s';").filter(([k]) => k !== "plain")).toEqual([
      ["name", "x"],
      ["type", "INT"],
      ["literal", "16#FF"],
      ["number", "2.5e3"],
      ["name", "s"],
      ["string", "'it'"],
      ["string", "'s'"],
    ]);
  });

  it("always joins back to the line it was given (property)", () => {
    fc.assert(
      fc.property(
        fc.string({
          unit: fc.constantFrom("a", "Z", "_", "1", "#", "'", '"', "(", "*", ")", "/", " ", ":", "=", ";", "$", "."),
        }),
        (line) => {
          expect(
            tokenize(line)
              .map((t) => t.text)
              .join(""),
          ).toBe(line);
        },
      ),
    );
  });
});
