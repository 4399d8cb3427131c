// The open project (zustand): the working copy, open POU tabs with their LD undo histories (and tabs
// of test files, named by their path tests/<name>.st), library and symbols for the editors, drafts in
// localStorage, and saving with conflict handling.
import { useStore } from "zustand";
import { createStore, type StoreApi } from "zustand/vanilla";
import { ApiError, projectApi, SaveConflictError, type ProjectApi } from "../api/client";
import type { ConflictDetail, Diagnostic, LibraryEntry, SymbolInfo, SymbolTable } from "../generated/api";
import type { FbdBody, LdBody, Pou, PouAction, Project, SfcBody, Task, TestFile } from "../generated/api";
import { historyOf, type History } from "./history";
import { addDeclaration, type VariableDeclaration } from "./declarations";
import { isGlobalClass } from "./newVariable";
import { gvlNameOf, gvlOf, isGvlTab } from "./gvls";
import { isProjectPart } from "./parts";
import { loadDraft, removeDraft, saveDraft } from "./drafts";

export interface WorkspaceData {
  status: "idle" | "loading" | "ready" | "error";
  error: string | null;
  name: string | null;
  /** The revision the working copy is based on, and when it was saved. */
  revision: string | null;
  modified: string | null;
  project: Project | null;
  /** POUs (and test files, by path) with unsaved changes. */
  changed: string[];
  /** The working copy came from a draft left by an earlier session. */
  restoredAt: string | null;
  tabs: string[];
  active: string | null;
  histories: Record<string, History<LdBody>>;
  fbdHistories: Record<string, History<FbdBody>>;
  sfcHistories: Record<string, History<SfcBody>>;
  library: LibraryEntry[];
  symbols: Record<string, SymbolTable>;
  /** POUs the saved project has (the server knows symbols only of those), upper case. */
  savedPous: string[];
  saving: boolean;
  saveError: string | null;
  conflict: ConflictDetail | null;
  /** The working copy before the last project operation (rename, delete, ...): one step back. */
  undo: ProjectUndo | null;
}

/** What undoing a project operation restores. */
export interface ProjectUndo {
  label: string;
  project: Project;
  changed: string[];
  tabs: string[];
  active: string | null;
}

/** A project operation's effect on the open tabs: tabs renamed (old -> new name) and tabs closed. */
export interface TabChanges {
  renamed?: Record<string, string>;
  closed?: string[];
}

export interface WorkspaceActions {
  open(name: string): Promise<void>;
  openPou(pou: string): void;
  closeTab(pou: string): void;
  setLdHistory(pou: string, history: History<LdBody>): void;
  setFbdHistory(pou: string, history: History<FbdBody>): void;
  setSfcHistory(pou: string, history: History<SfcBody>): void;
  declare(pou: string, declaration: VariableDeclaration): void;
  /** Replaces the declaration text of a POU (the declarations table and text view). */
  setDeclarations(pou: string, text: string): void;
  /** The new text of an ST POU's body (marks it unsaved and keeps a draft, like any edit). */
  setStBody(pou: string, text: string): void;
  /** The new ACTIONs of a function block (outside SFC, ST bodies; docs/st.md "ACTION"). */
  setActions(pou: string, actions: PouAction[]): void;
  /** Replaces the rest of the project (panels, the exercise): `key` names the change in `changed`. */
  setProjectPart(key: string, update: (project: Project) => Project): void;
  /** Opens a tab that is no POU (a panel, the exercise: keys of src/hmi/shell.tsx). */
  openTab(key: string): void;
  /** Adds a new, empty POU to the working copy and opens it; an error message when the name is refused. */
  addPou(name: string, kind: Pou["kind"], language: Pou["language"]): string | null;
  /** The new VAR_GLOBAL text, TYPE text or task list of the project (each marks its part unsaved). */
  setGlobals(text: string): void;
  setTypes(text: string): void;
  setTasks(tasks: Task[]): void;
  /** The new text of a test file (by path, tests/<name>.st). */
  setTestText(path: string, text: string): void;
  /** Adds a test file with a first test to the working copy and opens it; an error message when refused. */
  addTestFile(name: string): string | null;
  /** Saves the working copy; `overwrite` saves over the revision a conflict reported. */
  save(overwrite?: boolean): Promise<void>;
  /** Drops the working copy and loads the saved project. */
  reload(): Promise<void>;
  dismissConflict(): void;
  /** Fetches a POU's symbols and the library again (a view of it is reloaded after a failure). */
  refreshPou(pou: string): void;
  /** Replaces the working copy by `next` as one undoable step named `label` (rename, delete, ...);
   * `changed` are the items it marks unsaved. */
  applyOperation(label: string, next: Project, changed: string[], tabs?: TabChanges): void;
  /** Takes the last project operation back. */
  undoOperation(): void;
}

