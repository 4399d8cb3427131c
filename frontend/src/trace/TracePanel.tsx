// The Trace panel: pick up to 20 variables (typed with autocomplete from the programs' symbols, or
// from the watch list), an optional trigger and the buffer size; Start records every scan, the
// samples stream in and show as a chart (or a table), Export CSV saves them.
import { lazy, Suspense, useEffect, useMemo, useState, type FormEvent } from "react";
import { projectApi } from "../api/client";
import type { DisplayType } from "../generated/monitor";
import { downloadText } from "../ui/download";
import { pathKey } from "../online/monitor";
import { onlineStore, useOnline } from "../online/store";
import { useWorkspace } from "../store/project";
import { traceCandidates } from "./candidates";
import { formatSample, traceCsv, type Kind } from "./csv";
import type { SampleRing } from "./ring";
import { traceStore, useTrace, type TraceState } from "./store";
import "./trace.css";
import { CONDITIONS, describeTrigger, isCrossing, triggerOf, type Condition } from "./trigger";

// uPlot is loaded with the first chart (it reads the screen at import, and most sessions never trace).
const TraceChart = lazy(() => import("./TraceChart").then((m) => ({ default: m.TraceChart })));

/** The table shows at most this many samples (the newest); the chart and the CSV show them all. */
export const TABLE_ROWS = 500;

const NO_CANDIDATES: string[] = [];

/** Paths offered by the path inputs: BOOL and numeric variables of every program. */
function useCandidates(): string[] {
  const project = useWorkspace((s) => s.name);
  const pous = useWorkspace((s) => s.project?.pous);
  const library = useWorkspace((s) => s.library);
  // Candidates found for what was asked (another project or program list shows none until its answer).
  const [found, setFound] = useState<{ for: readonly string[]; candidates: string[] } | null>(null);
  const programs = useMemo(
    () => (pous ?? []).filter((p) => p.kind === "program" || p.kind === "plant").map((p) => p.name),
    [pous],
  );
  useEffect(() => {
    if (!project || !programs.length) return;
    let current = true;
    Promise.all(programs.map((pou) => projectApi.getSymbols(project, pou))).then(
      (tables) => current && setFound({ for: programs, candidates: traceCandidates(tables, library) }),
      () => undefined, // no symbols: the inputs still take typed paths
    );
    return () => {
      current = false;
    };
  }, [project, programs, library]);
  return project && found?.for === programs ? found.candidates : NO_CANDIDATES;
}

export function statusText(
  s: Pick<TraceState, "phase" | "ring" | "recorded" | "triggered" | "trigger" | "lost" | "capacity">,
): string {
  const count = s.ring?.length ?? 0;
  const lost = s.lost ? ` · ${s.lost} samples lost (the connection was too slow)` : "";
  const trigger = triggerOf(s.trigger);
  switch (s.phase) {
    case "idle":
      return "Not recording";
    case "starting":
      return "Starting…";
    case "waiting":
      return `Waiting for the trigger: ${trigger.ok && trigger.trigger ? describeTrigger(trigger.trigger) : "?"}`;
    case "recording":
      return `Recording · ${count} samples${s.triggered ? ` · triggered at scan ${s.triggered.scan}` : ""}${lost}`;
    case "done":
      return `Done · ${count} samples${s.ring && s.ring.total > count ? ` (the newest of ${s.ring.total})` : ""}${lost}`;
  }
}

