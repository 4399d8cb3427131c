import { describe, expect, it } from "vitest";
import type { Project } from "../generated/api";
import {
  gvlNameOf,
  gvlOfDiagnostic,
  gvlTab,
  isGvlTab,
  newGvlProblem,
  sharedListVariables,
  withGvlChange,
  withNewGvl,
  withoutGvl,
} from "./gvls";

const project: Project = {
  name: "p",
  gvls: [{ name: "GVL_IO", qualified_only: true, text: "VAR_GLOBAL\n    bStart : BOOL;\nEND_VAR" }],
  pous: [{ name: "Main", kind: "program", language: "st" }],
};

describe("global variable lists", () => {
  it("are tabs of their own, apart from POUs", () => {
    expect(gvlTab("GVL_IO")).toBe("gvl:GVL_IO");
    expect(isGvlTab("gvl:GVL_IO")).toBe(true);
    expect(isGvlTab("GVL_IO")).toBe(false);
    expect(gvlNameOf("gvl:GVL_IO")).toBe("GVL_IO");
  });

  it("find a diagnostic's list by its file", () => {
    expect(gvlOfDiagnostic({ code: "ST-DUPLICATE", message: "", file: "gvls/GVL_IO" })).toBe("GVL_IO");
    expect(gvlOfDiagnostic({ code: "ST-DUPLICATE", message: "", file: "globals" })).toBeNull();
  });

  it("refuse a new name that is no identifier or is taken by a list or a POU, in any case", () => {
    expect(newGvlProblem(project, "GVL_Motors")).toBeNull();
    expect(newGvlProblem(project, "gvl_io")).toBe("There is already a global variable list called GVL_IO.");
    expect(newGvlProblem(project, "MAIN")).toBe("There is already a POU called Main.");
    expect(newGvlProblem(project, "2x")).toBe(
      "2x is not an IEC identifier (letters, digits and _, not starting with a digit).",
    );
  });

  it("are added with an empty VAR_GLOBAL block, changed and removed", () => {
    const added = withNewGvl(project, "GVL_Motors");
    expect(added.gvls?.map((g) => [g.name, g.qualified_only, g.text])).toEqual([
      ["GVL_IO", true, project.gvls![0]!.text],
      ["GVL_Motors", false, "VAR_GLOBAL\nEND_VAR"],
    ]);
    const changed = withGvlChange(added, "GVL_Motors", { qualified_only: true });
    expect(changed.gvls?.[1]?.qualified_only).toBe(true);
    expect(withoutGvl(changed, "GVL_IO").gvls?.map((g) => g.name)).toEqual(["GVL_Motors"]);
  });
});

describe("sharedListVariables", () => {
  it("names what several lists declare (upper case), once", () => {
    const list = (name: string, text: string) => ({ name, qualified_only: false, text });
    const gvls = [
      list("GVL_A", "VAR_GLOBAL\n    x : INT;\n    t : TON;\nEND_VAR"),
      list("GVL_B", "VAR_GLOBAL\n    X : BOOL;\nEND_VAR"),
      list("GVL_C", "VAR_GLOBAL\n    x, y : INT;\nEND_VAR"),
    ];
    expect(sharedListVariables(gvls)).toEqual(["X"]);
    expect(sharedListVariables(gvls.slice(0, 1))).toEqual([]);
  });
});