export type WorkspaceState = WorkspaceData & WorkspaceActions;

export const emptyWorkspace: WorkspaceData = {
  status: "idle",
  error: null,
  name: null,
  revision: null,
  modified: null,
  project: null,
  changed: [],
  restoredAt: null,
  tabs: [],
  active: null,
  histories: {},
  fbdHistories: {},
  sfcHistories: {},
  library: [],
  symbols: {},
  savedPous: [],
  saving: false,
  saveError: null,
  conflict: null,
  undo: null,
};

/** The declarations a new (or re-kinded empty) POU starts with. */
export const emptyDeclarations = (kind: Pou["kind"]) => (kind === "function" ? "VAR_INPUT\nEND_VAR" : "VAR\nEND_VAR");

const IDENTIFIER = /^[A-Za-z_][A-Za-z0-9_]{0,63}$/;
const message = (err: unknown) => (err instanceof Error ? err.message : String(err));
const pouNames = (project: Project): string[] => (project.pous ?? []).map((p) => p.name.toUpperCase());
export const pouOf = (project: Project | null, name: string): Pou | undefined =>
  project?.pous?.find((p) => p.name === name);

/** Test files are shown and stored as tests/<name>.st; a tab of that name is a test file, never a POU. */
export const testPath = (name: string) => `tests/${name}.st`;
export const isTestPath = (tab: string) => tab.startsWith("tests/");
export const testOf = (project: Project | null, path: string): TestFile | undefined =>
  project?.tests?.find((t) => testPath(t.name) === path);
const TEST_NAME = /^[A-Za-z0-9][A-Za-z0-9_-]{0,63}$/;

/** Why `name` cannot name a test file of `project` (another than `except`), or null when it can. */
export function testNameProblem(project: Project | null, name: string, except?: string): string | null {
  if (!TEST_NAME.test(name))
    return `${name || "An empty name"} cannot name a test file (letters, digits, _ and -, starting with a letter or digit).`;
  const lower = name.toLowerCase();
  if (project?.tests?.some((t) => t.name !== except && t.name.toLowerCase() === lower))
    return `There is already a test file called ${name}.`;
  return null;
}

/** What a new test file starts with (docs/testing.md). */
export const NEW_TEST_TEXT = `TEST 'first test'
  RUN_SCANS(1);
  ASSERT_TRUE(TRUE, 'replace with what the program must do');
END_TEST
`;
/** What a new SFC POU starts with: the initial step, a transition and the jump back (as CODESYS does). */
const sfcStart = (): SfcBody => ({
  chart: {
    elements: [
      { type: "step", id: "s1", name: "Init", actions: [] },
      { type: "transition", id: "t1", condition: "FALSE" },
      { type: "jump", id: "j1", target: "Init" },
    ],
  },
  actions: [],
  transitions: [],
});

const isDiagramBody = (body: Pou["body"]): body is LdBody | FbdBody =>
  typeof body === "object" && body !== null && "networks" in body;
export const ldBodyOf = (pou: Pou): LdBody => (isDiagramBody(pou.body) ? (pou.body as LdBody) : { networks: [] });
export const fbdBodyOf = (pou: Pou): FbdBody => (isDiagramBody(pou.body) ? (pou.body as FbdBody) : { networks: [] });
export const sfcBodyOf = (pou: Pou): SfcBody =>
  typeof pou.body === "object" && pou.body !== null && "chart" in pou.body
    ? (pou.body as SfcBody)
    : { chart: { elements: [] } };

