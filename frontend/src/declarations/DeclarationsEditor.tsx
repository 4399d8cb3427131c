// Declarations of a POU (or the globals) as a table and as ST text: both edit the same text, so a
// change in one shows in the other. Table rows: name, class, type (autocomplete of elementary,
// user and FB types), initial value, address, comment; add, remove, move up/down. Problems the
// backend reports for a line appear on its row. Text the table cannot hold keeps it read-only.
import { PencilLine } from "lucide-react";
import { useEffect, useId, useMemo, useRef, useState } from "react";
import type { Diagnostic } from "../generated/api";
import { freeName, parseDeclarations, printDeclarations, VAR_CLASSES, type DeclRow } from "../iec/declarations";

export interface DeclarationsEditorProps {
  text: string;
  onChange(text: string): void;
  /** Problems located by line of this text. */
  diagnostics?: readonly Diagnostic[];
  /** Type names to offer (elementary, user and FB types). */
  types: readonly string[];
  /** A line to reveal (a diagnostic was clicked); `seq` repeats a request for the same line. */
  focus?: { line: number; seq: number } | null;
  /** Editing is off (online); the reason is shown. */
  readOnly?: string | null;
  /** Class of a new row (VAR for POUs, VAR_GLOBAL for the globals). */
  newClass?: string;
  /** Offers "Rename everywhere" on each row (the globals: a project-level name, see tree/refactor.ts). */
  onRename?(name: string): void;
  /** Removes a named row through the caller (the globals: the delete dialog lists its uses first); without it
   * the row goes at once. */
  onRemove?(name: string): void;
}

type Mode = "table" | "text";
const COLUMNS = ["name", "varClass", "type", "initial", "address", "comment"] as const;
const HEADINGS: Record<(typeof COLUMNS)[number], string> = {
  name: "Name",
  varClass: "Class",
  type: "Type",
  initial: "Initial value",
  address: "Address",
  comment: "Comment",
};

