// The Tests panel (zustand): the test files of the working copy and their tests, the results of the last
// runs (streamed in as each test finishes), the coverage of the last run that asked for it, and opening
// a failed test's last state online. The API is injected for tests.
import { useStore } from "zustand";
import { createStore, type StoreApi } from "zustand/vanilla";
import type { CoverageInfo, TestFileInfo, TestResultInfo, TestSummary } from "../generated/api";
import type { Project } from "../generated/api";
import { onlineStore } from "../online/store";
import { testsApi, type RunRequest, type TestsApi } from "./api";

/** Results are kept by file and test name. */
export const resultKey = (file: string, name: string) => `${file}\u0000${name}`;

export interface TestsData {
  files: TestFileInfo[];
  results: Record<string, TestResultInfo>;
  /** While tests run: how many finished, of how many (null until the files are compiled). */
  running: { done: number; total: number | null } | null;
  summary: TestSummary | null;
  /** Per POU name: what the last coverage run never executed or energised (null: no coverage shown). */
  coverage: Record<string, CoverageInfo> | null;
  /** Runs collect coverage (the toolbar's checkbox). */
  withCoverage: boolean;
  error: string | null;
}

export interface TestsActions {
  /** Lists the test files and tests of the working copy (nothing runs). */
  refresh(project: Project): Promise<void>;
  /** Runs every test, a file's (`file`) or one (`file` and `test`); with coverage (the request's, else the
   * checkbox's), tints what never ran. */
  run(project: Project, request?: RunRequest): Promise<void>;
  /** Opens the simulation as it stood when the test failed, online (the simulation bar shows it). */
  openFailure(project: Project, file: string, test: string): Promise<void>;
  clearCoverage(): void;
  setWithCoverage(on: boolean): void;
  clear(): void;
}

export type TestsState = TestsData & TestsActions;

export const emptyTests: TestsData = {
  files: [],
  results: {},
  running: null,
  summary: null,
  coverage: null,
  withCoverage: false,
  error: null,
};

const message = (err: unknown) => (err instanceof Error ? err.message : String(err));

export function createTestsStore(api: TestsApi = testsApi): StoreApi<TestsState> {
  let runs = 0;
  return createStore<TestsState>()((set, get) => ({
    ...emptyTests,

    async refresh(project) {
      try {
        const listing = await api.listTests(project);
        set({ files: listing.files, error: null });
      } catch (err) {
        set({ error: message(err) });
      }
    },

    async run(project, asked = {}) {
      const request = { coverage: get().withCoverage, ...asked };
      const mine = ++runs;
      const current = () => mine === runs;
      set({ running: { done: 0, total: null }, error: null, summary: null, coverage: null });
      try {
        await api.runTests(project, request, (event) => {
          if (!current()) return;
          if (event.type === "file" && event.file) {
            const file = event.file;
            const others = get().files.filter((f) => f.file !== file.file);
            const order = (project.tests ?? []).map((t) => `tests/${t.name}.st`);
            const files = [...others, file].sort((a, b) => order.indexOf(a.file) - order.indexOf(b.file));
            const wanted = request.test ? 1 : (file.tests ?? []).length;
            const total = (get().running?.total ?? 0) + wanted;
            set({ files, running: { done: get().running?.done ?? 0, total } });
          } else if (event.type === "result" && event.result) {
            const r = event.result;
            set({
              results: { ...get().results, [resultKey(r.file, r.name)]: r },
              running: { done: (get().running?.done ?? 0) + 1, total: get().running?.total ?? null },
            });
          } else if (event.type === "done") {
            set({ summary: event.summary ?? null, coverage: event.coverage ?? null });
          }
        });
      } catch (err) {
        if (current()) set({ error: message(err) });
      } finally {
        if (current()) set({ running: null });
      }
    },

    async openFailure(project, file, test) {
      await onlineStore.getState().compile(project.name, () => api.openFailure(project, file, test));
      const error = onlineStore.getState().error;
      if (error) set({ error });
    },

    clearCoverage: () => set({ coverage: null }),
    setWithCoverage: (on) => set({ withCoverage: on }),
    clear: () => set({ ...emptyTests, withCoverage: get().withCoverage }),
  }));
}

export const testsStore = createTestsStore();

export function useTests<T>(selector: (state: TestsState) => T): T {
  return useStore(testsStore, selector);
}