/** A symbol known by name and type only (a variable just declared, a path to suggest). */
export const plainSymbol = (name: string, type: string): SymbolInfo => ({
  name,
  type,
  var_class: "VAR",
  initial: null,
  address: null,
  comment: null,
  retain: false,
  constant: false,
});

/** The symbols of a POU and the globals, for autocomplete and online paths. */
export const symbolsOf = (table: SymbolTable | undefined): SymbolInfo[] =>
  table ? [...table.symbols, ...table.globals] : [];

/** The problems a diagram editor marks: its POU's, located in a network (symbol table and last check). */
export const diagramDiagnostics = (
  table: SymbolTable | undefined,
  checked: readonly Diagnostic[],
  pou: string,
): Diagnostic[] =>
  [...(table?.diagnostics ?? []), ...checked.filter((d) => d.pou?.toUpperCase() === pou.toUpperCase())].filter(
    (d) => d.network,
  );

/** Tabs with fresh diagram histories from `project` (a project operation may have changed any body). */
function diagramHistories(project: Project, tabs: string[], active: string | null): Partial<WorkspaceData> {
  const histories: Record<string, History<LdBody>> = {};
  const fbdHistories: Record<string, History<FbdBody>> = {};
  for (const tab of tabs) {
    const pou = pouOf(project, tab);
    if (pou?.language === "ld") histories[tab] = historyOf(ldBodyOf(pou));
    if (pou?.language === "fbd" || pou?.language === "cfc") fbdHistories[tab] = historyOf(fbdBodyOf(pou));
  }
  return { tabs, active, histories, fbdHistories };
}

