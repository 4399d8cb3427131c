// "View as ST": the exported ST of a saved LD/FBD POU, read-only and highlighted. The lines of
// each network form a block linked to its network (a click reveals it in the diagram), and the
// text downloads as <POU>.st.
import { useEffect, useMemo, useState } from "react";
import { ApiError, exportSt } from "../api/client";
import type { Diagnostic, StExport } from "../generated/api";
import { downloadText } from "../ui/download";
import { placeOf } from "../panels/DiagnosticsPanel";
import { highlightLines, Tokens } from "./highlight";

export interface StViewProps {
  project: string;
  pou: string;
  /** The POU has unsaved changes (the export is of the saved version). */
  unsaved: boolean;
  onRevealNetwork(network: string): void;
  load?: (project: string, pou: string) => Promise<StExport>;
}

interface Block {
  network: string | null;
  /** 1-based first line. */
  start: number;
  lines: string[];
}

/** Consecutive lines grouped by the network the source map says they come from (null: declarations etc.). */
export function blocksOf(text: string, sourceMap: StExport["source_map"] = []): Block[] {
  const networkOf = new Map(sourceMap.map((e) => [e.line, e.network]));
  const blocks: Block[] = [];
  text
    .replace(/\n$/, "")
    .split("\n")
    .forEach((line, i) => {
      const network = networkOf.get(i + 1) ?? null;
      const last = blocks[blocks.length - 1];
      if (last && last.network === network) last.lines.push(line);
      else blocks.push({ network, start: i + 1, lines: [line] });
    });
  return blocks;
}

type Outcome = { result: StExport } | { error: { message: string; diagnostics: Diagnostic[] } };

export function StView({ project, pou, unsaved, onRevealNetwork, load = exportSt }: StViewProps) {
  // The outcome of the export asked for `key`; another key (a new POU) shows "Exporting…" until its answer.
  const key = `${project}\u0000${pou}`;
  const [outcome, setOutcome] = useState<{ key: string; value: Outcome } | null>(null);
  useEffect(() => {
    let live = true;
    load(project, pou).then(
      (r) => live && setOutcome({ key, value: { result: r } }),
      (err: unknown) => {
        if (!live) return;
        const detail = err instanceof ApiError ? (err.detail as { diagnostics?: Diagnostic[] } | undefined) : undefined;
        setOutcome({
          key,
          value: {
            error: {
              message: err instanceof Error ? err.message : String(err),
              diagnostics: Array.isArray(detail?.diagnostics) ? detail.diagnostics : [],
            },
          },
        });
      },
    );
    return () => {
      live = false;
    };
  }, [project, pou, load, key]);
  const current = outcome?.key === key ? outcome.value : null;
  const result = current && "result" in current ? current.result : null;
  const error = current && "error" in current ? current.error : null;
  const blocks = useMemo(() => (result ? blocksOf(result.text, result.source_map) : []), [result]);
  const tokens = useMemo(() => (result ? highlightLines(result.text) : []), [result]);

  return (
    <div className="st-view" aria-label={`${pou} as ST`}>
      <div className="st-view-bar">
        <span>
          {pou} exported as Structured Text{unsaved ? " (of the saved version: save to include your changes)" : ""}
        </span>
        <button type="button" disabled={!result} onClick={() => result && downloadText(`${pou}.st`, result.text)}>
          Download {pou}.st
        </button>
      </div>
      {error ? (
        <div className="panel-empty" role="alert">
          <p>The export failed: {error.message}</p>
          {error.diagnostics.length ? (
            <ul>
              {error.diagnostics.map((d, i) => (
                <li key={i}>
                  {placeOf(d)}: {d.message}
                </li>
              ))}
            </ul>
          ) : null}
        </div>
      ) : !result ? (
        <p className="panel-empty">Exporting…</p>
      ) : (
        <pre className="st-code" aria-label="Exported ST">
          {blocks.map((block) => (
            <div
              key={block.start}
              className={block.network ? "st-block st-network" : "st-block"}
              data-network={block.network ?? undefined}
              title={block.network ? `Network ${block.network}: click to show it in the diagram` : undefined}
              onClick={block.network ? () => onRevealNetwork(block.network!) : undefined}
            >
              {block.lines.map((line, i) => (
                <div key={i} className="st-line">
                  <span className="st-line-number">{block.start + i}</span>
                  <code>
                    <Tokens tokens={tokens[block.start - 1 + i] ?? [{ text: line, className: "" }]} />
                  </code>
                </div>
              ))}
            </div>
          ))}
        </pre>
      )}
    </div>
  );
}
