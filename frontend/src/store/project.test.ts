// @vitest-environment jsdom
import { describe, expect, it, vi } from "vitest";
import { SaveConflictError, type ProjectApi } from "../api/client";
import type { ProjectDocument } from "../generated/api";
import type { Project } from "../generated/api";
import { motorMain } from "../ld/fixtures";
import { record } from "./history";
import { deleteElements } from "../ld/ops";
import { addNetwork } from "../fbd/ops";
import { loadDraft, saveDraft } from "./drafts";
import { createWorkspaceStore } from "./project";
import { MemoryStorage } from "../test/memoryStorage";

const project: Project = {
  name: "demo",
  pous: [
    { name: "Main", kind: "program", language: "ld", declarations: "VAR\n    Lamp : BOOL;\nEND_VAR", body: motorMain },
    { name: "Util", kind: "function", language: "st", return_type: "INT", body: "Util := 1;" },
  ],
};
const doc: ProjectDocument = { name: "demo", revision: "r1", modified: "2024-05-01T10:00:00Z", project };

function fakeApi(overrides: Partial<ProjectApi> = {}): ProjectApi {
  return {
    getProject: vi.fn(async () => doc),
    saveProject: vi.fn(async () => ({ revision: "r2", modified: "2024-05-02T10:00:00Z" })),
    getLibrary: vi.fn(async () => []),
    getSymbols: vi.fn(async (_p: string, pou: string) => ({ pou, symbols: [], globals: [], diagnostics: [] })),
    ...overrides,
  };
}

async function opened(api = fakeApi(), storage: Storage = new MemoryStorage()) {
  const store = createWorkspaceStore(api, storage);
  await store.getState().open("demo");
  return { store, api, storage };
}

function editMain(store: Awaited<ReturnType<typeof opened>>["store"]) {
  store.getState().openPou("Main");
  const history = store.getState().histories.Main!;
  const result = deleteElements(history.present, ["seal"]);
  if (!result.ok) throw new Error(result.error);
  store.getState().setLdHistory("Main", record(history, result.body));
}

