// The watch list: variables by path (typed, dragged from a diagram, or added from a box or the
// Variables view) with their live values. Programs, FB instances, structures and arrays expand into
// their members (ON-10); every row writes, forces, releases and prepares values in place. The list and
// what is expanded are kept per project (app/session.ts).
import { useState, type FormEvent } from "react";
import { pathKey } from "../online/monitor";
import { onlineStore, useOnline } from "../online/store";
import { TreeHead, VariableRow, type Expansion } from "./VariableTree";

function WatchRoot({ path, expansion }: { path: string; expansion: Expansion }) {
  const composite = useOnline((s) => {
    const value = s.monitor.values[pathKey(path)];
    return typeof value === "object" && value !== null;
  });
  const pointer = useOnline((s) => s.monitor.types[pathKey(path)]?.name === "REF_TO");
  return (
    <VariableRow
      node={{ name: path, path, type: null, expandable: composite || pointer, pointer }}
      depth={0}
      expansion={expansion}
      actions={
        <button type="button" aria-label={`Remove ${path}`} onClick={() => onlineStore.getState().removeWatch(path)}>
          ×
        </button>
      }
    />
  );
}

export function WatchPanel() {
  const watch = useOnline((s) => s.watch);
  const expanded = useOnline((s) => s.watchExpanded);
  const [text, setText] = useState("");
  const expansion: Expansion = {
    isOpen: (path) => expanded.includes(pathKey(path)),
    toggle: (path) => onlineStore.getState().toggleWatchExpanded(path),
  };
  const add = (e: FormEvent) => {
    e.preventDefault();
    if (!text.trim()) return;
    onlineStore.getState().addWatch(text);
    setText("");
  };
  return (
    <div className="watch">
      <form className="watch-add" onSubmit={add}>
        <input
          aria-label="Variable path to watch"
          placeholder="MAIN.Motor (or drag a variable here)"
          value={text}
          onChange={(e) => setText(e.target.value)}
          spellCheck={false}
        />
        <button type="submit" disabled={!text.trim()}>
          Add
        </button>
      </form>
      {watch.length ? (
        <table className="watch-table" aria-label="Watch list">
          <TreeHead />
          <tbody>
            {watch.map((p) => (
              <WatchRoot key={pathKey(p)} path={p} expansion={expansion} />
            ))}
          </tbody>
        </table>
      ) : (
        <p className="panel-empty">Type a path such as MAIN.Motor, or drag a variable from the diagram.</p>
      )}
    </div>
  );
}
