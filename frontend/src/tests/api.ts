// REST calls of the Tests panel (docs/testing.md): list, check, run (a stream of JSON lines) and open a
// failed test's last state online. Every call sends the working copy, so unsaved edits are tested.
import { http, unwrap } from "../api/client";
import type { Project, SimulationInfo, TestEvent, TestFileInfo, TestListing, TestRunRequest } from "../generated/api";

export function listTests(project: Project): Promise<TestListing> {
  return unwrap(http.POST("/api/tests/list", { body: project }));
}

export function checkTestFile(project: Project, file: string): Promise<TestFileInfo> {
  return unwrap(http.POST("/api/tests/check", { body: { project, file } }));
}

export function openFailure(project: Project, file: string, test: string): Promise<SimulationInfo> {
  return unwrap(http.POST("/api/tests/open", { body: { project, file, test } }));
}

export type RunRequest = Omit<TestRunRequest, "project">;

/** Runs tests and hands each event of the stream to `onEvent` as it arrives; resolves when the run ends. */
export async function runTests(
  project: Project,
  request: RunRequest,
  onEvent: (event: TestEvent) => void,
  signal?: AbortSignal,
): Promise<void> {
  const stream = await unwrap(
    http.POST("/api/tests/run", { body: { project, ...request }, parseAs: "stream", ...(signal ? { signal } : {}) }),
  );
  const reader = (stream as ReadableStream<Uint8Array>).getReader();
  const decoder = new TextDecoder();
  let pending = "";
  for (;;) {
    const { done, value } = await reader.read();
    pending += decoder.decode(value ?? new Uint8Array(), { stream: !done });
    const lines = pending.split("\n");
    pending = lines.pop() ?? "";
    for (const line of lines) if (line.trim()) onEvent(JSON.parse(line) as TestEvent);
    if (done) break;
  }
  if (pending.trim()) onEvent(JSON.parse(pending) as TestEvent);
}

export interface TestsApi {
  listTests: typeof listTests;
  checkTestFile: typeof checkTestFile;
  openFailure: typeof openFailure;
  runTests: typeof runTests;
}

export const testsApi: TestsApi = { listTests, checkTestFile, openFailure, runTests };
