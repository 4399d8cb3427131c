// The Cross references panel: every variable and direct address of the saved project with where it is
// declared, read, written and called (from the backend); a filter; a click on a place opens the POU
// there (the same reveal as a diagnostic). "Find all references" in the LD, FBD and ST editors opens
// it on one variable.
import { useEffect, useState } from "react";
import type { Diagnostic, XrefEntry } from "../generated/api";
import { useWorkspace } from "../store/project";
import { entryKey, filterEntries, placeOf, placeToReveal, XREF_COLUMNS } from "./model";
import { useXref, xrefStore } from "./store";
import "./xref.css";

const KIND_LABEL = { declared: "declared", read: "read", write: "write", call: "call" } as const;

export function XrefPanel({ onReveal }: { onReveal(place: Diagnostic): void }) {
  const project = useWorkspace((s) => s.name);
  const revision = useWorkspace((s) => s.revision);
  const { entries, loading, error, filter, focused } = useXref((s) => s);
  // Loaded when the panel opens and after every save (a new revision): the list is the saved project's.
  useEffect(() => {
    if (project) void xrefStore.getState().load(project);
  }, [project, revision]);
  if (!project) return <p className="panel-empty">Open a project to list its cross references.</p>;
  const shown = filterEntries(entries ?? [], filter);
  return (
    <div className="xref-panel">
      <div className="xref-toolbar">
        <input
          type="search"
          aria-label="Filter cross references"
          placeholder="Filter by name, address, type or POU"
          value={filter}
          onChange={(e) => xrefStore.getState().setFilter(e.target.value)}
        />
        <button type="button" onClick={() => void xrefStore.getState().load(project)} disabled={loading}>
          Refresh
        </button>
        <span className="xref-note">of the saved project{loading ? " (loading…)" : ""}</span>
      </div>
      {error ? (
        <p className="panel-empty" role="alert">
          Cross references failed: {error}
        </p>
      ) : null}
      <table className="xref-table" aria-label="Cross references">
        <thead>
          <tr>
            {[...XREF_COLUMNS, "Path"].map((c) => (
              <th key={c}>{c}</th>
            ))}
          </tr>
        </thead>
        <tbody>
          {shown.map((entry) => (
            <EntryRows
              key={entryKey(entry)}
              entry={entry}
              onReveal={onReveal}
              open={focused === entryKey(entry) || shown.length <= 3}
            />
          ))}
        </tbody>
      </table>
    </div>
  );
}

function EntryRows({
  entry,
  open: initiallyOpen,
  onReveal,
}: {
  entry: XrefEntry;
  open: boolean;
  onReveal(place: Diagnostic): void;
}) {
  const [open, setOpen] = useState(initiallyOpen);
  const [wasOpen, setWasOpen] = useState(initiallyOpen);
  if (wasOpen !== initiallyOpen) {
    setWasOpen(initiallyOpen);
    setOpen(initiallyOpen);
  }
  const label = `${entry.name}${entry.pou ? ` (${entry.pou})` : ""}`;
  return (
    <>
      <tr className="xref-entry" data-entry={entryKey(entry)}>
        <td>
          <button
            type="button"
            className="xref-toggle"
            aria-label={`${entry.name} (${entry.pou ?? "global"})`}
            aria-expanded={open}
            onClick={() => setOpen(!open)}
          >
            {open ? "▾" : "▸"} {entry.name}
          </button>
        </td>
        <td>{entry.pou ?? "global"}</td>
        <td>{entry.type}</td>
        <td>{entry.address ?? ""}</td>
        <td colSpan={3}>
          {entry.accesses.length} places{entry.comment ? ` - ${entry.comment}` : ""}
        </td>
      </tr>
      {open
        ? entry.accesses.map((access, i) => {
            const target = placeToReveal(access);
            return (
              <tr key={i} className={`xref-access xref-${access.kind}`} aria-label={`${label} ${access.kind}`}>
                <td />
                <td />
                <td />
                <td />
                <td>{KIND_LABEL[access.kind]}</td>
                <td>
                  <button
                    type="button"
                    className="xref-place"
                    disabled={!target}
                    onClick={() => target && onReveal(target)}
                  >
                    {placeOf(access)}
                  </button>
                </td>
                <td>{access.path}</td>
              </tr>
            );
          })
        : null}
    </>
  );
}
