// Live diagnostics for the ST editor: the working copy (unsaved edits included) goes to
// `POST /api/check` after the user pauses typing, and the answer becomes the underlines. An answer
// counts only while the working copy it was computed for is still the current one, so a slow,
// older check never overwrites a newer one or marks text that has changed since.
import { useEffect, useState } from "react";
import { checkUnsaved } from "../api/client";
import type { CheckReport, Diagnostic } from "../generated/api";
import type { Project } from "../generated/api";

export const CHECK_DELAY_MS = 500;

export function useLiveCheck(
  project: Project | null,
  check: (project: Project) => Promise<CheckReport> = checkUnsaved,
): Diagnostic[] {
  const [diagnostics, setDiagnostics] = useState<Diagnostic[]>([]);
  useEffect(() => {
    if (!project) return;
    let current = true;
    const timer = setTimeout(() => {
      check(project).then(
        (report) => current && setDiagnostics(report.diagnostics),
        () => current && setDiagnostics([]), // no answer: show no marks rather than marks of older text
      );
    }, CHECK_DELAY_MS);
    return () => {
      current = false;
      clearTimeout(timer);
    };
  }, [project, check]);
  return diagnostics;
}
