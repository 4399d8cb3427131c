// Unsaved changes survive a page reload: the working copy of a project is kept in localStorage,
// with the revision it is based on, until a save succeeds or the user discards it.
import type { Project } from "../generated/api";
import { migratedChanged } from "./parts";

export interface Draft {
  /** The revision the changes are based on; a save names it in If-Match. */
  base_revision: string;
  base_modified: string;
  saved_at: string;
  project: Project;
  /** POUs changed since the base revision. */
  changed: string[];
}

const key = (project: string) => `ladderlab:draft:${project}`;
/** 2: the project parts' unsaved marks are keyed `part:<id>` (store/parts.ts); a draft without it has the old keys. */
const DRAFT_VERSION = 2;

export function loadDraft(project: string, storage: Storage = localStorage): Draft | null {
  try {
    const text = storage.getItem(key(project));
    const draft = text ? (JSON.parse(text) as Draft) : null;
    if (!draft || typeof draft.base_revision !== "string" || draft.project?.name !== project) return null;
    if ((draft as { version?: unknown }).version === DRAFT_VERSION) return draft;
    const pous = new Set((draft.project.pous ?? []).map((p) => p.name));
    return { ...draft, changed: migratedChanged(draft.changed ?? [], (name) => pous.has(name)) };
  } catch {
    return null;
  }
}

/** Stores the draft; false when the browser refused (quota), so the caller can say so. */
export function saveDraft(draft: Draft, storage: Storage = localStorage): boolean {
  try {
    storage.setItem(key(draft.project.name), JSON.stringify({ ...draft, version: DRAFT_VERSION }));
    return true;
  } catch {
    return false;
  }
}

export function removeDraft(project: string, storage: Storage = localStorage): void {
  storage.removeItem(key(project));
}
