// "New from example": the shipped examples (GET /api/examples), each copied as a new project, starting
// from the student's files of an exercise or from its reference solution.
import { useEffect, useState, type FormEvent } from "react";
import { http, unwrap } from "../api/client";
import type { ExampleInfo } from "../generated/api";
import { appStore } from "../store/workspace";
import { FormError } from "../ui/FormError";

export function NewFromExample() {
  const [open, setOpen] = useState(false);
  const [examples, setExamples] = useState<ExampleInfo[] | null>(null);
  const [example, setExample] = useState("");
  const [name, setName] = useState("");
  const [start, setStart] = useState<"exercise" | "solution">("exercise");
  const [error, setError] = useState<string | null>(null);
  const [busy, setBusy] = useState(false);
  useEffect(() => {
    if (!open || examples) return;
    unwrap(http.GET("/api/examples")).then(
      (found) => {
        setExamples(found);
        if (found[0]) {
          setExample(found[0].name);
          setName(found[0].name);
        }
      },
      (err: unknown) => setError(err instanceof Error ? err.message : String(err)),
    );
  }, [open, examples]);
  if (!open)
    return (
      <button type="button" className="new-project-button" onClick={() => setOpen(true)}>
        New from example
      </button>
    );
  const chosen = examples?.find((e) => e.name === example);
  const submit = async (e: FormEvent) => {
    e.preventDefault();
    setBusy(true);
    try {
      await unwrap(
        http.POST("/api/projects", {
          body: { name: name.trim(), example, start: chosen?.exercise ? start : "solution" },
        }),
      );
      await appStore.getState().loadProjects();
      appStore.getState().selectProject(name.trim());
      setOpen(false);
      setError(null);
    } catch (err) {
      setError(err instanceof Error ? err.message : String(err));
    } finally {
      setBusy(false);
    }
  };
  return (
    <form className="new-project" aria-label="New from example" onSubmit={(e) => void submit(e)}>
      <select
        aria-label="Example"
        value={example}
        onChange={(e) => {
          setExample(e.target.value);
          setName(e.target.value);
        }}
      >
        {(examples ?? []).map((ex) => (
          <option key={ex.name} value={ex.name}>
            {ex.title}
          </option>
        ))}
      </select>
      {chosen ? <p className="project-meta">{chosen.summary}</p> : null}
      {chosen?.exercise ? (
        <select
          aria-label="Start from"
          value={start}
          onChange={(e) => setStart(e.target.value as "exercise" | "solution")}
        >
          <option value="exercise">the exercise (write the program)</option>
          <option value="solution">the reference solution</option>
        </select>
      ) : null}
      <input aria-label="New project name" value={name} onChange={(e) => setName(e.target.value)} spellCheck={false} />
      <button type="submit" disabled={busy || !example || !name.trim()}>
        Create
      </button>
      <button type="button" onClick={() => setOpen(false)}>
        Cancel
      </button>
      <FormError error={error} className="new-project-error" />
    </form>
  );
}