export function createWorkspaceStore(
  api: ProjectApi = projectApi,
  storage: Storage = localStorage,
): StoreApi<WorkspaceState> {
  let openCall = 0;
  return createStore<WorkspaceState>()((set, get) => {
    const replacePous = (pou: string, update: (pous: Pou[]) => Pou[]) =>
      replaceProject(pou, (project) => ({ ...project, pous: update(project.pous ?? []) }));

    const replaceTests = (path: string, update: (tests: TestFile[]) => TestFile[]) =>
      replaceProject(path, (project) => ({ ...project, tests: update(project.tests ?? []) }));

    /** A change of one POU or test file (`item`): marks it unsaved and keeps a draft. */
    const replaceProject = (item: string, update: (project: Project) => Project) => {
      const { project, changed } = get();
      if (!project) return;
      commit(update(project), changed.includes(item) ? changed : [...changed, item]);
    };

    /** The new working copy and its unsaved items, kept as a draft. */
    const commit = (next: Project, nextChanged: string[]) => {
      set({ project: next, changed: nextChanged });
      const { revision, modified } = get();
      saveDraft(
        {
          base_revision: revision!,
          base_modified: modified!,
          saved_at: new Date().toISOString(),
          project: next,
          changed: nextChanged,
        },
        storage,
      );
    };

    const replacePou = (pou: string, update: (p: Pou) => Pou) =>
      replacePous(pou, (pous) => pous.map((p) => (p.name === pou ? update(p) : p)));

    /** The symbols of a saved POU (a new one has none on the server until the project is saved). */
    const loadSymbols = (pou: string) => {
      const name = get().name;
      if (!name || !get().savedPous.includes(pou.toUpperCase())) return;
      api.getSymbols(name, pou).then(
        (table) => {
          if (get().name === name) set({ symbols: { ...get().symbols, [pou]: table } });
        },
        () => undefined, // no symbols: autocomplete is empty and every name gets the declare offer
      );
    };

    /** The library with the project's own functions and FBs (again after a save, which may add or change them). */
    const loadLibrary = (name: string, call: number) => {
      api.getLibrary(name).then(
        (library) => {
          if (call === openCall) set({ library });
        },
        () => undefined, // no library: the box picker is empty, boxes show their connected pins
      );
    };

    const load = async (name: string, useDraft: boolean) => {
      const call = ++openCall;
      set({ ...emptyWorkspace, status: "loading", name });
      try {
        const doc = await api.getProject(name);
        if (call !== openCall) return;
        const draft = useDraft ? loadDraft(name, storage) : null;
        set({
          status: "ready",
          savedPous: pouNames(doc.project),
          revision: draft?.base_revision ?? doc.revision,
          modified: draft?.base_modified ?? doc.modified,
          project: draft?.project ?? doc.project,
          changed: draft?.changed ?? [],
          restoredAt: draft?.saved_at ?? null,
        });
        loadLibrary(name, call);
      } catch (err) {
        if (call === openCall) set({ status: "error", error: message(err) });
      }
    };

    return {
      ...emptyWorkspace,

      open: (name) => load(name, true),

      openPou(pou) {
        const { tabs, project, histories } = get();
        if (isProjectPart(pou) || (isGvlTab(pou) && gvlOf(project, gvlNameOf(pou)))) {
          set({ active: pou, tabs: tabs.includes(pou) ? tabs : [...tabs, pou] });
          return;
        }
        if (isTestPath(pou)) {
          if (testOf(project, pou)) set({ active: pou, tabs: tabs.includes(pou) ? tabs : [...tabs, pou] });
          return;
        }
        const found = pouOf(project, pou);
        if (!found) return;
        const patch: Partial<WorkspaceData> = { active: pou, tabs: tabs.includes(pou) ? tabs : [...tabs, pou] };
        if (found.language === "ld" && !histories[pou])
          patch.histories = { ...histories, [pou]: historyOf(ldBodyOf(found)) };
        if ((found.language === "fbd" || found.language === "cfc") && !get().fbdHistories[pou])
          patch.fbdHistories = { ...get().fbdHistories, [pou]: historyOf(fbdBodyOf(found)) };
        if (found.language === "sfc" && !get().sfcHistories[pou])
          patch.sfcHistories = { ...get().sfcHistories, [pou]: historyOf(sfcBodyOf(found)) };
        set(patch);
        if (!get().symbols[pou]) loadSymbols(pou);
      },

      setProjectPart: replaceProject,

      openTab(key) {
        const { tabs } = get();
        set({ active: key, tabs: tabs.includes(key) ? tabs : [...tabs, key] });
      },

      closeTab(pou) {
        const { tabs, active } = get();
        const index = tabs.indexOf(pou);
        const rest = tabs.filter((t) => t !== pou);
        set({ tabs: rest, active: active === pou ? (rest[Math.min(index, rest.length - 1)] ?? null) : active });
      },

      setLdHistory(pou, history) {
        set({ histories: { ...get().histories, [pou]: history } });
        replacePou(pou, (p) => ({ ...p, body: history.present }));
      },

      setFbdHistory(pou, history) {
        set({ fbdHistories: { ...get().fbdHistories, [pou]: history } });
        replacePou(pou, (p) => ({ ...p, body: history.present }));
      },

      setSfcHistory(pou, history) {
        set({ sfcHistories: { ...get().sfcHistories, [pou]: history } });
        replacePou(pou, (p) => ({ ...p, body: history.present }));
      },

      declare(pou, variable) {
        const global = isGlobalClass(variable.varClass);
        if (global) get().setGlobals(addDeclaration(get().project?.globals ?? "", variable));
        else replacePou(pou, (p) => ({ ...p, declarations: addDeclaration(p.declarations ?? "", variable) }));
        const table = get().symbols[pou] ?? { pou, symbols: [], globals: [], diagnostics: [] };
        const symbol = plainSymbol(variable.name, variable.type);
        const next = global
          ? { ...table, globals: [...table.globals, symbol] }
          : { ...table, symbols: [...table.symbols, symbol] };
        set({ symbols: { ...get().symbols, [pou]: next } });
      },

      setDeclarations(pou, text) {
        if (pouOf(get().project, pou)?.declarations === text) return;
        replacePou(pou, (p) => ({ ...p, declarations: text }));
      },

      setActions(pou, actions) {
        replacePou(pou, (p) => ({ ...p, actions }));
      },

      setStBody(pou, text) {
        if (pouOf(get().project, pou)?.body === text) return;
        replacePou(pou, (p) => ({ ...p, body: text }));
      },

      addPou(text, kind, language) {
        const name = text.trim();
        if (!IDENTIFIER.test(name))
          return `${name || "An empty name"} is not an IEC identifier (letters, digits and _, not starting with a digit).`;
        if (pouOf(get().project, name) || get().project?.pous?.some((p) => p.name.toUpperCase() === name.toUpperCase()))
          return `There is already a POU called ${name}.`;
        const pou: Pou = {
          name,
          kind,
          language,
          declarations: emptyDeclarations(kind),
          body:
            language === "st" || language === "il"
              ? ""
              : language === "sfc"
                ? sfcStart()
                : language === "cfc"
                  ? { networks: [{ id: "chart", nodes: [], wires: [] }] } // one chart, no networks (CFC-01)
                  : { networks: [] },
          ...(kind === "function" ? { return_type: "BOOL" } : {}),
        };
        replacePous(name, (pous) => [...pous, pou]);
        get().openPou(name);
        return null;
      },

      setGlobals(text) {
        if (get().project?.globals !== text) replaceProject("part:globals", (p) => ({ ...p, globals: text }));
      },

      setTypes(text) {
        if (get().project?.types !== text) replaceProject("part:types", (p) => ({ ...p, types: text }));
      },

      setTasks(tasks) {
        replaceProject("part:tasks", (p) => ({ ...p, tasks }));
      },

      setTestText(path, text) {
        if (testOf(get().project, path)?.text === text) return;
        replaceTests(path, (tests) => tests.map((t) => (testPath(t.name) === path ? { ...t, text } : t)));
      },

      addTestFile(text) {
        const name = text.trim();
        const problem = testNameProblem(get().project, name);
        if (problem) return problem;
        replaceTests(testPath(name), (tests) => [...tests, { name, text: NEW_TEST_TEXT }]);
        get().openPou(testPath(name));
        return null;
      },

      async save(overwrite = false) {
        const { name, project, revision, conflict } = get();
        if (!name || !project || !revision) return;
        set({ saving: true, saveError: null });
        try {
          const result = await api.saveProject(
            name,
            overwrite && conflict ? conflict.current_revision : revision,
            project,
          );
          removeDraft(name, storage);
          set({
            savedPous: pouNames(project),
            saving: false,
            revision: result.revision,
            modified: result.modified,
            changed: [],
            restoredAt: null,
            conflict: null,
          });
          for (const pou of get().tabs) if (pouOf(get().project, pou)) loadSymbols(pou);
          loadLibrary(name, openCall);
        } catch (err) {
          if (err instanceof SaveConflictError) set({ saving: false, conflict: err.conflict });
          else set({ saving: false, saveError: err instanceof ApiError ? err.message : message(err) });
        }
      },

      async reload() {
        const { name, tabs, active } = get();
        if (!name) return;
        removeDraft(name, storage);
        await load(name, false);
        for (const tab of tabs) (isTestPath(tab) || pouOf(get().project, tab) ? get().openPou : get().openTab)(tab);
        if (active && get().tabs.includes(active)) set({ active });
      },

      dismissConflict: () => set({ conflict: null }),

      applyOperation(label, next, items, tabChanges = {}) {
        const { project, changed, tabs, active } = get();
        if (!project) return;
        const renamed = tabChanges.renamed ?? {};
        const closed = new Set(tabChanges.closed ?? []);
        const nextTabs = tabs.filter((t) => !closed.has(t)).map((t) => renamed[t] ?? t);
        const nextActive = active && !closed.has(active) ? (renamed[active] ?? active) : (nextTabs[0] ?? null);
        set({ undo: { label, project, changed, tabs, active }, ...diagramHistories(next, nextTabs, nextActive) });
        commit(next, [...new Set([...changed.map((c) => renamed[c] ?? c), ...items])]);
      },

      undoOperation() {
        const { undo } = get();
        if (!undo) return;
        set({ undo: null, ...diagramHistories(undo.project, undo.tabs, undo.active) });
        commit(undo.project, undo.changed);
      },

      refreshPou(pou) {
        const { name } = get();
        if (!name) return;
        loadSymbols(pou);
        loadLibrary(name, openCall);
      },
    };
  });
}

export const workspaceStore = createWorkspaceStore();

export function useWorkspace<T>(selector: (state: WorkspaceState) => T): T {
  return useStore(workspaceStore, selector);
}
