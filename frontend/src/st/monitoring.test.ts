import { describe, expect, it } from "vitest";
import { monitoringMode } from "./monitoring";

const accessor = (declarations: string) => ({ declarations, body: "" });

describe("monitoringMode", () => {
  it("reads the attribute heading the GET's declarations, past comments and other pragmas", () => {
    expect(monitoringMode({ get: accessor("{attribute 'monitoring' := 'variable'}") })).toBe("variable");
    expect(
      monitoringMode({ get: accessor("(* shown *)\n{attribute 'hide'}\n{ attribute 'monitoring':='Call' }") }),
    ).toBe("call");
  });

  it("reads the SET's when the property has no GET", () => {
    expect(
      monitoringMode({ get: null, set: accessor("{attribute 'monitoring' := 'variable'}\nVAR x : INT; END_VAR") }),
    ).toBe("variable");
  });

  it("is null without the attribute at the head, or with a mode CODESYS has not", () => {
    expect(monitoringMode({ get: accessor("VAR x : INT; END_VAR\n{attribute 'monitoring' := 'call'}") })).toBeNull();
    expect(monitoringMode({ get: accessor("{attribute 'monitoring' := 'value'}") })).toBeNull();
    expect(monitoringMode({ get: null, set: null })).toBeNull();
  });
});
