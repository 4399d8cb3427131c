// The online log (ON-15): run/stop, writes, forces, releases, breakpoint hits, watchdog trips and
// runtime errors as the simulation logs them (its whole log again after a reconnect), and this
// browser's own notes (refused requests, a lost connection); each with its scan and virtual time.
// Filter by kind; export what is shown as CSV.
import { useEffect, useMemo, useRef, useState } from "react";
import { downloadText } from "../ui/download";
import { LOG_KINDS, type LogEntry, type LogKind } from "../online/monitor";
import { useOnline } from "../online/store";
import { formatClock } from "../online/values";
import { csvField } from "../trace/csv";

/** Where an entry happened, in words: POU, instance, network, element, line. */
export function placeOf(entry: Pick<LogEntry, "at">): string {
  const at = entry.at;
  if (!at) return "";
  return [
    at.pou,
    at.instance && at.instance.toUpperCase() !== at.pou.toUpperCase() ? at.instance : null,
    at.network ? `network ${at.network}` : null,
    at.element ? `element ${at.element}` : null,
    at.line != null ? `line ${at.line}` : null,
  ]
    .filter(Boolean)
    .join(", ");
}

/** The entries as CSV: scan, virtual time, kind, level, message, place (RFC 4180 quoting). */
export function logCsv(entries: readonly LogEntry[]): string {
  const rows = [["scan", "time_ms", "kind", "level", "message", "where"].join(",")];
  for (const e of entries)
    rows.push(
      [String(e.scan), String(e.timeMs), e.kind, e.level, e.message, placeOf(e)].map((f) => csvField(f)).join(","),
    );
  return rows.join("\n") + "\n";
}

export function LogPanel() {
  const log = useOnline((s) => s.monitor.log);
  const project = useOnline((s) => s.project);
  const [hidden, setHidden] = useState<ReadonlySet<LogKind>>(new Set());
  const shown = useMemo(() => log.filter((e) => !hidden.has(e.kind)), [log, hidden]);
  const counts = useMemo(() => {
    const by = new Map<LogKind, number>();
    for (const e of log) by.set(e.kind, (by.get(e.kind) ?? 0) + 1);
    return by;
  }, [log]);
  const end = useRef<HTMLLIElement>(null);
  // The newest entry scrolls into view (a block body: an effect's return value is its cleanup).
  useEffect(() => {
    end.current?.scrollIntoView?.({ block: "nearest" });
  }, [shown]);

  const toggle = (kind: LogKind) => {
    const next = new Set(hidden);
    if (!next.delete(kind)) next.add(kind);
    setHidden(next);
  };
  return (
    <div className="online-log-panel">
      <div className="log-bar" role="group" aria-label="Show log entries of kind">
        {LOG_KINDS.map((kind) => (
          <label key={kind} className={`log-kind log-kind-${kind}`}>
            <input type="checkbox" checked={!hidden.has(kind)} onChange={() => toggle(kind)} />
            {kind} ({counts.get(kind) ?? 0})
          </label>
        ))}
        <button
          type="button"
          disabled={!shown.length}
          onClick={() => downloadText(`${project ?? "simulation"}-log.csv`, logCsv(shown), "text/csv;charset=utf-8")}
        >
          Export CSV
        </button>
      </div>
      {!log.length ? (
        <p className="panel-empty">Nothing logged yet.</p>
      ) : (
        <ol className="online-log" aria-label="Online log">
          {shown.map((entry, i) => (
            <li
              key={entry.seq}
              ref={i === shown.length - 1 ? end : undefined}
              className={`log-${entry.level} log-entry-${entry.kind}`}
              data-kind={entry.kind}
            >
              <span className="log-scan" title="scan">
                #{entry.scan}
              </span>
              <span className="log-time" title="virtual time">
                {formatClock(entry.timeMs)}
              </span>
              <span className="log-kind-name">{entry.kind}</span>
              <span className="log-message">{entry.message}</span>
              {entry.at ? <span className="log-at">{placeOf(entry)}</span> : null}
            </li>
          ))}
        </ol>
      )}
    </div>
  );
}
