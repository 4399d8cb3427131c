// Unsaved changes survive a page reload: the working copy of a project is kept in localStorage,
// with the revision it is based on, until a save succeeds or the user discards it.
import type { Project } from "../generated/api";

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

export function loadDraft(project: string, storage: Storage = localStorage): Draft | null {
  try {
    const text = storage.getItem(key(project));
    const draft = text ? (JSON.parse(text) as Draft) : null;
    return draft && typeof draft.base_revision === "string" && draft.project?.name === project ? draft : null;
  } catch {
    return null;
  }
}

/** Stores the draft; false when the browser refused (quota), so the caller can say so. */
export function saveDraft(draft: Draft, storage: Storage = localStorage): boolean {
  try {
    storage.setItem(key(draft.project.name), JSON.stringify(draft));
    return true;
  } catch {
    return false;
  }
}

export function removeDraft(project: string, storage: Storage = localStorage): void {
  storage.removeItem(key(project));
}
