// "View as ST": the exported ST of a saved LD/FBD POU, read-only and highlighted. The lines of
// each network form a block linked to its network (a click reveals it in the diagram), and the
// text downloads as <POU>.st.
import { useEffect, useMemo, useState } from "react";
import { ApiError, exportSt } from "../api/client";
import type { Diagnostic, StExport } from "../generated/api";
import { placeOf } from "../panels/DiagnosticsPanel";
import { tokenize } from "./highlight";

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

function download(name: string, text: string) {
  const url = URL.createObjectURL(new Blob([text], { type: "text/plain;charset=utf-8" }));
  const a = document.createElement("a");
  a.href = url;
  a.download = `${name}.st`;
  a.click();
  URL.revokeObjectURL(url);
}

export function StView({ project, pou, unsaved, onRevealNetwork, load = exportSt }: StViewProps) {
  const [result, setResult] = useState<StExport | null>(null);
  const [error, setError] = useState<{ message: string; diagnostics: Diagnostic[] } | null>(null);
  useEffect(() => {
    let live = true;
    setResult(null);
    setError(null);
    load(project, pou).then(
      (r) => live && setResult(r),
      (err: unknown) => {
        if (!live) return;
        const detail = err instanceof ApiError ? (err.detail as { diagnostics?: Diagnostic[] } | undefined) : undefined;
        setError({
          message: err instanceof Error ? err.message : String(err),
          diagnostics: Array.isArray(detail?.diagnostics) ? detail.diagnostics : [],
        });
      },
    );
    return () => {
      live = false;
    };
  }, [project, pou, load]);
  const blocks = useMemo(() => (result ? blocksOf(result.text, result.source_map) : []), [result]);

  return (
    <div className="st-view" aria-label={`${pou} as ST`}>
      <div className="st-view-bar">
        <span>
          {pou} exported as Structured Text{unsaved ? " (of the saved version: save to include your changes)" : ""}
        </span>
        <button type="button" disabled={!result} onClick={() => result && download(pou, result.text)}>
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
                    {tokenize(line).map((t, j) => (
                      <span key={j} className={`st-${t.kind}`}>
                        {t.text}
                      </span>
                    ))}
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