function SamplesTable({
  paths,
  kinds,
  types,
  ring,
  origin,
}: {
  paths: string[];
  kinds: (Kind | null)[];
  types: (DisplayType | null)[];
  ring: SampleRing;
  origin: number;
}) {
  const [changesOnly, setChangesOnly] = useState(false);
  useTrace((s) => s.version); // re-render with every chunk
  const rows: number[] = [];
  for (let i = 0; i < ring.length; i++) {
    if (changesOnly && i > 0) {
      const a = ring.sample(i - 1).values;
      const b = ring.sample(i).values;
      if (a.every((v, c) => Object.is(v, b[c]))) continue;
    }
    rows.push(i);
  }
  const shown = rows.slice(-TABLE_ROWS);
  return (
    <div className="trace-table-wrap">
      <label className="trace-inline">
        <input type="checkbox" checked={changesOnly} onChange={(e) => setChangesOnly(e.target.checked)} /> Only samples
        where a value changed
      </label>
      {rows.length > shown.length ? (
        <p className="panel-empty">
          The newest {shown.length} of {rows.length} samples; Export CSV has them all.
        </p>
      ) : null}
      <table className="trace-table" aria-label="Trace samples">
        <thead>
          <tr>
            <th>t (ms)</th>
            <th>scan</th>
            {paths.map((p) => (
              <th key={p}>{p}</th>
            ))}
          </tr>
        </thead>
        <tbody>
          {shown.map((i) => {
            const sample = ring.sample(i);
            return (
              <tr key={i} data-scan={sample.scan}>
                <td>{sample.timeMs - origin}</td>
                <td>{sample.scan}</td>
                {sample.values.map((v, c) => (
                  <td key={c}>{formatSample(v, kinds[c] ?? "number", types[c])}</td>
                ))}
              </tr>
            );
          })}
        </tbody>
      </table>
    </div>
  );
}

function TraceSetup({ candidates }: { candidates: string[] }) {
  const paths = useTrace((s) => s.paths);
  const trigger = useTrace((s) => s.trigger);
  const capacity = useTrace((s) => s.capacity);
  const stopWhenFull = useTrace((s) => s.stopWhenFull);
  const busy = useTrace((s) => s.phase === "starting" || s.phase === "waiting" || s.phase === "recording");
  const watched = useOnline((s) => s.watch);
  const [text, setText] = useState("");
  const [refusal, setRefusal] = useState<string | null>(null);
  const t = traceStore.getState();
  const add = (path: string) => {
    const why = t.addPath(path);
    setRefusal(why);
    if (!why) setText("");
  };
  const submit = (e: FormEvent) => {
    e.preventDefault();
    add(text);
  };
  const offered = watched.filter((w) => !paths.some((p) => pathKey(p) === pathKey(w)));
  return (
    <div className="trace-setup">
      <datalist id="trace-candidates">
        {candidates.map((c) => (
          <option key={c} value={c} />
        ))}
      </datalist>
      <form className="trace-add" onSubmit={submit}>
        <input
          aria-label="Variable to trace"
          list="trace-candidates"
          placeholder="MAIN.Motor"
          value={text}
          onChange={(e) => setText(e.target.value)}
          spellCheck={false}
          disabled={busy}
        />
        <button type="submit" disabled={busy || !text.trim()}>
          Add
        </button>
      </form>
      {refusal ? (
        <p className="trace-error" role="alert">
          {refusal}
        </p>
      ) : null}
      <ul className="trace-paths" aria-label="Traced variables">
        {paths.map((p) => (
          <li key={pathKey(p)}>
            <span>{p}</span>
            <button type="button" aria-label={`Stop tracing ${p}`} disabled={busy} onClick={() => t.removePath(p)}>
              ×
            </button>
          </li>
        ))}
      </ul>
      {offered.length ? (
        <div className="trace-offered">
          From the watch list:{" "}
          {offered.map((w) => (
            <button key={pathKey(w)} type="button" disabled={busy} onClick={() => add(w)}>
              + {w}
            </button>
          ))}
        </div>
      ) : null}
      <fieldset className="trace-trigger" disabled={busy}>
        <legend>Trigger (optional)</legend>
        <input
          aria-label="Trigger variable"
          list="trace-candidates"
          placeholder="none: start at once"
          value={trigger.path}
          onChange={(e) => t.setTrigger({ path: e.target.value })}
          spellCheck={false}
        />
        <select
          aria-label="Trigger condition"
          value={trigger.condition}
          onChange={(e) => t.setTrigger({ condition: e.target.value as Condition })}
        >
          {CONDITIONS.map((c) => (
            <option key={c.value} value={c.value}>
              {c.label}
            </option>
          ))}
        </select>
        {isCrossing(trigger.condition) ? (
          <input
            aria-label="Trigger level"
            placeholder="level"
            value={trigger.level}
            onChange={(e) => t.setTrigger({ level: e.target.value })}
            size={8}
          />
        ) : null}
      </fieldset>
      <div className="trace-buffer">
        <label>
          Samples{" "}
          <input
            aria-label="Samples to keep"
            type="number"
            min={1}
            max={10000}
            value={capacity}
            disabled={busy}
            onChange={(e) => t.setCapacity(Number(e.target.value))}
          />
        </label>
        <label className="trace-inline">
          <input
            type="checkbox"
            checked={stopWhenFull}
            disabled={busy}
            onChange={(e) => t.setStopWhenFull(e.target.checked)}
          />{" "}
          Stop when full
        </label>
      </div>
    </div>
  );
}

