// REST calls of the Tests panel (docs/testing.md): list, check, run (a stream of JSON lines) and open a
// failed test's last state online. Every call sends the working copy, so unsaved edits are tested.
import { errorFromResponse, requestJson } from "../api/client";
import type { SimulationInfo, TestEvent, TestFileInfo, TestListing } from "../generated/api";
import type { Project } from "../generated/project";

const post = (body: unknown): RequestInit => ({
  method: "POST",
  headers: { "Content-Type": "application/json" },
  body: JSON.stringify(body),
});

export function listTests(project: Project): Promise<TestListing> {
  return requestJson<TestListing>("/api/tests/list", post(project));
}

export function checkTestFile(project: Project, file: string): Promise<TestFileInfo> {
  return requestJson<TestFileInfo>("/api/tests/check", post({ project, file }));
}

export function openFailure(project: Project, file: string, test: string): Promise<SimulationInfo> {
  return requestJson<SimulationInfo>("/api/tests/open", post({ project, file, test }));
}

export interface RunRequest {
  file?: string | null;
  test?: string | null;
  coverage?: boolean;
}

/** Runs tests and hands each event of the stream to `onEvent` as it arrives; resolves when the run ends. */
export async function runTests(
  project: Project,
  request: RunRequest,
  onEvent: (event: TestEvent) => void,
  signal?: AbortSignal,
): Promise<void> {
  const response = await fetch("/api/tests/run", { ...post({ project, ...request }), signal });
  if (!response.ok) throw await errorFromResponse(response);
  const reader = response.body!.getReader();
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
