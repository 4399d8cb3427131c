// The project tree's Global variable lists section (CODESYS's GVLs): each list opens in its tab; its "⋯" menu
// renames it everywhere (its qualifier in every GVL.x too) or deletes it, listing what uses its name; New list
// adds one. Each is one undoable step of the working copy, through the POUs' dialogs (dialogs.tsx).
import { useMemo } from "react";
import type { GlobalVariableList } from "../generated/api";
import { gvlTab, newGvlProblem, withNewGvl } from "../store/gvls";
import { useWorkspace, workspaceStore } from "../store/project";
import { NewNameForm } from "../ui/NewNameForm";
import { TreeActions } from "../ui/TreeActions";
import { DeleteDialog, RenameDialog } from "./lazyDialogs";
import { gvlOperations } from "./operations";

const NO_GVLS: GlobalVariableList[] = [];

export function GvlsTree() {
  const gvls = useWorkspace((s) => s.project?.gvls ?? NO_GVLS);
  const active = useWorkspace((s) => s.active);
  const changed = useWorkspace((s) => s.changed);
  const add = (wanted: string): string | null => {
    const ws = workspaceStore.getState();
    if (!ws.project) return null;
    const problem = newGvlProblem(ws.project, wanted);
    if (problem) return problem;
    ws.setProjectPart(gvlTab(wanted), (project) => withNewGvl(project, wanted));
    ws.openPou(gvlTab(wanted));
    return null;
  };
  return (
    <section aria-label="Global variable lists">
      <h3>Global variable lists</h3>
      {gvls.length ? (
        <ul>
          {gvls.map((g) => (
            <li key={g.name} className="tree-row">
              <button
                type="button"
                className="tree-item"
                aria-current={active === gvlTab(g.name) ? "true" : undefined}
                onClick={() => workspaceStore.getState().openPou(gvlTab(g.name))}
              >
                <span className="tree-name">{g.name}</span>
                <span className="lang">GVL</span>
                {g.qualified_only ? <span className="tree-meta">qualified only</span> : null}
                {changed.includes(gvlTab(g.name)) ? (
                  <span className="unsaved" aria-label="unsaved changes">
                    ●
                  </span>
                ) : null}
              </button>
              <GvlActions name={g.name} />
            </li>
          ))}
        </ul>
      ) : (
        <p className="tree-empty">none</p>
      )}
      <NewNameForm formLabel="New global variable list" inputLabel="List name" buttonLabel="New list" create={add} />
    </section>
  );
}

function GvlActions({ name }: { name: string }) {
  const operations = useMemo(() => gvlOperations(name), [name]);
  return (
    <TreeActions
      item={`list ${name}`}
      entries={[
        { action: "rename", label: "Rename…" },
        { action: "delete", label: "Delete…" },
      ]}
      dialog={(action, close) =>
        action === "rename" ? (
          <RenameDialog current={name} isPou={false} tabOf={gvlTab} onClose={close} />
        ) : (
          <DeleteDialog name={`global variable list ${name}`} item={operations} onClose={close} />
        )
      }
    />
  );
}
