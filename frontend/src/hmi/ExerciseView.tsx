// The project's exercise statement (EXERCISE.md), rendered from Markdown; Edit shows the text to change.
// markdown-it with HTML off escapes any markup in the text, so a statement cannot run script in the page.
import MarkdownIt from "markdown-it";
import { useMemo, useState } from "react";
import { useWorkspace, workspaceStore } from "../store/project";
import { EXERCISE_TAB } from "../store/parts";

const markdown = new MarkdownIt({ html: false, linkify: true });

/** The statement as HTML (links open outside the app). */
export function renderExercise(text: string): string {
  return markdown.render(text).replace(/<a href=/g, '<a target="_blank" rel="noreferrer" href=');
}

export function ExerciseView() {
  const text = useWorkspace((s) => s.project?.exercise ?? "");
  const [editing, setEditing] = useState(false);
  const html = useMemo(() => renderExercise(text), [text]);
  return (
    <div className="pou-view">
      <div className="pou-modes" role="tablist" aria-label="Exercise views">
        <button type="button" role="tab" aria-selected={!editing} onClick={() => setEditing(false)}>
          Statement
        </button>
        <button type="button" role="tab" aria-selected={editing} onClick={() => setEditing(true)}>
          Edit
        </button>
      </div>
      {editing ? (
        <textarea
          aria-label="Exercise statement (Markdown)"
          className="hmi-exercise-text"
          value={text}
          style={{ width: "100%", height: "100%", fontFamily: "monospace" }}
          onChange={(e) =>
            workspaceStore
              .getState()
              .setProjectPart(EXERCISE_TAB, (project) => ({ ...project, exercise: e.target.value }))
          }
        />
      ) : text.trim() ? (
        // markdown-it escapes HTML (html: false): the statement cannot put markup into the page
        <article className="hmi-exercise" aria-label="Exercise statement" dangerouslySetInnerHTML={{ __html: html }} />
      ) : (
        <p className="placeholder">This project has no exercise statement. Edit writes one (EXERCISE.md).</p>
      )}
    </div>
  );
}
