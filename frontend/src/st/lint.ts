// Backend diagnostics (1-based line/column, end column exclusive, relative to one text) as
// CodeMirror lint diagnostics (document offsets). A diagnostic without a line marks the first
// line; positions beyond the text are clamped, since the text may have changed since the check.
import type { Diagnostic as LintDiagnostic } from "@codemirror/lint";
import type { Text } from "@codemirror/state";
import type { Diagnostic } from "../generated/api";

/** The diagnostics whose `file` is `file` (case-insensitive, e.g. "Main/body"), as lint marks. */
export function lintDiagnostics(diagnostics: Diagnostic[], file: string, doc: Text): LintDiagnostic[] {
  const wanted = file.toUpperCase();
  return diagnostics
    .filter((d) => d.file?.toUpperCase() === wanted)
    .map((d) => {
      const line = doc.line(Math.min(Math.max(d.line ?? 1, 1), doc.lines));
      const from = line.from + Math.min(Math.max((d.column ?? 1) - 1, 0), line.length);
      let to = from;
      if (d.end_line != null && d.end_column != null) {
        const end = doc.line(Math.min(Math.max(d.end_line, 1), doc.lines));
        to = Math.max(from, end.from + Math.min(Math.max(d.end_column - 1, 0), end.length));
      }
      if (to === from) to = d.column == null ? line.to : Math.min(from + 1, line.to);
      return { from, to: Math.max(to, from), severity: d.severity ?? "error", message: `${d.code}: ${d.message}` };
    });
}
