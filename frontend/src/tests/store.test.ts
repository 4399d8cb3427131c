// The Tests panel's state (issue 20): streamed events become files, results and the summary; a newer
// run wins over an older one; coverage comes only from a run that asked for it.
import { describe, expect, it } from "vitest";
import type { TestEvent, TestFileInfo, TestResultInfo } from "../generated/api";
import type { Project } from "../generated/api";
import type { RunRequest, TestsApi } from "./api";
import { coverageLines, coverageMarks, coverageOf } from "./coverage";
import { createTestsStore, resultKey } from "./store";

const project: Project = {
  name: "p",
  tests: [
    { name: "a", text: "" },
    { name: "b", text: "" },
  ],
};
const file = (name: string, tests: string[]): TestFileInfo => ({
  file: `tests/${name}.st`,
  tests: tests.map((t, i) => ({ name: t, line: i + 1 })),
  diagnostics: [],
});
const result = (f: string, name: string, outcome: "passed" | "failed"): TestResultInfo => ({
  file: `tests/${f}.st`,
  name,
  line: 1,
  outcome,
  duration_s: 0,
  scans: 0,
  ...(outcome === "failed" ? { failure: { message: "no", kind: "assertion" } } : {}),
});

/** An API whose run hands out `events` and remembers what it was asked. */
function fakeApi(events: TestEvent[], asked: RunRequest[] = []): TestsApi {
  return {
    listTests: async () => ({ files: [file("a", ["x"])] }),
    checkTestFile: async () => file("a", []),
    openFailure: async () => {
      throw new Error("not here");
    },
    runTests: async (_p, request, onEvent) => {
      asked.push(request);
      for (const e of events) onEvent(e);
    },
  };
}

describe("the tests store", () => {
  it("turns the stream into files in project order, results, progress and the summary", async () => {
    const progress: (number | null)[] = [];
    const store = createTestsStore(
      fakeApi([
        { type: "file", file: file("b", ["y"]) },
        { type: "file", file: file("a", ["x", "z"]) },
        { type: "result", result: result("a", "x", "passed") },
        { type: "result", result: result("a", "z", "failed") },
        { type: "result", result: result("b", "y", "passed") },
        { type: "done", summary: { passed: 2, failed: 1, skipped: 0, files_with_errors: 0, seconds: 0.1 } },
      ]),
    );
    store.subscribe((s) => progress.push(s.running?.total ?? null));
    await store.getState().run(project);
    const state = store.getState();
    expect(state.files.map((f) => f.file)).toEqual(["tests/a.st", "tests/b.st"]);
    expect(state.results[resultKey("tests/a.st", "z")]!.outcome).toBe("failed");
    expect(Object.keys(state.results)).toHaveLength(3);
    expect(state.summary?.failed).toBe(1);
    expect(state.running).toBeNull();
    expect(progress).toContain(3); // 1 + 2 tests announced before the results
    expect(state.coverage).toBeNull();
  });

  it("asks for coverage when the checkbox is on, and keeps it from the done event", async () => {
    const asked: RunRequest[] = [];
    const coverage = { Main: { language: "ld", elements: 2, executed: 1, never_executed: ["c1"] } };
    const store = createTestsStore(fakeApi([{ type: "done", coverage }], asked));
    store.getState().setWithCoverage(true);
    await store.getState().run(project, { file: "tests/a.st" });
    expect(asked).toEqual([{ coverage: true, file: "tests/a.st" }]);
    expect(store.getState().coverage).toEqual(coverage);
    store.getState().clearCoverage();
    expect(store.getState().coverage).toBeNull();
  });

  it("reports a failed run's error", async () => {
    const api = fakeApi([]);
    api.runTests = async () => {
      throw new Error("project 'p' has no test file 'tests/x.st'");
    };
    const store = createTestsStore(api);
    await store.getState().run(project, { file: "tests/x.st" });
    expect(store.getState().error).toBe("project 'p' has no test file 'tests/x.st'");
    expect(store.getState().running).toBeNull();
  });
});

describe("coverage marks", () => {
  it("marks elements never executed over never energised and a pin's probe on its box", () => {
    const marks = coverageMarks({
      language: "ld",
      elements: 5,
      executed: 3,
      never_executed: ["blink", "blink.OUT"],
      never_energised: ["ton.Q", "seal"],
    });
    expect([...marks.entries()].sort()).toEqual([
      ["blink", "never-executed"],
      ["seal", "never-energised"],
      ["ton", "never-energised"],
    ]);
    expect(coverageLines({ language: "st", elements: 4, executed: 2, never_executed_lines: [3, 4] })).toEqual([3, 4]);
    expect(coverageOf({ Main: { language: "ld", elements: 0, executed: 0 } }, "MAIN")).toBeDefined();
    expect(coverageOf(null, "Main")).toBeUndefined();
  });
});
