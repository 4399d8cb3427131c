// Scan history (issue 23): a timeline of the scans the server keeps, in the simulation toolbar. Dragging
// the slider or stepping one scan back or forward (the buttons, or the arrow keys on the slider) shows
// that scan as it was: every watched value, the LD power flow, FBD pins and ST inline values come from
// the server recomputing it, while the live scans go on. "Live" shows them again. The banner over the
// editors says that the diagrams show the past. "Find" jumps to the previous or next scan where a
// variable changed or a condition (as Run until takes it: Motor, Tank.Level >= 80) became TRUE. "Step into this scan"
// replays the scan shown in the debug code and goes through it network by network or line by line.
import { useEffect, useState } from "react";
import type { HistoryMark } from "../generated/api";
import { findInHistory, historyDiff, historyMarks, historyStep } from "./api";
import { CallStack } from "./CallStack";
import { type HaltPlace, useRevealHalt } from "./useRevealHalt";
import type { Value, Where } from "./protocol";
import { formatValue } from "./values";
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
  const simulation = useOnline((s) => s.simulation);
  const refused = useOnline((s) => s.historyError);
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
        onClick={() => back !== null && void s.seek(back)}
        disabled={back === null}
        title="One scan back"
      >
        ◀
      </button>
      <span className="history-timeline">
        <input
          type="range"
          aria-label="Scan"
          min={history.first}
          max={history.last}
          step={1}
          value={scan}
          onChange={(event) => void s.seek(Number(event.target.value))}
          title={`History from scan ${history.first} to ${history.last}`}
        />
        <HistoryMarks first={history.first} last={history.last} marked={history.marked ?? 0} />
      </span>
      <button
        type="button"
        onClick={() => forward !== null && void s.seek(forward)}
        disabled={forward === null}
        title="One scan forward"
      >
        ▶
      </button>
      <button type="button" onClick={() => void s.goLive()} disabled={!viewing} title="Show the live scans again">
        Live
      </button>
      <span className="history-range" aria-label="History kept">
        {history.recording ? "recording · history only · " : ""}from scan {history.first}
        {(history.branch ?? 1) > 1 ? ` · branch ${history.branch} live` : ""}
      </span>
      {refused ? (
        <span className="history-note" role="alert" aria-label="History refused">
          {refused}
        </span>
      ) : null}
      <HistoryFind scan={scan} />
      {simulation ? (
        <a
          className="history-download"
          href={`/api/simulations/${encodeURIComponent(simulation)}/recording`}
          download
          title="The session as a file: ladderlab replay FILE prints its scans again"
        >
          Download recording
        </a>
      ) : null}
    </span>
  );
}

/** Where a mark sits along the slider, in percent of its width. */
export function markOffset(scan: number, first: number, last: number): number {
  return last > first ? ((scan - first) / (last - first)) * 100 : 0;
}

/** A mark's class: its colour says the most telling thing that happened in its scan (a runtime error, then a
 * breakpoint hit, then a trace trigger; else an input). */
export function markClass(kinds: string[]): string {
  const kind = ["error", "breakpoint", "trigger"].find((k) => kinds.includes(k));
  return kind ? `history-mark ${kind}` : "history-mark";
}

/** Ticks under the slider at the scans with an input (write, force, panel, fault...), a runtime error, a
 * breakpoint hit or a trace trigger; fetched again when the history's `marked` counter grows. A click shows that
 * scan. */
function HistoryMarks({ first, last, marked }: { first: number; last: number; marked: number }) {
  const simulation = useOnline((s) => s.simulation);
  const [marks, setMarks] = useState<HistoryMark[]>([]);
  useEffect(() => {
    if (!simulation) return;
    let current = true;
    historyMarks(simulation)
      .then((found) => current && setMarks(found))
      .catch(() => current && setMarks([]));
    return () => {
      current = false;
    };
  }, [simulation, marked]);
  return (
    <span className="history-marks" aria-label="Marks">
      {marks
        .filter((mark) => mark.scan >= first && mark.scan <= last)
        .map((mark) => (
          <button
            type="button"
            key={mark.scan}
            className={markClass(mark.kinds)}
            data-mark-scan={mark.scan}
            style={{ left: `${markOffset(mark.scan, first, last)}%` }}
            title={`scan ${mark.scan}: ${mark.kinds.join(", ")}`}
            aria-label={`scan ${mark.scan}: ${mark.kinds.join(", ")}`}
            onClick={() => void onlineStore.getState().seek(mark.scan)}
          />
        ))}
    </span>
  );
}

