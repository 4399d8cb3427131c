import { Text } from "@codemirror/state";
import { describe, expect, it, vi } from "vitest";
import type { Diagnostic } from "../generated/api";
import { lintDiagnostics, undeclaredName } from "./lint";

const unknown = (name: string, extra = ""): Diagnostic =>
  ({
    code: "ST-UNKNOWN-VAR",
    message: `unknown variable '${name}'${extra}`,
    file: "Main/body",
    line: 1,
    column: 10,
    end_line: 1,
    end_column: 15,
    severity: "error",
  }) as Diagnostic;

describe("the ST quick fix of an unknown variable (issue 22)", () => {
  it("knows the name an unknown-variable diagnostic is about, and only those", () => {
    expect(undeclaredName(unknown("Start", "; did you mean 'Stop'?"))).toBe("Start");
    expect(undeclaredName({ ...unknown("Red"), message: "'Red' is not a value of Colour" })).toBeNull();
    expect(undeclaredName({ ...unknown("x"), code: "ST-UNKNOWN-TYPE" })).toBeNull();
  });

  it("puts a Declare action on the mark when the editor can declare, which calls back with the name", () => {
    const doc = Text.of(["Motor := Start;"]);
    const declare = vi.fn();
    const [mark] = lintDiagnostics([unknown("Start")], "Main/body", doc, declare);
    expect(mark).toMatchObject({ from: 9, to: 14 });
    expect(mark!.actions?.map((a) => a.name)).toEqual(["Declare Start"]);
    mark!.actions![0]!.apply(null as never, 9, 14);
    expect(declare).toHaveBeenCalledWith("Start");
    expect(lintDiagnostics([unknown("Start")], "Main/body", doc)[0]!.actions).toBeUndefined();
  });
});
