// The "⋯" menu of a user type (the project tree under Types, and the Types editor's list): rename it
// everywhere, duplicate it, delete it (listing every variable, STRUCT member, other type and FB pin that uses
// it, by POU and line). Each is one undoable step; the dialogs are the POUs' (dialogs.tsx).
import { useMemo } from "react";
import { TreeActions } from "../ui/TreeActions";
import { DeleteDialog, DuplicateDialog, RenameDialog } from "./lazyDialogs";
import type { ItemOperations } from "./operations";
import { typeReferences } from "./refactor";
import { typeCopyName, typeRows, withoutTypeIn, withTypeCopyIn } from "../store/types";
import { workspaceStore } from "../store/project";
import { panelsStore } from "../store/panels";

const TYPES = ["part:types"];

const typeOperations = (type: string): ItemOperations => ({
  references: (project) => typeReferences(project, type),
  remove: (project) => withoutTypeIn(project, type),
  changed: TYPES,
  copyName: (project) => typeCopyName(project, type),
  copy: async (project, name) => withTypeCopyIn(project, type, name),
  copyChanged: () => TYPES,
});

export function TypeActions({ type, disabledBecause }: { type: string; disabledBecause?: string }) {
  const operations = useMemo(() => typeOperations(type), [type]);
  return (
    <TreeActions
      item={`type ${type}`}
      entries={[
        { action: "rename", label: "Rename…", disabledBecause },
        { action: "duplicate", label: "Duplicate…", disabledBecause },
        { action: "delete", label: "Delete…", disabledBecause },
      ]}
      dialog={(action, close) =>
        action === "rename" ? (
          <RenameDialog current={type} isPou={false} onClose={close} />
        ) : action === "duplicate" ? (
          <DuplicateDialog name={`type ${type}`} item={operations} onClose={close} />
        ) : (
          <DeleteDialog name={`type ${type}`} item={operations} onClose={close} />
        )
      }
    />
  );
}

/** The user types under Types in the project tree, each with its menu; choosing one shows it in the Types
 * editor. */
export function TypesInTree({ text }: { text: string }) {
  const rows = useMemo(() => typeRows(text), [text]);
  if (!rows.length) return null;
  const show = (line: number) => {
    workspaceStore.getState().openPou("part:types");
    panelsStore.getState().reveal({ pou: "part:types", line });
  };
  return (
    <ul className="tree-members" aria-label="User types">
      {rows.map((r) => (
        <li key={`${r.name}:${r.line}`} className="tree-row">
          <button type="button" className="tree-item tree-member" onClick={() => show(r.line)}>
            <span className="tree-kind">T</span>
            <span className="tree-name">{r.name}</span>
          </button>
          <TypeActions type={r.name} />
        </li>
      ))}
    </ul>
  );
}
