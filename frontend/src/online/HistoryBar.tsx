// Scan history (issue 23): a timeline of the scans the server keeps, in the simulation toolbar. Dragging
// the slider or stepping one scan back or forward (the buttons, or the arrow keys on the slider) shows
// that scan as it was: every watched value, the LD power flow, FBD pins and ST inline values come from
// the server recomputing it, while the live scans go on. "Live" shows them again. The banner over the
// editors says that the diagrams show the past.
import { onlineStore, useOnline } from "./store";

/** The scan the history shows: the one viewed, else the live one. */
export function shownScan(history: { last: number; viewing?: number | null }): number {
  return history.viewing ?? history.last;
}

/** The scan one step from `scan` within the history (null: no such scan). */
export function stepScan(history: { first: number; last: number }, scan: number, by: -1 | 1): number | null {
  const next = scan + by;
  return next < history.first || next > history.last ? null : next;
}

export function HistoryBar() {
  const history = useOnline((s) => s.monitor.history);
  const online = useOnline((s) => s.phase === "online");
  if (!online || !history || history.last < history.first) return null;
  const s = onlineStore.getState();
  const scan = shownScan(history);
  const viewing = history.viewing != null;
  const back = stepScan(history, scan, -1);
  const forward = stepScan(history, scan, 1);
  return (
    <span className={`history-bar${viewing ? " viewing" : ""}`} role="group" aria-label="Scan history">
      <button
        type="button"
        onClick={() => back !== null && s.seek(back)}
        disabled={back === null}
        title="One scan back"
      >
        ◀
      </button>
      <input
        type="range"
        aria-label="Scan"
        min={history.first}
        max={history.last}
        step={1}
        value={scan}
        onChange={(event) => s.seek(Number(event.target.value))}
        title={`History from scan ${history.first} to ${history.last}`}
      />
      <button
        type="button"
        onClick={() => forward !== null && s.seek(forward)}
        disabled={forward === null}
        title="One scan forward"
      >
        ▶
      </button>
      <button type="button" onClick={s.goLive} disabled={!viewing} title="Show the live scans again">
        Live
      </button>
      <span className="history-range" aria-label="History kept">
        from scan {history.first}
      </span>
    </span>
  );
}

/** Over the editors while a past scan is shown: the diagrams' values are that scan's, not live. */
export function HistoryBanner() {
  const viewing = useOnline((s) => (s.phase === "online" ? (s.monitor.history?.viewing ?? null) : null));
  const timeMs = useOnline((s) => s.monitor.timeMs);
  if (viewing === null) return null;
  return (
    <div className="history-banner" role="status" aria-label="History view">
      Viewing scan {viewing} (history) · t = {timeMs} ms · the values are those of that scan; the simulation goes on
      <button type="button" onClick={onlineStore.getState().goLive}>
        Back to live
      </button>
    </div>
  );
}
