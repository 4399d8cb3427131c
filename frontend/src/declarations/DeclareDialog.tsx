// The declare dialog, the like of CODESYS's Auto Declare: opened when a name no declaration knows is typed
// where a variable is expected (an LD operand, an FBD input or output, an FBD/LD block's instance, the ST
// editor's quick fix). Driven by the keyboard: it opens with the type selected, Tab walks name, class, type,
// initial value, comment, Declare, Cancel; Enter declares, Escape cancels (or first closes the type
// suggestions). It floats over the editor, so opening it never shifts the diagram under the pointer.
import { useEffect, useMemo, useRef, useState } from "react";
import { defaultSuggestion, suggest } from "../ui/OperandEditor";
import { DECLARE_CLASSES, declareProblem, type NewVariable } from "../store/newVariable";
import "./declare.css";

export interface DeclareDialogProps {
  /** The name as typed and the proposed type (and class, when the editor knows better than VAR). */
  offer: NewVariable;
  /** The types to complete from: the IEC vocabulary's and the project's. */
  types: readonly string[];
  onDeclare(variable: NewVariable): void;
  onCancel(): void;
}

export function DeclareDialog({ offer, types, onDeclare, onCancel }: DeclareDialogProps) {
  const [varClass, setVarClass] = useState(offer.varClass ?? "VAR");
  const [type, setType] = useState(offer.type);
  const [initial, setInitial] = useState(offer.initial ?? "");
  const [comment, setComment] = useState(offer.comment ?? "");
  const [problem, setProblem] = useState<string | null>(null);
  const typeField = useRef<HTMLInputElement>(null);
  // Opens with the type selected (typing replaces it); closing gives the focus back to where it was (the editor).
  useEffect(() => {
    const before = document.activeElement instanceof HTMLElement ? document.activeElement : null;
    typeField.current?.focus();
    typeField.current?.select();
    return () => {
      const lost = !document.activeElement || document.activeElement === document.body;
      if (lost && before?.isConnected) before.focus();
    };
  }, []);

  // Type completion: shown once the user types, closed by picking one, by Escape or by leaving the field.
  const [completing, setCompleting] = useState(false);
  const [active, setActive] = useState(-1);
  const named = useMemo(() => types.map((name) => ({ name })), [types]);
  // Closed as well once the text names a type exactly: the answer is complete.
  const exact = useMemo(() => new Set(types.map((t) => t.toUpperCase())).has(type.trim().toUpperCase()), [types, type]);
  const list = useMemo(() => (completing && !exact ? suggest(type, named) : []), [completing, exact, type, named]);
  const highlighted = active >= 0 ? active : defaultSuggestion(type, list, named);
  const pick = (name: string) => {
    setType(name);
    setCompleting(false);
    setActive(-1);
  };

  const submit = () => {
    const variable: NewVariable = { name: offer.name, type: type.trim(), varClass, initial, comment };
    const why = declareProblem(variable);
    if (why) setProblem(why);
    else onDeclare(variable);
  };

  return (
    <form
      className="declare-dialog"
      role="dialog"
      aria-label={`Declare variable ${offer.name}`}
      onSubmit={(e) => {
        e.preventDefault();
        submit();
      }}
      onKeyDown={(e) => {
        e.stopPropagation(); // the editor's shortcuts do not see keys typed here
        if (e.key === "Escape") {
          e.preventDefault();
          onCancel();
        } else if (e.key === "Enter" && e.target instanceof HTMLSelectElement) {
          e.preventDefault(); // a select does not submit on Enter by itself
          submit();
        }
      }}
    >
      <p className="declare-title">
        <code>{offer.name}</code> is not declared. Declare it:
      </p>
      <label>
        Name
        <input aria-label="Name of the new variable" value={offer.name} readOnly spellCheck={false} />
      </label>
      <label>
        Class
        <select aria-label="Class of the new variable" value={varClass} onChange={(e) => setVarClass(e.target.value)}>
          {DECLARE_CLASSES.map((c) => (
            <option key={c} value={c}>
              {c}
            </option>
          ))}
        </select>
      </label>
      <label>
        Type
        <span className="declare-type">
          <input
            ref={typeField}
            aria-label="Type of the new variable"
            role="combobox"
            aria-expanded={list.length > 0}
            aria-autocomplete="list"
            value={type}
            spellCheck={false}
            onChange={(e) => {
              setType(e.target.value);
              setCompleting(true);
              setActive(-1);
            }}
            onKeyDown={(e) => {
              if (!list.length) return;
              if (e.key === "ArrowDown") {
                e.preventDefault();
                setActive((highlighted + 1) % list.length);
              } else if (e.key === "ArrowUp") {
                e.preventDefault();
                setActive(highlighted <= 0 ? list.length - 1 : highlighted - 1);
              } else if ((e.key === "Enter" || e.key === "Tab") && highlighted >= 0) {
                e.preventDefault();
                e.stopPropagation();
                pick(list[highlighted]!.name);
              } else if (e.key === "Escape") {
                e.preventDefault();
                e.stopPropagation();
                setCompleting(false);
              }
            }}
            onBlur={() => setCompleting(false)}
          />
          {list.length ? (
            <ul role="listbox" className="ld-suggestions" aria-label="Types">
              {list.map((t, i) => (
                <li
                  key={t.name}
                  role="option"
                  aria-selected={i === highlighted}
                  onMouseDown={(e) => {
                    e.preventDefault();
                    pick(t.name);
                  }}
                >
                  {t.name}
                </li>
              ))}
            </ul>
          ) : null}
        </span>
      </label>
      <label>
        Initial value
        <input
          aria-label="Initial value of the new variable"
          value={initial}
          placeholder="none"
          spellCheck={false}
          onChange={(e) => setInitial(e.target.value)}
        />
      </label>
      <label>
        Comment
        <input aria-label="Comment of the new variable" value={comment} onChange={(e) => setComment(e.target.value)} />
      </label>
      {problem ? (
        <p className="declare-problem" role="alert">
          {problem}
        </p>
      ) : null}
      <div className="declare-buttons">
        <button type="submit">Declare {offer.name}</button>
        <button type="button" onClick={onCancel}>
          Cancel
        </button>
      </div>
    </form>
  );
}
