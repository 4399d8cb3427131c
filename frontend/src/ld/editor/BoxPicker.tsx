// The box picker: a searchable list of every standard and user function and function block, and of the programs'
// methods (`Prog.M`), from /api/library, with the EN/ENO choice. LD boxes and FBD blocks share it; they differ in the
// dialog's name and in when EN/ENO is proposed.
import { useMemo, useState } from "react";
import type { LibraryEntry } from "../../generated/api";

export interface BoxPickerProps {
  library: readonly LibraryEntry[];
  onPick(entry: LibraryEntry, en: boolean): void;
  onCancel(): void;
  /** The dialog's accessible name ("Insert box" in LD, "Insert block" in FBD). */
  title?: string;
  /** Whether EN/ENO starts ticked for an entry; LD ticks it when the rung's power needs it. */
  defaultEn?(entry: LibraryEntry): boolean;
}

/** Entries whose name or comment contains the query; name matches first, then by name. */
export function searchLibrary(library: readonly LibraryEntry[], query: string): LibraryEntry[] {
  const q = query.trim().toUpperCase();
  const rank = (e: LibraryEntry) => (e.name.toUpperCase().startsWith(q) ? 0 : e.name.toUpperCase().includes(q) ? 1 : 2);
  return library
    .filter((e) => !q || rank(e) < 2 || (e.comment ?? "").toUpperCase().includes(q))
    .sort((a, b) => rank(a) - rank(b) || a.name.localeCompare(b.name));
}

/** GR-27 (b): a box without BOOL inputs needs EN/ENO to carry the rung's power. */
export const needsEn = (entry: LibraryEntry): boolean => !entry.inputs.some((p) => p.type.toUpperCase() === "BOOL");

/** FB, FUN, or METHOD for a program's method (`Prog.M`: the library lists it as a function). */
const entryKind = (e: LibraryEntry) => (e.kind === "function_block" ? "FB" : e.name.includes(".") ? "METHOD" : "FUN");

const signature = (e: LibraryEntry) =>
  `(${e.inputs.map((p) => p.name).join(", ")})${e.kind === "function" && e.return_type ? ` : ${e.return_type}` : e.outputs.length ? ` → ${e.outputs.map((p) => p.name).join(", ")}` : ""}`;

export function BoxPicker({ library, onPick, onCancel, title = "Insert box", defaultEn = needsEn }: BoxPickerProps) {
  const [query, setQuery] = useState("");
  const [active, setActive] = useState(0);
  const [en, setEn] = useState<boolean | null>(null);
  const hits = useMemo(() => searchLibrary(library, query), [library, query]);
  const chosen = hits[Math.min(active, hits.length - 1)];
  const pick = (entry: LibraryEntry | undefined) => entry && onPick(entry, en ?? defaultEn(entry));
  return (
    <div className="ld-dialog-backdrop" onMouseDown={onCancel}>
      <div
        className="ld-dialog ld-box-picker"
        role="dialog"
        aria-label={title}
        onMouseDown={(e) => e.stopPropagation()}
      >
        <input
          aria-label="Search functions and function blocks"
          autoFocus
          value={query}
          placeholder="Search: TON, ADD, counter…"
          onChange={(e) => {
            setQuery(e.target.value);
            setActive(0);
          }}
          onKeyDown={(e) => {
            e.stopPropagation();
            if (e.key === "ArrowDown") setActive((i) => Math.min(i + 1, hits.length - 1));
            else if (e.key === "ArrowUp") setActive((i) => Math.max(i - 1, 0));
            else if (e.key === "Enter") pick(chosen);
            else if (e.key === "Escape") onCancel();
            else return;
            e.preventDefault();
          }}
        />
        <ul role="listbox" aria-label="Functions and function blocks">
          {hits.map((entry) => (
            <li
              key={`${entry.source}:${entry.name}`}
              role="option"
              aria-selected={entry === chosen}
              onMouseDown={(e) => {
                e.preventDefault();
                pick(entry);
              }}
            >
              <span className="ld-entry-name">{entry.name}</span>
              <span className="ld-entry-signature">{signature(entry)}</span>
              <span className="ld-entry-kind">
                {entryKind(entry)}
                {entry.source === "standard" ? "" : ` · ${entry.source}`}
              </span>
              {entry.comment ? <span className="ld-entry-comment">{entry.comment}</span> : null}
            </li>
          ))}
          {hits.length === 0 ? <li className="ld-empty">No function or function block matches.</li> : null}
        </ul>
        <label className="ld-en-choice">
          <input
            type="checkbox"
            checked={en ?? (chosen ? defaultEn(chosen) : false)}
            onChange={(e) => setEn(e.target.checked)}
          />{" "}
          EN/ENO
        </label>
      </div>
    </div>
  );
}
