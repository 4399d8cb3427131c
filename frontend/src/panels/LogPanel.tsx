// The online log: the server's log messages (runtime errors, watchdog, forces) and refused
// requests, newest last, with the scan they belong to.
import { useEffect, useRef } from "react";
import { useOnline } from "../online/store";

export function LogPanel() {
  const log = useOnline((s) => s.monitor.log);
  const end = useRef<HTMLLIElement>(null);
  useEffect(() => end.current?.scrollIntoView?.({ block: "nearest" }), [log]);
  if (!log.length) return <p className="panel-empty">Nothing logged yet.</p>;
  return (
    <ol className="online-log" aria-label="Online log">
      {log.map((entry, i) => (
        <li key={entry.seq} ref={i === log.length - 1 ? end : undefined} className={`log-${entry.level}`}>
          <span className="log-scan">#{entry.scan}</span>
          <span className="log-level">{entry.level}</span>
          <span className="log-message">{entry.message}</span>
          {entry.at ? (
            <span className="log-at">
              {[
                entry.at.pou,
                entry.at.network,
                entry.at.element,
                entry.at.line != null ? `line ${entry.at.line}` : null,
              ]
                .filter(Boolean)
                .join(", ")}
            </span>
          ) : null}
        </li>
      ))}
    </ol>
  );
}
