// The cross-reference panel's state (zustand): the list of the saved project, the filter, and the
// entry "Find all references" asked for. The request is injected for tests.
import { useStore } from "zustand";
import { createStore, type StoreApi } from "zustand/vanilla";
import type { XrefEntry, XrefList } from "../generated/api";
import { panelsStore } from "../store/panels";
import { workspaceStore } from "../store/project";
import { getXref } from "./api";
import { entryKey, entryOf, rootOf } from "./model";

export interface XrefState {
  project: string | null;
  entries: XrefEntry[] | null;
  loading: boolean;
  error: string | null;
  filter: string;
  /** The entry whose references are shown first and open (by entryKey). */
  focused: string | null;
  load(project: string): Promise<void>;
  setFilter(text: string): void;
  /** Lists the references of `operand` as used in `pou` (default: the open POU) and shows the panel. */
  find(operand: string, pou?: string | null): Promise<void>;
}

export function createXrefStore(request: (project: string) => Promise<XrefList> = getXref): StoreApi<XrefState> {
  let call = 0;
  return createStore<XrefState>()((set, get) => ({
    project: null,
    entries: null,
    loading: false,
    error: null,
    filter: "",
    focused: null,
    async load(project) {
      const mine = ++call;
      set({ project, loading: true, error: null });
      try {
        const list = await request(project);
        if (mine === call) set({ entries: list.entries, loading: false });
      } catch (error) {
        if (mine === call) set({ loading: false, error: error instanceof Error ? error.message : String(error) });
      }
    },
    setFilter: (filter) => set({ filter, focused: null }),
    async find(operand, pou) {
      const workspace = workspaceStore.getState();
      const project = workspace.name;
      panelsStore.getState().show("xref");
      if (!project) return;
      await get().load(project);
      const entry = entryOf(get().entries ?? [], operand, pou ?? workspace.active);
      set({ filter: entry?.name ?? rootOf(operand) ?? operand, focused: entry ? entryKey(entry) : null });
    },
  }));
}

export const xrefStore = createXrefStore();

export function useXref<T>(selector: (s: XrefState) => T): T {
  return useStore(xrefStore, selector);
}

/** The context-menu item of the diagram editors for an operand. */
export const referencesItem = (operand: string) => ({
  id: "find-references",
  label: `Find all references of ${rootOf(operand) ?? operand}`,
  run: () => void xrefStore.getState().find(operand),
});
