// @vitest-environment jsdom
import { describe, expect, it } from "vitest";
import type { Project } from "../generated/api";
import { focusOf } from "./panels";
import { loadDraft, saveDraft } from "./drafts";
import { isProjectPart, migratedChanged, migratedTab, partLabel, partOf, PROJECT_PARTS, taskIndexOf } from "./parts";
import { MemoryStorage } from "../test/memoryStorage";

describe("diagnostics of the project's parts", () => {
  it("are located in the part's tab, at their line or task", () => {
    const global = { code: "ST-UNKNOWN-TYPE", message: "", file: "globals", line: 2 };
    const task = { code: "BAD-INTERVAL", message: "", json_path: "$.tasks[3].interval" };
    expect(partOf(global)).toBe("part:globals");
    expect(partOf({ code: "X", message: "", file: "types" })).toBe("part:types");
    expect(partOf(task)).toBe("part:tasks");
    expect(partOf({ code: "BAD-FILE", message: "", json_path: "$.typing" })).toBe("part:libraries");
    expect(partOf({ code: "X", message: "", file: "Main/body", pou: "Main" })).toBeNull();
    expect(taskIndexOf(task)).toBe(3);
    expect(taskIndexOf(global)).toBeNull();
    expect(focusOf(global)).toEqual({ pou: "part:globals", network: null, element: null, line: 2, part: null });
  });
});

describe("the parts' tab keys (issue 22: a POU called Types or Tasks)", () => {
  it("can never be a POU's name: each holds a character no IEC identifier has", () => {
    for (const part of PROJECT_PARTS) expect(part).not.toMatch(/^[A-Za-z_][A-Za-z0-9_]*$/);
    expect(isProjectPart("Types")).toBe(false);
    expect(isProjectPart("Tasks")).toBe(false);
    expect(isProjectPart("constructor")).toBe(false); // an object's own keys only
    expect(migratedTab("toString")).toBe("toString");
    expect(partLabel("part:types")).toBe("Types");
    expect(partLabel("part:exercise")).toBe("Exercise");
    expect(partLabel("Types")).toBe("Types"); // a POU's name is its own label
  });

  it("reads the keys older versions stored (the parts' labels) as the parts' keys", () => {
    expect(["Global variables", "Types", "Tasks", "Library manager", "exercise", "Main"].map(migratedTab)).toEqual([
      "part:globals",
      "part:types",
      "part:tasks",
      "part:libraries",
      "part:exercise",
      "Main",
    ]);
    // an old unsaved mark "Tasks" could have been the POU Tasks too: both stay marked
    expect(migratedChanged(["Tasks", "Types", "Main", "part:types"], (n) => n === "Tasks")).toEqual([
      "part:tasks",
      "Tasks",
      "part:types",
      "Main",
    ]);
  });

  it("migrates a draft's unsaved marks as it loads", () => {
    const storage = new MemoryStorage();
    const project: Project = { name: "p", pous: [{ name: "Types", kind: "program", language: "st", body: "" }] };
    const draft = {
      base_revision: "r1",
      base_modified: "",
      saved_at: "",
      project,
      changed: ["Types", "Global variables"],
    };
    storage.setItem("ladderlab:draft:p", JSON.stringify(draft));
    expect(loadDraft("p", storage)?.changed).toEqual(["part:types", "Types", "part:globals"]);
    // a draft this version saved is read as it is: its "Types" is the POU
    saveDraft({ ...draft, changed: ["Types"] }, storage);
    expect(loadDraft("p", storage)?.changed).toEqual(["Types"]);
  });
});
