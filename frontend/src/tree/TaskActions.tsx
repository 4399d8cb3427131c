// The "⋯" menu of a task in the project tree: rename it (one undoable step; nothing else names a task).
import { useState, type FormEvent } from "react";
import { Dialog, DialogFooter, TreeActions } from "../ui/TreeActions";
import { workspaceStore } from "../store/project";
import { renameTask } from "../store/tasks";

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
    ws.applyOperation(`rename task ${task} to ${name.trim()}`, next, ["Tasks"]);
    onClose();
  };
  return (
    <Dialog title={`Rename task ${task}`} onClose={onClose}>
      <form onSubmit={submit}>
        <input
          aria-label="New name"
          autoFocus
          value={name}
          onChange={(e) => setName(e.target.value)}
          spellCheck={false}
        />
        <DialogFooter error={error} submit="Rename" onClose={onClose} />
      </form>
    </Dialog>
  );
}

export function TaskActions({ task }: { task: string }) {
  return (
    <TreeActions
      item={`task ${task}`}
      entries={[{ action: "rename", label: "Rename…" }]}
      dialog={(_, close) => <RenameTaskDialog task={task} onClose={close} />}
    />
  );
}