/** What the find field suggests: the first watched variable (or a condition on it), else a generic hint. */
export function findPlaceholder(what: "changed" | "true", watched: string | undefined): string {
  if (!watched) return what === "changed" ? "a variable, e.g. Main.Motor" : "a condition, e.g. Main.Level >= 80";
  return what === "changed" ? watched : `a condition, e.g. on ${watched}`;
}

/** Jump to the previous or next scan where a variable changed or a condition became TRUE. */
function HistoryFind({ scan }: { scan: number }) {
  const [text, setText] = useState("");
  const [what, setWhat] = useState<"changed" | "true">("changed");
  const [note, setNote] = useState<string | null>(null);
  const watched = useOnline((s) => s.watch[0]);
  const find = async (direction: 1 | -1) => {
    const s = onlineStore.getState();
    if (!s.simulation || !text.trim()) return;
    const query = what === "changed" ? { path: text.trim() } : { condition: text.trim() };
    try {
      const found = await findInHistory(s.simulation, scan, direction, query);
      setNote(found === null ? `no scan ${direction > 0 ? "after" : "before"} ${scan} in the history` : null);
      if (found !== null) await s.seek(found);
    } catch (err) {
      setNote(err instanceof Error ? err.message : String(err));
    }
  };
  return (
    <span className="history-find">
      <input
        aria-label="Find in history"
        placeholder={findPlaceholder(what, watched)}
        value={text}
        onChange={(event) => setText(event.target.value)}
        onKeyDown={(event) => {
          if (event.key === "Enter") void find(event.shiftKey ? -1 : 1);
        }}
      />
      <select
        aria-label="Find what"
        value={what}
        onChange={(event) => setWhat(event.target.value as "changed" | "true")}
      >
        <option value="changed">changed</option>
        <option value="true">became TRUE</option>
      </select>
      <button type="button" onClick={() => void find(-1)} title="The previous scan where it happened (Shift+Enter)">
        Previous
      </button>
      <button type="button" onClick={() => void find(1)} title="The next scan where it happened (Enter)">
        Next
      </button>
      {note ? (
        <span className="history-note" role="status" aria-label="History search">
          {note}
        </span>
      ) : null}
    </span>
  );
}

/** Over the editors while a past scan is shown: the diagrams' values are that scan's, not live. */
export interface HistoryBannerProps {
  /** A halt point in words ("MAIN, network 2"), as the debug bar says it. */
  describe(at: Where): string;
  /** Shows a location in its editor (opens the POU, selects the network or the line). */
  reveal(place: HaltPlace): void;
}

export function HistoryBanner({ describe, reveal }: HistoryBannerProps) {
  const viewing = useOnline((s) => (s.phase === "online" ? (s.monitor.history?.viewing ?? null) : null));
  const recording = useOnline((s) => s.monitor.history?.recording ?? false);
  const timeMs = useOnline((s) => s.monitor.timeMs);
  if (viewing === null) return null;
  return (
    <div className="history-banner-area">
      <div className="history-banner" role="status" aria-label="History view">
        Viewing scan {viewing} (history) · t = {timeMs} ms · the values are those of that scan
        {recording ? " of the recording" : "; the simulation goes on"}
        <button type="button" onClick={() => void onlineStore.getState().goLive()}>
          Back to live
        </button>
        <button
          type="button"
          onClick={onlineStore.getState().fork}
          title="Continue from this scan: the simulation takes its state (stopped); the scans after it stay viewable as the earlier branch"
        >
          Continue from here
        </button>
      </div>
      <HistoryStepping viewing={viewing} describe={describe} reveal={reveal} />
      <HistoryCompare viewing={viewing} />
    </div>
  );
}

/** What the step through the scan shown says: where it halted (`where`, in words), or that the scan ran to its end. */
export function steppingText(viewing: number, stepping: object | null | undefined, where: string | null): string {
  if (!stepping) return `Step through scan ${viewing}: network by network (LD, FBD), line by line (ST, IL)`;
  return where ? `Scan ${viewing}, halted before ${where}` : `Scan ${viewing} ran to its end`;
}

