// A text field for an operand, with autocomplete from the POU's symbols and the globals.
import { useMemo, useRef, useState, type CSSProperties } from "react";
import type { SymbolInfo } from "../../generated/api";

export interface OperandEditorProps {
  label: string;
  initial: string;
  suggestions?: readonly SymbolInfo[];
  style?: CSSProperties;
  onCommit(text: string): void;
  onCancel(): void;
}

const MAX_SUGGESTIONS = 8;

/** Symbols whose name contains the text (case-insensitive), those starting with it first. */
export function suggest(text: string, symbols: readonly SymbolInfo[]): SymbolInfo[] {
  const needle = text.trim().toUpperCase();
  const hits = symbols.filter((s) => s.name.toUpperCase().includes(needle) && s.name.toUpperCase() !== needle);
  const starts = (s: SymbolInfo) => (s.name.toUpperCase().startsWith(needle) ? 0 : 1);
  return hits.sort((a, b) => starts(a) - starts(b) || a.name.localeCompare(b.name)).slice(0, MAX_SUGGESTIONS);
}

export function OperandEditor({ label, initial, suggestions = [], style, onCommit, onCancel }: OperandEditorProps) {
  const [text, setText] = useState(initial);
  const [active, setActive] = useState(-1);
  const list = useMemo(() => suggest(text, suggestions), [text, suggestions]);
  // Enter, Escape and the blur that follows them must end the edit once, not twice.
  const done = useRef(false);
  const finish = (end: () => void) => {
    if (done.current) return;
    done.current = true;
    end();
  };
  const commit = (value: string) => finish(() => onCommit(value));
  return (
    <div className="ld-operand-editor" style={style}>
      <input
        aria-label={label}
        role="combobox"
        aria-expanded={list.length > 0}
        aria-autocomplete="list"
        autoFocus
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
            setActive((i) => (i + 1) % list.length);
          } else if (e.key === "ArrowUp" && list.length) {
            e.preventDefault();
            setActive((i) => (i <= 0 ? list.length - 1 : i - 1));
          } else if (e.key === "Enter" || e.key === "Tab") {
            e.preventDefault();
            commit(list[active]?.name ?? text);
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
              aria-selected={i === active}
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
