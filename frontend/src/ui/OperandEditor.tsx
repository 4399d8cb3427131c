// A text field for an operand, with autocomplete from the POU's symbols and the globals, and after a qualifier
// (`T1.`, `Prog.`, `Color.`, `Color#`) from its members, as the editor's `members` gives them.
import { useEffect, useMemo, useRef, useState, type CSSProperties } from "react";
import type { SymbolInfo } from "../generated/api";

/** The suggestions for a qualified operand being typed (`T1.`, `Prog.`, `Color#`: st/operandScope.ts), as whole
 * operands; null: the text is no such operand. */
export type MembersAfter = (text: string) => readonly { name: string; type: string }[] | null;

export interface OperandEditorProps {
  label: string;
  initial: string;
  suggestions?: readonly SymbolInfo[];
  /** The members offered after a qualifier; none: only the plain names are offered. */
  members?: MembersAfter;
  style?: CSSProperties;
  onCommit(text: string): void;
  onCancel(): void;
}

const MAX_SUGGESTIONS = 8;

/** Symbols (or types) whose name contains the text (case-insensitive), those starting with it first. */
export function suggest<T extends { name: string }>(text: string, symbols: readonly T[]): T[] {
  const needle = text.trim().toUpperCase();
  const hits = symbols.filter((s) => s.name.toUpperCase().includes(needle) && s.name.toUpperCase() !== needle);
  const starts = (s: T) => (s.name.toUpperCase().startsWith(needle) ? 0 : 1);
  return hits.sort((a, b) => starts(a) - starts(b) || a.name.localeCompare(b.name)).slice(0, MAX_SUGGESTIONS);
}

/** The suggestion highlighted before the user picks one: the first, if it starts with the typed text
 * and the text names no symbol already (typing "Start" keeps Start even when StartCount exists). */
export function defaultSuggestion(
  text: string,
  list: readonly { name: string }[],
  symbols: readonly { name: string }[],
): number {
  const needle = text.trim().toUpperCase();
  if (!needle || symbols.some((s) => s.name.toUpperCase() === needle)) return -1;
  return list[0]?.name.toUpperCase().startsWith(needle) ? 0 : -1;
}

export function OperandEditor({
  label,
  initial,
  suggestions = [],
  members,
  style,
  onCommit,
  onCancel,
}: OperandEditorProps) {
  const [text, setText] = useState(initial);
  const [active, setActive] = useState(-1);
  const list = useMemo(
    () => members?.(text)?.slice(0, MAX_SUGGESTIONS) ?? suggest(text, suggestions),
    [text, suggestions, members],
  );
  // Until the user picks with the arrows, a suggestion that starts with the typed text is highlighted,
  // and Enter or Tab take it (as IDE completion does): typing "Mo" + Enter gives "Motor".
  const highlighted = active >= 0 ? active : defaultSuggestion(text, list, suggestions);
  // Enter, Escape and the blur that follows them must end the edit once, not twice.
  const done = useRef(false);
  const finish = (end: () => void) => {
    if (done.current) return;
    done.current = true;
    end();
  };
  const commit = (value: string) => finish(() => onCommit(value));
  // Focused as it opens, also where it is drawn hidden at first (an @xyflow node is invisible until it
  // is measured, and a hidden field cannot take focus): tried again each frame until it has it.
  const field = useRef<HTMLInputElement>(null);
  useEffect(() => {
    let frame = 0;
    let tries = 0;
    const focus = () => {
      const input = field.current;
      if (!input || document.activeElement === input) return;
      input.focus();
      if (document.activeElement !== input && tries++ < 60) frame = requestAnimationFrame(focus);
    };
    focus();
    return () => cancelAnimationFrame(frame);
  }, []);
  return (
    <div className="ld-operand-editor" style={style}>
      <input
        aria-label={label}
        role="combobox"
        aria-expanded={list.length > 0}
        aria-autocomplete="list"
        ref={field}
        value={text}
        spellCheck={false}
        onChange={(e) => {
          setText(e.target.value);
          setActive(-1);
        }}
        onKeyDown={(e) => {
          e.stopPropagation();
          if (e.key === "ArrowDown" && list.length) {
            e.preventDefault();
            setActive((highlighted + 1) % list.length);
          } else if (e.key === "ArrowUp" && list.length) {
            e.preventDefault();
            setActive(highlighted <= 0 ? list.length - 1 : highlighted - 1);
          } else if (e.key === "Enter" || e.key === "Tab") {
            e.preventDefault();
            commit(list[highlighted]?.name ?? text);
          } else if (e.key === "Escape") {
            e.preventDefault();
            finish(onCancel);
          }
        }}
        onBlur={() => commit(text)}
      />
      {list.length ? (
        <ul role="listbox" className="ld-suggestions">
          {list.map((s, i) => (
            <li
              key={s.name}
              role="option"
              aria-selected={i === highlighted}
              onMouseDown={(e) => {
                e.preventDefault();
                commit(s.name);
              }}
            >
              <span className="ld-suggestion-name">{s.name}</span> <span className="ld-suggestion-type">{s.type}</span>
            </li>
          ))}
        </ul>
      ) : null}
    </div>
  );
}
