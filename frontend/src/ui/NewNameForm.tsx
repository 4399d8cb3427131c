// A project tree section's "New ..." button opening a one-field form for the new item's name (panels, global
// variable lists): `create` makes the item and returns null, or says why the name cannot be used (kept shown).
import { useState, type FormEvent } from "react";

export function NewNameForm({
  formLabel,
  inputLabel,
  buttonLabel,
  create,
}: {
  formLabel: string;
  inputLabel: string;
  buttonLabel: string;
  create: (name: string) => string | null;
}) {
  const [adding, setAdding] = useState(false);
  const [name, setName] = useState("");
  const [error, setError] = useState<string | null>(null);
  const submit = (e: FormEvent) => {
    e.preventDefault();
    const problem = create(name.trim());
    if (problem) return setError(problem);
    setAdding(false);
    setName("");
    setError(null);
  };
  return adding ? (
    <form className="new-pou" aria-label={formLabel} onSubmit={submit}>
      <input
        aria-label={inputLabel}
        autoFocus
        value={name}
        onChange={(e) => setName(e.target.value)}
        spellCheck={false}
      />
      <button type="submit">Create</button>
      <button type="button" onClick={() => setAdding(false)}>
        Cancel
      </button>
      {error ? <p role="alert">{error}</p> : null}
    </form>
  ) : (
    <button type="button" onClick={() => setAdding(true)}>
      {buttonLabel}
    </button>
  );
}