export function TracePanel() {
  const candidates = useCandidates();
  const state = useTrace((s) => s);
  const project = useWorkspace((s) => s.name);
  const [view, setView] = useState<"chart" | "table">("chart");
  const busy = state.phase === "starting" || state.phase === "waiting" || state.phase === "recording";
  const { ring, recorded, kinds, types, origin } = state;
  const viewing = useOnline((s) => s.monitor.history?.viewing ?? null);
  /** A click on the chart: that scan from the history, when the history still holds it. */
  const showScan = (scan: number) => {
    const online = onlineStore.getState();
    const history = online.monitor.history;
    if (history && scan >= history.first && scan <= history.last) void online.seek(scan);
  };
  const exportCsv = () => {
    if (!ring) return;
    downloadText(
      `trace-${project ?? "project"}.csv`,
      traceCsv(
        recorded,
        kinds.map((k) => k ?? "number"),
        ring.columnsInOrder(),
        types,
      ),
      "text/csv;charset=utf-8",
    );
  };
  return (
    <div className="trace">
      <TraceSetup candidates={candidates} />
      <div className="trace-main">
        <div className="trace-controls">
          {busy ? (
            <button type="button" onClick={state.stop}>
              Stop trace
            </button>
          ) : (
            <button type="button" onClick={state.start} disabled={!state.paths.length}>
              Start trace
            </button>
          )}
          <button type="button" onClick={exportCsv} disabled={!ring?.length}>
            Export CSV
          </button>
          <div role="radiogroup" aria-label="Trace view" className="trace-view">
            {(["chart", "table"] as const).map((v) => (
              <label key={v}>
                <input type="radio" name="trace-view" checked={view === v} onChange={() => setView(v)} />{" "}
                {v === "chart" ? "Chart" : "Table"}
              </label>
            ))}
          </div>
          <label className="trace-inline">
            <input type="checkbox" checked={state.laneView} onChange={(e) => state.setLaneView(e.target.checked)} />{" "}
            BOOL lanes
          </label>
          <span role="status" aria-label="Trace state" className="trace-status">
            {statusText(state)}
          </span>
        </div>
        {state.error ? (
          <p className="trace-error" role="alert">
            {state.error}
          </p>
        ) : null}
        {ring && ring.length && origin !== null ? (
          view === "chart" ? (
            <Suspense fallback={<p className="panel-empty">Loading the chart…</p>}>
              <TraceChart
                paths={recorded}
                kinds={kinds}
                types={types}
                ring={ring}
                version={state.version}
                origin={origin}
                laneView={state.laneView}
                viewing={viewing}
                onPick={showScan}
              />
            </Suspense>
          ) : (
            <SamplesTable paths={recorded} kinds={kinds} types={types} ring={ring} origin={origin} />
          )
        ) : (
          <p className="panel-empty">
            {state.phase === "idle"
              ? "Add variables, go online and start a trace: every scan is recorded."
              : "No samples yet."}
          </p>
        )}
      </div>
    </div>
  );
}