/** What an arrow key does in the stepping group: → the next step (into the scan first), ← back one (while
 * stepping); null: nothing (another key, or → after the scan's end). */
export function steppingKey(key: string, stepping: boolean, ended: boolean): "statement" | "back" | null {
  if (key === "ArrowRight" && !ended) return "statement";
  if (key === "ArrowLeft" && stepping) return "back";
  return null;
}

/** Step through the scan shown (replayed from the scan before it, in the debug code): the diagrams and values show
 * the point reached, the network or line about to run is marked and shown; the recorded history does not change. */
function HistoryStepping({ viewing, describe, reveal }: { viewing: number } & HistoryBannerProps) {
  const stepping = useOnline((s) => s.monitor.history?.stepping ?? null);
  const at = stepping?.at ?? null;
  useRevealHalt(at, reveal);
  const [note, setNote] = useState<string | null>(null);
  const ended = stepping != null && !stepping.at;
  const step = async (granularity: "statement" | "over" | "back") => {
    const id = onlineStore.getState().simulation;
    if (!id) return;
    try {
      await historyStep(id, granularity);
      setNote(null);
    } catch (err) {
      setNote(err instanceof Error ? err.message : String(err));
    }
  };
  return (
    <div
      className="history-stepping"
      role="group"
      aria-label="Step through the scan"
      title="← and → step back and forth while a button here has the focus"
      onKeyDown={(event) => {
        const by = steppingKey(event.key, stepping != null, ended);
        if (!by) return;
        event.preventDefault();
        void step(by);
      }}
    >
      <span aria-label="Step point">{steppingText(viewing, stepping, at ? describe(at) : null)}</span>
      <button
        type="button"
        onClick={() => void step("statement")}
        disabled={ended}
        title="Run the scan shown to its next network or line (into the blocks it calls; →)"
      >
        {stepping ? "Next step" : "Step into this scan"}
      </button>
      {stepping ? (
        <button type="button" onClick={() => void step("back")} title="Back to the network or line before (←)">
          Step back
        </button>
      ) : null}
      {stepping ? (
        <button type="button" onClick={() => void step("over")} disabled={ended} title="Past the calls">
          Step over
        </button>
      ) : null}
      {stepping ? (
        <button type="button" onClick={() => void onlineStore.getState().seek(viewing)} title="The scan complete again">
          Whole scan
        </button>
      ) : null}
      {note ? <span role="alert">{note}</span> : null}
      <CallStack stack={stepping?.stack ?? []} describe={describe} reveal={reveal} />
    </div>
  );
}

/** The variables that differ between the scan shown and another one (by default the live scan), both values. */
function HistoryCompare({ viewing }: { viewing: number }) {
  const last = useOnline((s) => s.monitor.history?.last ?? viewing);
  const [other, setOther] = useState("");
  const types = useOnline((s) => s.monitor.types);
  const [rows, setRows] = useState<[string, Value[]][] | null>(null);
  const [note, setNote] = useState<string | null>(null);
  const compare = async () => {
    const id = onlineStore.getState().simulation;
    const second = other.trim() ? Number(other) : last;
    if (!id || !Number.isInteger(second)) return;
    try {
      const diff = await historyDiff(id, viewing, second);
      setRows(Object.entries(diff.differences));
      setNote(`${Object.keys(diff.differences).length} variables differ between scan ${viewing} and scan ${second}`);
    } catch (err) {
      setRows(null);
      setNote(err instanceof Error ? err.message : String(err));
    }
  };
  return (
    <div className="history-compare" role="group" aria-label="Compare scans">
      <label>
        Compare with scan{" "}
        <input
          aria-label="Compare with scan"
          inputMode="numeric"
          placeholder={String(last)}
          value={other}
          onChange={(event) => setOther(event.target.value)}
        />
      </label>
      <button type="button" onClick={() => void compare()}>
        Show differences
      </button>
      {note ? <span aria-label="Comparison">{note}</span> : null}
      {rows?.length ? (
        <table aria-label="Differences">
          <tbody>
            {rows.map(([path, [a, b]]) => (
              <tr key={path} data-path={path}>
                <td>{path}</td>
                <td>{formatValue(a, types[path])}</td>
                <td>→</td>
                <td>{formatValue(b, types[path])}</td>
              </tr>
            ))}
          </tbody>
        </table>
      ) : null}
    </div>
  );
}
