// The project tree's item menus (POUs, tasks, test files): the "⋯" button with its menu, and the modal
// dialog an entry opens with its footer (the last attempt's error, submit, Cancel).
import { useState, type ReactNode } from "react";
import { FormError } from "./FormError";
import { ConfirmButtons } from "./NameField";

/** A modal dialog of the project tree's menus (Escape closes it). */
export function Dialog({ title, children, onClose }: { title: string; children: ReactNode; onClose(): void }) {
  return (
    <div className="ld-dialog-backdrop" onKeyDown={(e) => e.key === "Escape" && onClose()}>
      <div className="ld-dialog project-dialog" role="dialog" aria-label={title}>
        <h2>{title}</h2>
        {children}
      </div>
    </div>
  );
}

/** One entry of a tree item's menu: the action it opens, its label, and why it is disabled (if it is). */
export interface MenuEntry<A extends string> {
  action: A;
  label: string;
  disabledBecause?: string;
}

/** The "⋯" button of an item of the project tree (a POU, a test file) and its menu; a chosen entry opens the
 * dialog `dialog` returns for it, which calls `close` when done. */
export function TreeActions<A extends string>({
  item,
  entries,
  dialog,
}: {
  item: string;
  entries: readonly MenuEntry<A>[];
  dialog(action: A, close: () => void): ReactNode;
}) {
  const [menu, setMenu] = useState(false);
  const [action, setAction] = useState<A | null>(null);
  const close = () => setAction(null);
  return (
    <span className="tree-actions">
      <button
        type="button"
        className="tree-actions-button"
        aria-label={`Actions for ${item}`}
        aria-haspopup="menu"
        aria-expanded={menu}
        onClick={() => setMenu((m) => !m)}
      >
        ⋯
      </button>
      {menu ? (
        <div className="tree-menu" role="menu" aria-label={`${item} actions`}>
          {entries.map((entry) => (
            <button
              key={entry.action}
              type="button"
              role="menuitem"
              disabled={entry.disabledBecause !== undefined}
              title={entry.disabledBecause}
              onClick={() => {
                setMenu(false);
                setAction(entry.action);
              }}
            >
              {entry.label}
            </button>
          ))}
        </div>
      ) : null}
      {action !== null ? dialog(action, close) : null}
    </span>
  );
}

/** The end of a dialog's form: the error of the last attempt (if any), the submit button and Cancel. */
export function DialogFooter({ error, submit, onClose }: { error: string | null; submit: string; onClose(): void }) {
  return (
    <>
      <FormError error={error} />
      <ConfirmButtons confirm={submit} onClose={onClose} />
    </>
  );
}
