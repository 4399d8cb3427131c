import { describe, expect, it } from "vitest";
import type { Diagnostic, Pou } from "../generated/api";
import { parametersOf, runField, runText, withBinding, withInstanceName } from "./bindings";

const pump: Pou = {
  name: "Pump",
  kind: "program",
  language: "st",
  declarations:
    "VAR_INPUT\n    Start : BOOL;\n    Level : INT;\nEND_VAR\nVAR_OUTPUT\n    Running : BOOL;\nEND_VAR\nVAR\n    x : INT;\nEND_VAR",
  body: "",
} as Pou;

describe("program-instance bindings (issue 22, CFG-06)", () => {
  it("binds and unbinds parameters; a run that adds nothing is the program's name again", () => {
    const bound = withBinding("Pump", "inputs", "Start", " %IX0.0 ");
    expect(bound).toEqual({ name: "Pump", type: "Pump", inputs: { Start: "%IX0.0" }, outputs: {} });
    const both = withBinding(bound, "outputs", "Running", "Out");
    expect(runText(both, "Fast")).toBe("PROGRAM Pump WITH Fast : Pump(Start := %IX0.0, Running => Out);");
    expect(withBinding(withBinding(both, "inputs", "Start", ""), "outputs", "Running", " ")).toBe("Pump");
  });

  it("renames the instance; its program's own name gives the plain run back", () => {
    const renamed = withInstanceName("Pump", "P1");
    expect(renamed).toEqual({ name: "P1", type: "Pump", inputs: {}, outputs: {} });
    expect(runText(renamed, "Fast")).toBe("PROGRAM P1 WITH Fast : Pump;");
    expect(withInstanceName(renamed, "Pump")).toBe("Pump");
    expect(runText({ name: "P2", type: "Pump", retain: "RETAIN" }, "Slow")).toBe("PROGRAM RETAIN P2 WITH Slow : Pump;");
  });

  it("lists a program's VAR_INPUT and VAR_OUTPUT in declaration order, or null for declarations no table reads", () => {
    expect(parametersOf(pump)).toEqual({ inputs: ["Start", "Level"], outputs: ["Running"] });
    expect(parametersOf({ ...pump, declarations: "VAR_INPUT\n  a, b : INT;\n  (* note *)\nEND_VAR" })).toBeNull();
    expect(parametersOf(undefined)).toBeNull();
  });

  it("places a diagnostic at its binding, the program or the run by its JSON path", () => {
    const at = (json_path: string) => ({ code: "X", message: "m", json_path }) as Diagnostic;
    expect(runField(at("$.tasks[1].programs[0].inputs.Level"), 1, 0)).toBe("inputs.LEVEL");
    expect(runField(at("$.tasks[1].programs[0].outputs.Running"), 1, 0)).toBe("outputs.RUNNING");
    expect(runField(at("$.tasks[1].programs[0].type"), 1, 0)).toBe("type");
    expect(runField(at("$.tasks[1].programs[0]"), 1, 0)).toBeNull();
    expect(runField(at("$.tasks[1].programs[10]"), 1, 1)).toBeUndefined();
    expect(runField(at("$.tasks[1].programs[1].inputs.Level"), 1, 0)).toBeUndefined();
    expect(runField(at("$.tasks[1].interval"), 1, 0)).toBeUndefined();
  });
});
