// The "⋯" menu of a task in the project tree: rename it, duplicate it (with its program instances under new
// names), delete it. Each is one undoable step (nothing else names a task, so only the tasks change); the
// duplicate and delete dialogs are the POUs' (PouActions).
import { useMemo, useState, type FormEvent } from "react";
import { NameField } from "../ui/NameField";
import { Dialog, DialogFooter, TreeActions } from "../ui/TreeActions";
import { DeleteDialog, DuplicateDialog } from "./lazyDialogs";
import type { ItemOperations } from "./operations";
import { workspaceStore } from "../store/project";
import { duplicateTask, renameTask, runsOf, taskCopyName, withoutTask } from "../store/tasks";

const TASKS = ["part:tasks"];

const taskOperations = (task: string): ItemOperations => ({
  references: async () => [],
  remove: (project) => withoutTask(project, task),
  consequence: (project) => {
    const runs = runsOf(project)
      .resources.flatMap((r) => r.tasks)
      .find((t) => t.name === task)?.instances;
    return runs?.length ? `${task} runs ${runs.join(", ")}: those runs stop with it.` : null;
  },
  changed: TASKS,
  copyName: (project) => taskCopyName(project, task),
  copy: async (project, name) => duplicateTask(project, task, name),
  copyChanged: () => TASKS,
});

function RenameTaskDialog({ task, onClose }: { task: string; onClose(): void }) {
  const [name, setName] = useState(task);
  const [error, setError] = useState<string | null>(null);
  const submit = (e: FormEvent) => {
    e.preventDefault();
    const ws = workspaceStore.getState();
    if (!ws.project) return;
    const next = renameTask(ws.project, task, name);
    if (typeof next === "string") {
      setError(next);
      return;
    }
    ws.applyOperation(`rename task ${task} to ${name.trim()}`, next, TASKS);
    onClose();
  };
  return (
    <Dialog title={`Rename task ${task}`} onClose={onClose}>
      <form onSubmit={submit}>
        <NameField label="New name" value={name} onChange={setName} />
        <DialogFooter error={error} submit="Rename" onClose={onClose} />
      </form>
    </Dialog>
  );
}

export function TaskActions({ task }: { task: string }) {
  const operations = useMemo(() => taskOperations(task), [task]);
  return (
    <TreeActions
      item={`task ${task}`}
      entries={[
        { action: "rename", label: "Rename…" },
        { action: "duplicate", label: "Duplicate…" },
        { action: "delete", label: "Delete…" },
      ]}
      dialog={(action, close) =>
        action === "rename" ? (
          <RenameTaskDialog task={task} onClose={close} />
        ) : action === "duplicate" ? (
          <DuplicateDialog name={`task ${task}`} item={operations} onClose={close} />
        ) : (
          <DeleteDialog name={`task ${task}`} item={operations} onClose={close} />
        )
      }
    />
  );
}
