// The Tests panel (docs/testing.md): the test files of the working copy and their tests with pass/fail;
// run all, a file or one test (results stream in); a failure shows its message, both values and where
// it happened (a click opens the test file at that line); a failed test's last state opens online;
// a run with coverage tints what no test executed or energised in the LD/FBD/ST editors.
import { useEffect } from "react";
import type { Diagnostic, TestFailureInfo, TestResultInfo } from "../generated/api";
import type { Project } from "../generated/api";
import { panelsStore } from "../store/panels";
import { useWorkspace, workspaceStore } from "../store/project";
import { CHECK_DELAY_MS } from "../store/useLiveCheck";
import { resultKey, testsStore, useTests } from "./store";

/** Opens a test file in the editor at a line. */
export function revealTestLine(file: string, line: number | null | undefined) {
  workspaceStore.getState().openPou(file);
  panelsStore.getState().reveal({ pou: file, line: line ?? 1, part: "body" });
}

const STATUS = { passed: "✓", failed: "✗" } as const;

function FailureView({ file, name, failure }: { file: string; name: string; failure: TestFailureInfo }) {
  const project = useWorkspace((s) => s.project);
  const online = failure.kind !== "memory";
  return (
    <div className="test-failure" role="group" aria-label={`Failure of ${name}`}>
      <pre className="test-failure-message">{failure.message}</pre>
      {failure.expected != null || failure.actual != null ? (
        <dl className="test-values">
          <dt>expected</dt>
          <dd data-testid="expected">{failure.expected}</dd>
          <dt>actual</dt>
          <dd data-testid="actual">{failure.actual}</dd>
        </dl>
      ) : null}
      {failure.note ? <p className="test-note">{failure.note}</p> : null}
      <div className="test-failure-actions">
        {failure.line != null ? (
          <button type="button" className="link" onClick={() => revealTestLine(file, failure.line)}>
            {file}:{failure.line}
          </button>
        ) : null}
        {online && project ? (
          <button type="button" onClick={() => void testsStore.getState().openFailure(project, file, name)}>
            Open failure online
          </button>
        ) : null}
      </div>
    </div>
  );
}

function TestRow({ project, file, name, line }: { project: Project; file: string; name: string; line: number }) {
  const result: TestResultInfo | undefined = useTests((s) => s.results[resultKey(file, name)]);
  const running = useTests((s) => s.running !== null);
  const outcome = result?.outcome ?? "not-run";
  return (
    <li className={`test-row test-${outcome}`} data-test={name}>
      <span className="test-status" aria-label={outcome === "not-run" ? "not run" : outcome}>
        {result ? STATUS[result.outcome] : "·"}
      </span>
      <button type="button" className="link test-name" onClick={() => revealTestLine(file, line)}>
        {name}
      </button>
      <button
        type="button"
        aria-label={`Run test ${name}`}
        disabled={running}
        onClick={() => void testsStore.getState().run(project, { file, test: name })}
      >
        Run
      </button>
      {result?.failure ? <FailureView file={file} name={name} failure={result.failure} /> : null}
    </li>
  );
}

function FileDiagnostics({ file, diagnostics }: { file: string; diagnostics: readonly Diagnostic[] }) {
  const errors = diagnostics.filter((d) => d.severity === "error");
  if (!errors.length) return null;
  return (
    <ul className="test-diagnostics" aria-label={`Problems of ${file}`}>
      {errors.map((d, i) => (
        <li key={i}>
          <button type="button" className="link" onClick={() => revealTestLine(file, d.line)}>
            {d.line != null ? `${d.line}:${d.column ?? 1}` : file}
          </button>{" "}
          {d.message}
        </li>
      ))}
    </ul>
  );
}

export function TestsPanel() {
  const project = useWorkspace((s) => s.project);
  const files = useTests((s) => s.files);
  const running = useTests((s) => s.running);
  const summary = useTests((s) => s.summary);
  const error = useTests((s) => s.error);
  const coverage = useTests((s) => s.coverage);
  const withCoverage = useTests((s) => s.withCoverage);
  const tests = project?.tests;
  // The list follows the working copy's test files (names and tests, parsed by the server), once typing pauses.
  useEffect(() => {
    if (!project) return;
    const timer = setTimeout(() => void testsStore.getState().refresh(project), CHECK_DELAY_MS);
    return () => clearTimeout(timer);
    // Only a change of the test files themselves asks again.
    // eslint-disable-next-line react-hooks/exhaustive-deps
  }, [tests]);
  if (!project) return null;
  const run = (request = {}) => void testsStore.getState().run(project, request);
  let status = "";
  if (running) status = `Running… ${running.done}${running.total != null ? ` of ${running.total}` : ""}`;
  else if (summary)
    status =
      `${summary.passed} passed, ${summary.failed} failed` +
      (summary.skipped ? `, ${summary.skipped} skipped` : "") +
      (summary.files_with_errors ? `; ${summary.files_with_errors} file(s) with errors` : "");
  return (
    <div className="tests-panel">
      <div className="tests-toolbar">
        <button type="button" disabled={running !== null || !files.length} onClick={() => run()}>
          Run all
        </button>
        <label>
          <input
            type="checkbox"
            checked={withCoverage}
            onChange={(e) => testsStore.getState().setWithCoverage(e.target.checked)}
          />{" "}
          with coverage
        </label>
        {coverage ? (
          <button type="button" onClick={() => testsStore.getState().clearCoverage()}>
            Hide coverage
          </button>
        ) : null}
        <span className="tests-status" role="status">
          {status}
        </span>
      </div>
      {error ? (
        <p className="tests-error" role="alert">
          {error}
        </p>
      ) : null}
      {files.length ? (
        <ul className="test-files">
          {files.map((f) => (
            <li key={f.file} className="test-file">
              <div className="test-file-head">
                <span className="test-file-name">{f.file}</span>
                <button
                  type="button"
                  aria-label={`Run ${f.file}`}
                  disabled={running !== null}
                  onClick={() => run({ file: f.file })}
                >
                  Run file
                </button>
              </div>
              <FileDiagnostics file={f.file} diagnostics={f.diagnostics ?? []} />
              <ul className="test-list">
                {(f.tests ?? []).map((t) => (
                  <TestRow key={t.name} project={project} file={f.file} name={t.name} line={t.line} />
                ))}
              </ul>
            </li>
          ))}
        </ul>
      ) : (
        <p className="tests-empty">No test files yet: add one with “New test file” in the project tree.</p>
      )}
    </div>
  );
}
