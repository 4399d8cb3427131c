// The Diagnostics panel: the last Check (or a refused compile), errors first; a click opens the
// POU and reveals the network, element or line the diagnostic names (or opens the operator panel). Each code opens its entry of
// the diagnostics catalogue (docs/diagnostics.md, loaded on first use by ./catalogue): what it means, an
// example that triggers it and how to fix it.
import { useState } from "react";
import type { Diagnostic } from "../generated/api";
import { useCatalogue, type Catalogue } from "./catalogue";
import { focusOf, panelOf, usePanels } from "../store/panels";

const RANK = { error: 0, warning: 1, info: 2 } as const;

/** Where a diagnostic is, as the panel shows it. */
export function placeOf(d: Diagnostic): string {
  const panel = panelOf(d);
  if (panel) return d.element ? `panel ${panel}, widget ${d.element}` : `panel ${panel}`;
  const parts: string[] = [];
  if (d.pou) parts.push(d.pou);
  if (d.file?.endsWith("/declarations")) parts.push("declarations");
  if (d.place) parts.push(d.place);
  else if (d.network) parts.push(`network ${d.network}`);
  if (d.element && !d.place) parts.push(`element ${d.element}${d.pin ? `.${d.pin}` : ""}`);
  if (d.line != null) parts.push(`line ${d.line}${d.column != null ? `:${d.column}` : ""}`);
  if (!parts.length && d.json_path) parts.push(d.json_path);
  return parts.join(", ") || "project";
}

/** A code's catalogue entry, shown under the diagnostic. */
function Entry({ code, catalogue }: { code: string; catalogue: Catalogue | null }) {
  if (!catalogue) return <p className="diagnostic-entry">Loading the catalogue…</p>;
  const entry = catalogue[code];
  if (!entry) return <p className="diagnostic-entry">No entry for {code} in the catalogue.</p>;
  return (
    <div className="diagnostic-entry" role="note" aria-label={`About ${code}`}>
      <p>{entry.summary}</p>
      {entry.example ? <pre>{entry.example}</pre> : null}
      {entry.example_note ? <p>{entry.example_note}</p> : null}
      {entry.fix ? <p>Fix: {entry.fix}</p> : null}
    </div>
  );
}

export function DiagnosticsPanel({ onReveal }: { onReveal(d: Diagnostic): void }) {
  const diagnostics = usePanels((s) => s.diagnostics);
  const checking = usePanels((s) => s.checking);
  const error = usePanels((s) => s.checkError);
  if (checking) return <p className="panel-empty">Checking…</p>;
  if (error) {
    return (
      <p className="panel-empty" role="alert">
        Check failed: {error}
      </p>
    );
  }
  if (diagnostics === null)
    return <p className="panel-empty">Press Check to list the problems of the saved project.</p>;
  if (!diagnostics.length) return <p className="panel-empty">No problems found.</p>;
  return <DiagnosticsList diagnostics={diagnostics} onReveal={onReveal} />;
}

/** The problems, each with its code's catalogue entry (the catalogue is loaded when a list first shows). */
function DiagnosticsList({
  diagnostics,
  onReveal,
}: {
  diagnostics: readonly Diagnostic[];
  onReveal(d: Diagnostic): void;
}) {
  const [open, setOpen] = useState<number | null>(null);
  const catalogue = useCatalogue();
  const sorted = [...diagnostics].sort((a, b) => RANK[a.severity ?? "error"] - RANK[b.severity ?? "error"]);
  return (
    <ul className="diagnostics" aria-label="Diagnostics">
      {sorted.map((d, i) => {
        const target = focusOf(d) ?? panelOf(d);
        return (
          <li key={i}>
            <button
              type="button"
              className={`diagnostic diagnostic-${d.severity ?? "error"}`}
              disabled={!target}
              onClick={() => onReveal(d)}
            >
              <span className="diagnostic-severity">{d.severity ?? "error"}</span>
              <span className="diagnostic-place">{placeOf(d)}</span>
              <span className="diagnostic-message">{d.message}</span>
            </button>
            <button
              type="button"
              className="diagnostic-code"
              aria-expanded={open === i}
              title={catalogue?.[d.code]?.summary ?? d.code}
              onClick={() => setOpen(open === i ? null : i)}
            >
              {d.code}
            </button>
            {open === i ? <Entry code={d.code} catalogue={catalogue} /> : null}
          </li>
        );
      })}
    </ul>
  );
}
