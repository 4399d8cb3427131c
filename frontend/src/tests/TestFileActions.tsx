// The project tree's menu of a test file: rename and delete, each one undoable step of the working copy
// (workspace store's applyOperation), saved with the project (the old tests/<name>.st goes on save).
import { useState, type FormEvent } from "react";
import { ConfirmButtons, NameField } from "../ui/NameField";
import { Dialog, DialogFooter, TreeActions } from "../ui/TreeActions";
import { testNameProblem, testPath, workspaceStore } from "../store/project";

function RenameTestDialog({ name, onClose }: { name: string; onClose(): void }) {
  const [text, setText] = useState(name);
  const [error, setError] = useState<string | null>(null);
  const submit = (e: FormEvent) => {
    e.preventDefault();
    const ws = workspaceStore.getState();
    const next = text.trim();
    const problem = testNameProblem(ws.project, next, name);
    if (problem) return setError(problem);
    if (!ws.project || next === name) return onClose();
    const tests = (ws.project.tests ?? []).map((t) => (t.name === name ? { ...t, name: next } : t));
    ws.applyOperation(`rename test file ${name} to ${next}`, { ...ws.project, tests }, [testPath(next)], {
      renamed: { [testPath(name)]: testPath(next) },
    });
    onClose();
  };
  return (
    <Dialog title={`Rename ${testPath(name)}`} onClose={onClose}>
      <form onSubmit={submit}>
        <label>
          New name <NameField label="New test file name" value={text} onChange={setText} />
        </label>
        <DialogFooter error={error} submit="Rename" onClose={onClose} />
      </form>
    </Dialog>
  );
}

function DeleteTestDialog({ name, onClose }: { name: string; onClose(): void }) {
  const remove = () => {
    const ws = workspaceStore.getState();
    if (!ws.project) return;
    const tests = (ws.project.tests ?? []).filter((t) => t.name !== name);
    ws.applyOperation(`delete test file ${name}`, { ...ws.project, tests }, [testPath(name)], {
      closed: [testPath(name)],
    });
    onClose();
  };
  return (
    <Dialog title={`Delete ${testPath(name)}`} onClose={onClose}>
      <p>The file and its tests leave the project when you save (Undo takes it back until then).</p>
      <ConfirmButtons confirm="Delete" onConfirm={remove} onClose={onClose} />
    </Dialog>
  );
}

/** The "⋯" button of a test file in the tree and its menu. */
export function TestFileActions({ name }: { name: string }) {
  return (
    <TreeActions
      item={testPath(name)}
      entries={[
        { action: "rename", label: "Rename…" },
        { action: "delete", label: "Delete…" },
      ]}
      dialog={(action, close) =>
        action === "rename" ? (
          <RenameTestDialog name={name} onClose={close} />
        ) : (
          <DeleteTestDialog name={name} onClose={close} />
        )
      }
    />
  );
}
