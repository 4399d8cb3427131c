// Variables as rows of a tree table (the watch list and the Variables view, ON-10): name (programs,
// FB instances, structures and arrays expand; a pointer shows its own value, ADR(a[1]), and expands to
// what it points to, p^, as CODESYS shows it online: ON-11), value (forced and prepared marked), type, and
// in-place write / force / release. Double-clicking a value prepares one (CODESYS): a BOOL toggles, another
// value is typed into the row's field.
import { useRef, useState, type FormEvent, type ReactNode } from "react";
import { useShallow } from "zustand/react/shallow";
import { pathKey } from "../online/monitor";
import { operandCommands } from "../online/operandCommands";
import { shownPath } from "../online/shown";
import { onlineStore, useOnline } from "../online/store";
import { ValueTag } from "../online/ValueTag";
import { parseValue } from "../online/values";
import { hasValue, useChildren, useSubscribedPaths } from "./variables";

export interface TreeNode {
  name: string;
  path: string;
  /** IEC type text; null when not known yet (a watched path before its first value). */
  type: string | null;
  expandable: boolean;
  /** A REF_TO / POINTER TO / REFERENCE TO: it has a value (set by the program only) and expands to `p^`. */
  pointer?: boolean;
}

/** Which rows of a tree are expanded, by upper-case path. */
export interface Expansion {
  isOpen(path: string): boolean;
  toggle(path: string): void;
}

/** Commands on a path as typed (the tree's paths are simulation paths already). */
const commands = operandCommands((path) => path);

export function VariableRow({
  node,
  depth,
  expansion,
  actions,
  lead,
}: {
  node: TreeNode;
  depth: number;
  expansion: Expansion;
  /** More controls at the row's end (the watch list's remove button). */
  actions?: ReactNode;
  /** Cells before the name (the I/O view's area and address). */
  lead?: ReactNode;
}) {
  const key = pathKey(node.path);
  const shown = useOnline(useShallow((s) => shownPath(s.monitor, key, s.prepared)));
  const type = useOnline((s) => s.monitor.types[key]?.name);
  const online = useOnline((s) => s.phase === "online");
  const [text, setText] = useState("");
  const input = useRef<HTMLInputElement>(null);
  const open = node.expandable && expansion.isOpen(node.path);
  const s = onlineStore.getState();
  const submit = (e: FormEvent, action: "write" | "force") => {
    e.preventDefault();
    if (!text.trim()) return;
    (action === "write" ? s.write : s.force)(node.path, parseValue(text));
    setText("");
  };
  const prepare = () => {
    if (!online || node.expandable) return; // a pointer is set by the program, not online
    if (!commands.prepare(node.path)) input.current?.focus(); // not a BOOL: type the value, Enter prepares
  };
  return (
    <>
      <tr className={shown?.forced ? "watch-forced" : undefined} data-path={key} aria-level={depth + 1}>
        {lead}
        <td className="watch-path" style={{ paddingLeft: `${0.5 + depth * 1.1}rem` }}>
          {node.expandable ? (
            <button
              type="button"
              className="tree-toggle"
              aria-expanded={open}
              aria-label={`${open ? "Collapse" : "Expand"} ${node.path}`}
              onClick={() => expansion.toggle(node.path)}
            >
              {open ? "▾" : "▸"}
            </button>
          ) : (
            <span className="tree-toggle-space" />
          )}
          {node.name}
        </td>
        <td className="watch-value" aria-label={`Value of ${node.path}`} onDoubleClick={prepare}>
          {!online ? "—" : !hasValue(node) ? "" : shown ? <ValueTag shown={shown} /> : "…"}
        </td>
        <td className="watch-type">{node.type ?? type ?? ""}</td>
        <td>
          <form
            className="watch-edit"
            onSubmit={(e) => {
              e.preventDefault();
              if (!text.trim()) return;
              commands.prepare(node.path, text); // Enter prepares; F7 forces, Ctrl+F7 writes (or the buttons)
              setText("");
            }}
          >
            {node.expandable ? null : (
              <>
                <input
                  ref={input}
                  aria-label={`New value for ${node.path}`}
                  value={text}
                  onChange={(e) => setText(e.target.value)}
                  disabled={!online}
                  spellCheck={false}
                />
                <button type="button" disabled={!online || !text.trim()} onClick={(e) => submit(e, "write")}>
                  Write
                </button>
                <button type="button" disabled={!online || !text.trim()} onClick={(e) => submit(e, "force")}>
                  Force
                </button>
                <button type="button" disabled={!online || !shown?.forced} onClick={() => s.unforce(node.path)}>
                  Release
                </button>
              </>
            )}
            {actions}
          </form>
        </td>
      </tr>
      {open ? <ChildRows path={node.path} depth={depth + 1} expansion={expansion} /> : null}
    </>
  );
}

/** The members of an expanded row, fetched from the server and subscribed while shown. */
export function ChildRows({ path, depth, expansion }: { path: string; depth: number; expansion: Expansion }) {
  const loaded = useChildren(path, true);
  const children = loaded?.state === "ready" ? loaded.children : [];
  useSubscribedPaths(
    `tree:${pathKey(path)}`,
    children.filter(hasValue).map((c) => c.path),
  );
  if (!loaded || loaded.state === "loading")
    return (
      <tr>
        <td colSpan={4} className="tree-note" style={{ paddingLeft: `${1.6 + depth * 1.1}rem` }}>
          …
        </td>
      </tr>
    );
  if (loaded.state === "error")
    return (
      <tr>
        <td colSpan={4} className="tree-note" role="alert" style={{ paddingLeft: `${1.6 + depth * 1.1}rem` }}>
          {loaded.message}
        </td>
      </tr>
    );
  return (
    <>
      {children.map((child) => (
        <VariableRow key={child.path} node={child} depth={depth} expansion={expansion} />
      ))}
      {loaded.more ? (
        <tr>
          <td colSpan={4} className="tree-note" style={{ paddingLeft: `${1.6 + depth * 1.1}rem` }}>
            {loaded.more} more elements (watch one by its path, e.g. {path}[…])
          </td>
        </tr>
      ) : null}
    </>
  );
}

/** The table head of a variable tree. */
export function TreeHead() {
  return (
    <thead>
      <tr>
        <th>Variable</th>
        <th>Value</th>
        <th>Type</th>
        <th>Write / force</th>
      </tr>
    </thead>
  );
}
