// How a project item (a POU, a type, a global variable or list, a task) is deleted or duplicated: the description the
// tree's dialogs (dialogs.tsx) are driven by, and the operations of a POU and of a global variable.
import type { Pou, Project } from "../generated/api";
import { copyName } from "../iec/identifier";
import { onlineStore } from "../online/store";
import { withoutGlobalIn } from "../store/globals";
import { gvlTab, withoutGvl } from "../store/gvls";
import { workspaceStore } from "../store/project";
import { traceStore } from "../trace/store";
import { duplicated, globalReferences, referencesTo, sessionUses, type Use } from "./refactor";

/** How a project item is deleted, for the delete dialog. */
export interface DeleteOperations {
  /** What refers to the item (deleting it breaks those places). */
  references(project: Project): Promise<Use[]>;
  /** The working copy without the item. */
  remove(project: Project): Project;
  /** What else deleting it does, in words (a task's runs stop), or null. */
  consequence?(project: Project): string | null;
  /** The unsaved-changes keys a change of the item marks, and the tabs deleting it closes. */
  changed: string[];
  closed?: string[];
}

/** How a project item is deleted and duplicated, for the delete and duplicate dialogs. */
export interface ItemOperations extends DeleteOperations {
  /** The name a copy gets unless the user types another. */
  copyName(project: Project): string;
  /** The working copy with a copy called `name`, or why not (a thrown error says so too). */
  copy(project: Project, name: string): Promise<Project | string>;
  /** The keys a new copy marks unsaved, and what opens it. */
  copyChanged(name: string): string[];
  open?(name: string): void;
}

/** The watch list rows, traced variables and trace trigger of this session whose path starts with `name`. */
export function sessionUsesOf(name: string) {
  const trace = traceStore.getState();
  return sessionUses(name, onlineStore.getState().watch, trace.paths, trace.trigger.path);
}

/** The operations of a POU (the server's refactoring finds its uses and copies it). */
export const pouOperations = (pou: Pou): ItemOperations => ({
  references: async (project) => [...(await referencesTo(project, pou.name)), ...sessionUsesOf(pou.name)],
  remove: (project) => ({ ...project, pous: (project.pous ?? []).filter((p) => p.name !== pou.name) }),
  changed: [pou.name],
  closed: [pou.name],
  copyName: (project) =>
    copyName(
      (project.pous ?? []).map((p) => p.name),
      pou.name,
    ),
  copy: (project, name) => duplicated(project, pou.name, name),
  copyChanged: (name) => [name],
  open: (name) => workspaceStore.getState().openPou(name),
});

/** The operations of a global variable (of the global variable list `list`, or of no list): its uses (every POU,
 * diagram, task, panel, watch and trace path but its own declaration) and the globals without it. */
export const globalOperations = (name: string, list: string | null = null): DeleteOperations => ({
  references: async (project) => [...(await globalReferences(project, name, list)), ...sessionUsesOf(name)],
  remove: (project) => withoutGlobalIn(project, name, list),
  changed: [list === null ? "part:globals" : gvlTab(list)],
});

/** The operations of a global variable list: the uses of its name (``GVL.x``) and the project without it. */
export const gvlOperations = (list: string): DeleteOperations => ({
  references: (project) => referencesTo(project, list),
  remove: (project) => withoutGvl(project, list),
  changed: [gvlTab(list)],
  closed: [gvlTab(list)],
});