export function DeclarationsEditor({
  text,
  onChange,
  diagnostics = [],
  types,
  focus = null,
  readOnly = null,
  newClass = "VAR",
  onRename,
  onRemove,
}: DeclarationsEditorProps) {
  const focusLine = focus?.line ?? null;
  const [mode, setMode] = useState<Mode>("table");
  const parsed = useMemo(() => parseDeclarations(text), [text]);
  // The table keeps its own rows while the user types (a half-typed row need not parse);
  // the text wins whenever it changes from elsewhere (the text view, the LD declare prompt).
  const [rows, setRows] = useState<DeclRow[]>(parsed.ok ? parsed.rows : []);
  /** The text the table printed last: while it is the text, the table's rows describe it. */
  const [printed, setPrinted] = useState<string | null>(null);
  const [textSeen, setTextSeen] = useState(text);
  if (text !== textSeen) {
    // A new text during render (React's "adjusting state when a prop changes"), not in an effect.
    setTextSeen(text);
    if (text !== printed && parsed.ok) setRows(parsed.rows);
  }
  const tabular = parsed.ok || text === printed;
  const listId = useId();

  const update = (next: DeclRow[]) => {
    setRows(next);
    const out = printDeclarations(next);
    setPrinted(out);
    onChange(out);
  };
  const setCell = (index: number, column: (typeof COLUMNS)[number], value: string) =>
    update(rows.map((r, i) => (i === index ? { ...r, [column]: value } : r)));
  const move = (index: number, by: number) => {
    const next = [...rows];
    const [r] = next.splice(index, 1);
    next.splice(index + by, 0, r!);
    update(next);
  };

  const lines = parsed.ok ? parsed.rows.map((r) => r.line) : [];
  const problemsOf = (index: number) => diagnostics.filter((d) => d.line != null && d.line === lines[index]);
  const unplaced = diagnostics.filter((d) => d.line == null || !lines.includes(d.line));
  const editable = tabular && !readOnly;
  const tableRef = useRef<HTMLTableSectionElement>(null);
  // Only a new focus request switches the view (switching on every keystroke would fight the user).
  const seq = focus?.seq ?? null;
  const [seqSeen, setSeqSeen] = useState<number | null>(null);
  if (seq !== seqSeen) {
    setSeqSeen(seq);
    if (focusLine != null) setMode(parsed.ok && lines.includes(focusLine) ? "table" : "text");
  }
  useEffect(() => {
    if (focusLine == null) return;
    const frame = requestAnimationFrame(() =>
      tableRef.current?.querySelector(`[data-line="${focusLine}"]`)?.scrollIntoView?.({ block: "nearest" }),
    );
    return () => cancelAnimationFrame(frame);
  }, [seq, focusLine]);

  return (
    <div className="declarations">
      <div className="declarations-bar">
        <div role="tablist" aria-label="Declarations view">
          {(["table", "text"] as const).map((m) => (
            <button key={m} type="button" role="tab" aria-selected={mode === m} onClick={() => setMode(m)}>
              {m === "table" ? "Table" : "Text"}
            </button>
          ))}
        </div>
        {mode === "table" ? (
          <button
            type="button"
            disabled={!editable}
            onClick={() =>
              update([
                ...rows,
                {
                  name: freeName(rows),
                  varClass: rows[rows.length - 1]?.varClass ?? newClass,
                  type: "BOOL",
                  initial: "",
                  address: "",
                  comment: "",
                },
              ])
            }
          >
            Add variable
          </button>
        ) : null}
        {readOnly ? <span className="declarations-note">{readOnly}</span> : null}
      </div>
      {mode === "text" ? (
        <textarea
          className="declarations-text"
          aria-label="Declarations text"
          value={text}
          readOnly={!!readOnly}
          spellCheck={false}
          onChange={(e) => onChange(e.target.value)}
        />
      ) : !tabular && !parsed.ok ? (
        <p className="panel-empty" role="status">
          The table cannot show this text without losing part of it ({parsed.error}, line {parsed.line}); edit it in the
          Text view.
        </p>
      ) : (
        <table className="declarations-table" aria-label="Declarations">
          <thead>
            <tr>
              {COLUMNS.map((c) => (
                <th key={c}>{HEADINGS[c]}</th>
              ))}
              <th />
            </tr>
          </thead>
          <tbody ref={tableRef}>
            {rows.map((r, i) => {
              const problems = problemsOf(i);
              return (
                <tr
                  key={i}
                  data-line={lines[i]}
                  className={
                    [problems.length ? "has-problem" : "", focusLine != null && lines[i] === focusLine ? "focused" : ""]
                      .join(" ")
                      .trim() || undefined
                  }
                >
                  {COLUMNS.map((c) => (
                    <td key={c}>
                      {c === "varClass" ? (
                        <select
                          aria-label={`Class of ${r.name}`}
                          value={r.varClass}
                          disabled={!editable}
                          onChange={(e) => setCell(i, c, e.target.value)}
                        >
                          {[...new Set([r.varClass, ...VAR_CLASSES])].map((v) => (
                            <option key={v}>{v}</option>
                          ))}
                        </select>
                      ) : (
                        <input
                          aria-label={`${HEADINGS[c]} of ${r.name || `row ${i + 1}`}`}
                          value={r[c]}
                          list={c === "type" ? listId : undefined}
                          disabled={!editable}
                          spellCheck={false}
                          onChange={(e) => setCell(i, c, e.target.value)}
                        />
                      )}
                      {c === "comment" && problems.length ? (
                        <div className="row-problems" role="alert">
                          {problems.map((d, k) => (
                            <span key={k}>{d.message}</span>
                          ))}
                        </div>
                      ) : null}
                    </td>
                  ))}
                  <td className="row-actions">
                    {onRename ? (
                      <button
                        type="button"
                        aria-label={`Rename ${r.name} everywhere`}
                        title="Rename everywhere (every use in the project)"
                        disabled={!editable || !r.name}
                        onClick={() => onRename(r.name)}
                      >
                        <PencilLine size={14} aria-hidden="true" />
                      </button>
                    ) : null}
                    <button
                      type="button"
                      aria-label={`Move ${r.name} up`}
                      disabled={!editable || i === 0}
                      onClick={() => move(i, -1)}
                    >
                      ↑
                    </button>
                    <button
                      type="button"
                      aria-label={`Move ${r.name} down`}
                      disabled={!editable || i === rows.length - 1}
                      onClick={() => move(i, 1)}
                    >
                      ↓
                    </button>
                    <button
                      type="button"
                      aria-label={`Remove ${r.name}`}
                      disabled={!editable}
                      onClick={() => (onRemove && r.name ? onRemove(r.name) : update(rows.filter((_, k) => k !== i)))}
                    >
                      ×
                    </button>
                  </td>
                </tr>
              );
            })}
          </tbody>
        </table>
      )}
      {unplaced.length || (mode === "text" && diagnostics.length) ? (
        <ul className="declarations-problems" aria-label="Declaration problems">
          {(mode === "text" ? diagnostics : unplaced).map((d, k) => (
            <li key={k}>
              {d.line != null ? `line ${d.line}: ` : ""}
              {d.message}
            </li>
          ))}
        </ul>
      ) : null}
      <datalist id={listId}>
        {types.map((t) => (
          <option key={t} value={t} />
        ))}
      </datalist>
    </div>
  );
}
