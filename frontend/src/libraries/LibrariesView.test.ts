// @vitest-environment jsdom
import { describe, expect, it } from "vitest";

import { IEC } from "../generated/iec";
import { toggled } from "./LibrariesView";

describe("the Library manager's list", () => {
  it("offers the backend's libraries, each with its functions' signatures", () => {
    expect(IEC.libraries.map((l) => l.name)).toEqual(["Tc2_Math", "Tc2_Utilities"]);
    expect(IEC.libraries[0]!.functions.map((f) => f.signature)).toContain("FRAC(in : LREAL) : LREAL");
  });

  it("keeps the catalogue's order whatever order the libraries are ticked in", () => {
    expect(toggled(["Tc2_Utilities"], "Tc2_Math", true)).toEqual(["Tc2_Math", "Tc2_Utilities"]);
    expect(toggled(["Tc2_Math", "Tc2_Utilities"], "Tc2_Math", false)).toEqual(["Tc2_Utilities"]);
    expect(toggled([], "Tc2_Utilities", false)).toEqual([]);
  });
});
