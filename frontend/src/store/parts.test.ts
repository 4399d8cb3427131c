import { describe, expect, it } from "vitest";
import { focusOf } from "./panels";
import { partOf, taskIndexOf } from "./parts";

describe("diagnostics of the project's parts", () => {
  it("are located in the part's tab, at their line or task", () => {
    const global = { code: "ST-UNKNOWN-TYPE", message: "", file: "globals", line: 2 };
    const task = { code: "BAD-INTERVAL", message: "", json_path: "$.tasks[3].interval" };
    expect(partOf(global)).toBe("Global variables");
    expect(partOf({ code: "X", message: "", file: "types" })).toBe("Types");
    expect(partOf(task)).toBe("Tasks");
    expect(partOf({ code: "X", message: "", file: "Main/body", pou: "Main" })).toBeNull();
    expect(taskIndexOf(task)).toBe(3);
    expect(taskIndexOf(global)).toBeNull();
    expect(focusOf(global)).toEqual({ pou: "Global variables", network: null, element: null, line: 2, part: null });
  });
});
