// Backend diagnostics (1-based line/column, end column exclusive, relative to one text) as
// CodeMirror lint diagnostics (document offsets). A diagnostic without a line marks the first
// line; positions beyond the text are clamped, since the text may have changed since the check.
import type { Diagnostic as LintDiagnostic } from "@codemirror/lint";
import type { Text } from "@codemirror/state";
import type { Diagnostic } from "../generated/api";

const UNKNOWN_VARIABLE = /^unknown variable '([A-Za-z_][A-Za-z0-9_]*)'/;

/** The name an "unknown variable" diagnostic is about (the ST quick fix declares it), else null. */
export function undeclaredName(d: Diagnostic): string | null {
  return d.code === "ST-UNKNOWN-VAR" ? (UNKNOWN_VARIABLE.exec(d.message)?.[1] ?? null) : null;
}

/** The diagnostics whose `file` is `file` (case-insensitive, e.g. "Main/body"), as lint marks; with `declare`, an
 * unknown variable's mark has the quick fix "Declare NAME" (Shift+F2 at the cursor runs it). */
export function lintDiagnostics(
  diagnostics: Diagnostic[],
  file: string,
  doc: Text,
  declare?: (name: string) => void,
): LintDiagnostic[] {
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
      const name = declare ? undeclaredName(d) : null;
      const actions = name ? [{ name: `Declare ${name}`, apply: () => declare!(name) }] : undefined;
      return {
        from,
        to: Math.max(to, from),
        severity: d.severity ?? "error",
        message: `${d.code}: ${d.message}`,
        ...(actions ? { actions } : {}),
      };
    });
}