describe("workspace store", () => {
  it("opens a project and its POUs in tabs with an LD history", async () => {
    const { store, api } = await opened();
    expect(store.getState()).toMatchObject({ status: "ready", name: "demo", revision: "r1", changed: [], tabs: [] });
    store.getState().openPou("Main");
    store.getState().openPou("Util");
    expect(store.getState().tabs).toEqual(["Main", "Util"]);
    expect(store.getState().active).toBe("Util");
    expect(store.getState().histories.Main!.present).toBe(motorMain);
    expect(store.getState().histories.Util).toBeUndefined();
    expect(api.getSymbols).toHaveBeenCalledWith("demo", "Main");
    store.getState().closeTab("Util");
    expect(store.getState()).toMatchObject({ tabs: ["Main"], active: "Main" });
  });

  it("keeps an undo history for a new FBD POU; its edits are unsaved changes", async () => {
    const { store } = await opened();
    expect(store.getState().addPou("Calc", "program", "fbd")).toBeNull();
    const history = store.getState().fbdHistories.Calc!;
    expect(history.present).toEqual({ networks: [] });
    const next = addNetwork(history.present);
    if (!next.ok) throw new Error(next.error);
    store.getState().setFbdHistory("Calc", record(history, next.body));
    expect(store.getState().project!.pous!.find((p) => p.name === "Calc")!.body).toEqual({
      networks: [{ id: "n1", nodes: [], wires: [] }],
    });
    expect(store.getState().changed).toEqual(["Calc"]);
    expect(store.getState().fbdHistories.Calc!.past).toHaveLength(1);
  });

  it("marks edits unsaved and keeps them as a draft that a reload of the page restores", async () => {
    const storage = new MemoryStorage();
    const { store } = await opened(fakeApi(), storage);
    editMain(store);
    expect(store.getState().changed).toEqual(["Main"]);
    const draft = loadDraft("demo", storage)!;
    expect(draft.base_revision).toBe("r1");
    expect(draft.changed).toEqual(["Main"]);

    const again = createWorkspaceStore(fakeApi(), storage);
    await again.getState().open("demo");
    expect(again.getState().changed).toEqual(["Main"]);
    expect(again.getState().restoredAt).toBe(draft.saved_at);
    again.getState().openPou("Main");
    expect(JSON.stringify(again.getState().histories.Main!.present)).not.toContain('"seal"');
  });

  it("saves with If-Match of the base revision and clears the draft", async () => {
    const { store, api, storage } = await opened();
    editMain(store);
    await store.getState().save();
    expect(api.saveProject).toHaveBeenCalledWith("demo", "r1", store.getState().project);
    expect(store.getState()).toMatchObject({
      revision: "r2",
      modified: "2024-05-02T10:00:00Z",
      changed: [],
      saving: false,
    });
    expect(loadDraft("demo", storage)).toBeNull();
  });

  it("reloads the library after a save, so a new or changed function block is offered (issue 9)", async () => {
    const counter = {
      name: "Counter",
      kind: "function_block" as const,
      source: "user" as const,
      inputs: [],
      outputs: [{ name: "Count", type: "INT" }],
      in_outs: [],
      extensible: false,
      return_type: null,
      comment: null,
    };
    const getLibrary = vi.fn<ProjectApi["getLibrary"]>().mockResolvedValueOnce([]).mockResolvedValueOnce([counter]);
    const { store } = await opened(fakeApi({ getLibrary }));
    editMain(store);
    await store.getState().save();
    await vi.waitFor(() => expect(store.getState().library).toEqual([counter]));
    expect(getLibrary).toHaveBeenCalledTimes(2);
  });

  it("reports a conflict, then overwrites with the current revision on request", async () => {
    const conflict = {
      message: "changed",
      base_revision: "r1",
      current_revision: "r7",
      current_modified: "2024-05-03T09:00:00Z",
    };
    const saveProject = vi
      .fn<ProjectApi["saveProject"]>()
      .mockRejectedValueOnce(new SaveConflictError(conflict))
      .mockResolvedValueOnce({ revision: "r8", modified: "2024-05-03T10:00:00Z" });
    const { store } = await opened(fakeApi({ saveProject }));
    editMain(store);
    await store.getState().save();
    expect(store.getState().conflict).toEqual(conflict);
    expect(store.getState().changed).toEqual(["Main"]);
    await store.getState().save(true);
    expect(saveProject.mock.calls[1]![1]).toBe("r7");
    expect(store.getState()).toMatchObject({ conflict: null, revision: "r8", changed: [] });
  });

  it("reloads the saved version, dropping the draft but keeping the tabs", async () => {
    const { store, storage } = await opened();
    editMain(store);
    await store.getState().reload();
    expect(store.getState()).toMatchObject({ changed: [], tabs: ["Main"], active: "Main", restoredAt: null });
    expect(store.getState().histories.Main!.present).toBe(motorMain);
    expect(loadDraft("demo", storage)).toBeNull();
  });

  it("declares a variable in the POU's VAR block and offers it to autocomplete at once", async () => {
    const { store } = await opened();
    store.getState().openPou("Main");
    await vi.waitFor(() => expect(store.getState().symbols.Main).toBeDefined());
    store.getState().declare("Main", { name: "Pump", type: "BOOL" });
    expect(store.getState().project!.pous![0]!.declarations).toBe("VAR\n    Lamp : BOOL;\n    Pump : BOOL;\nEND_VAR");
    expect(store.getState().symbols.Main!.symbols.map((s) => s.name)).toEqual(["Pump"]);
    expect(store.getState().changed).toEqual(["Main"]);
  });

  it("shows a failed open and a failed save", async () => {
    const failing = createWorkspaceStore(
      fakeApi({ getProject: async () => Promise.reject(new Error("project 'demo' not found")) }),
      new MemoryStorage(),
    );
    await failing.getState().open("demo");
    expect(failing.getState()).toMatchObject({ status: "error", error: "project 'demo' not found" });
    const { store } = await opened(fakeApi({ saveProject: async () => Promise.reject(new Error("disk full")) }));
    editMain(store);
    await store.getState().save();
    expect(store.getState()).toMatchObject({ saveError: "disk full", saving: false, changed: ["Main"] });
  });

  it("ignores a draft stored for another project or damaged", () => {
    const storage = new MemoryStorage();
    saveDraft(
      { base_revision: "r1", base_modified: "", saved_at: "", project: { name: "other" }, changed: [] },
      storage,
    );
    storage.setItem("ladderlab:draft:demo", "{not json");
    expect(loadDraft("demo", storage)).toBeNull();
    expect(loadDraft("other", storage)?.base_revision).toBe("r1");
  });
});

describe("project operations", () => {
  it("applies a new working copy as one step, following renamed and closed tabs, and undoes it", async () => {
    const { store, storage } = await opened();
    store.getState().openPou("Main");
    store.getState().openPou("Util");
    const before = store.getState().project!;
    const renamed: Project = {
      ...before,
      pous: before.pous!.map((p) => (p.name === "Main" ? { ...p, name: "Plant" } : p)),
    };
    store.getState().applyOperation("rename Main to Plant", renamed, ["Plant"], { renamed: { Main: "Plant" } });
    expect(store.getState()).toMatchObject({ tabs: ["Plant", "Util"], active: "Util", changed: ["Plant"] });
    expect(store.getState().histories.Plant?.present).toEqual(motorMain);
    expect(loadDraft("demo", storage)?.project.pous?.[0]?.name).toBe("Plant");
    const deleted: Project = { ...renamed, pous: renamed.pous!.filter((p) => p.name !== "Util") };
    store.getState().applyOperation("delete Util", deleted, ["Util"], { closed: ["Util"] });
    expect(store.getState()).toMatchObject({ tabs: ["Plant"], active: "Plant", changed: ["Plant", "Util"] });
    store.getState().undoOperation();
    expect(store.getState()).toMatchObject({ tabs: ["Plant", "Util"], active: "Util", changed: ["Plant"], undo: null });
    expect(store.getState().project).toEqual(renamed);
  });
});
