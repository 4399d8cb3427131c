// @vitest-environment jsdom
import { afterEach, beforeEach, describe, expect, it } from "vitest";
import type { Project } from "../generated/api";
import { debugStore } from "../debug/store";
import { onlineStore } from "../online/store";
import { panelsStore } from "../store/panels";
import { emptyWorkspace, workspaceStore } from "../store/project";
import { followBreakpoints } from "./followBreakpoints";

const project: Project = {
  name: "demo",
  pous: [{ name: "Main", kind: "program", language: "st", declarations: "", body: "a := 1;\nb := 2;\nc := 3;" }],
};

let stop: () => void = () => undefined;

beforeEach(() => {
  localStorage.clear();
  workspaceStore.setState({ ...emptyWorkspace, status: "ready", name: "demo", revision: "r1", project });
  debugStore.getState().open("demo");
  debugStore.getState().toggle({ pou: "Main", line: 3 });
  stop = followBreakpoints();
});

afterEach(() => stop());

describe("a breakpoint whose place is gone (issue 22)", () => {
  it("is dropped with its message in the Breakpoints panel and in the online log", () => {
    const shortened = { ...project, pous: [{ ...project.pous![0]!, body: "a := 1;" }] };
    workspaceStore.getState().setStBody("Main", shortened.pous[0]!.body as string);
    const why = "The breakpoint at Main, line 3: c := 3; was removed: Main has no line 3 any more.";
    expect(debugStore.getState().notice).toBe(why);
    expect(panelsStore.getState().panel).toBe("breakpoints");
    const last = onlineStore.getState().monitor.log.at(-1);
    expect(last).toMatchObject({ kind: "system", level: "warning", message: why, origin: "client" });
  });
});
