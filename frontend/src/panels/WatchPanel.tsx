// The watch list: variables by path (typed, or dragged from a diagram) with their live values;
// each row writes, forces and releases like the diagram's context menu.
import { useState, type FormEvent } from "react";
import { formatValue, parseValue, pathKey } from "../online/monitor";
import { useOnline, onlineStore } from "../online/store";

/** The live value of a path, with an F when it is forced (a table cell of the watch list and the I/O view). */
export function LiveValue({ path }: { path: string }) {
  const value = useOnline((s) => s.monitor.values[pathKey(path)]);
  const type = useOnline((s) => s.monitor.types[pathKey(path)]);
  const forced = useOnline((s) => s.monitor.forced.has(pathKey(path)));
  const online = useOnline((s) => s.phase === "online");
  return (
    <td className={`watch-value${value === true ? " watch-true" : ""}`} aria-label={`Value of ${path}`}>
      {online ? formatValue(value, type) : "—"}
      {forced ? (
        <span className="watch-forced-mark" title="forced">
          {" "}
          F
        </span>
      ) : null}
    </td>
  );
}

/** Write, force and release a path (and, given `onRemove`, a × that removes its row). */
export function ValueCommands({ path, onRemove }: { path: string; onRemove?: () => void }) {
  const forced = useOnline((s) => s.monitor.forced.has(pathKey(path)));
  const online = useOnline((s) => s.phase === "online");
  const [text, setText] = useState("");
  const s = onlineStore.getState();
  const submit = (e: FormEvent, action: "write" | "force") => {
    e.preventDefault();
    if (!text.trim()) return;
    (action === "write" ? s.write : s.force)(path, parseValue(text));
    setText("");
  };
  return (
    <form className="watch-edit" onSubmit={(e) => submit(e, "write")}>
      <input
        aria-label={`New value for ${path}`}
        value={text}
        onChange={(e) => setText(e.target.value)}
        disabled={!online}
        spellCheck={false}
      />
      <button type="submit" disabled={!online || !text.trim()}>
        Write
      </button>
      <button type="button" disabled={!online || !text.trim()} onClick={(e) => submit(e, "force")}>
        Force
      </button>
      <button type="button" disabled={!online || !forced} onClick={() => s.unforce(path)}>
        Release
      </button>
      {onRemove ? (
        <button type="button" aria-label={`Remove ${path}`} onClick={onRemove}>
          ×
        </button>
      ) : null}
    </form>
  );
}

function WatchRow({ path }: { path: string }) {
  const forced = useOnline((s) => s.monitor.forced.has(pathKey(path)));
  return (
    <tr className={forced ? "watch-forced" : undefined} data-path={pathKey(path)}>
      <td className="watch-path">{path}</td>
      <LiveValue path={path} />
      <td>
        <ValueCommands path={path} onRemove={() => onlineStore.getState().removeWatch(path)} />
      </td>
    </tr>
  );
}

export function WatchPanel() {
  const watch = useOnline((s) => s.watch);
  const [text, setText] = useState("");
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
          <thead>
            <tr>
              <th>Variable</th>
              <th>Value</th>
              <th>Write / force</th>
            </tr>
          </thead>
          <tbody>
            {watch.map((p) => (
              <WatchRow key={pathKey(p)} path={p} />
            ))}
          </tbody>
        </table>
      ) : (
        <p className="panel-empty">Type a path such as MAIN.Motor, or drag a variable from the diagram.</p>
      )}
    </div>
  );
}
