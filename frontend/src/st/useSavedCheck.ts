// Diagnostics for the ST editor from `POST /check`. The server checks the *saved* project, so a
// check runs (debounced) whenever the POU is in its saved state - on opening and after each save -
// and results are kept only if it is still saved when they arrive; the editor's lint state then
// maps the underlines through later edits until the next save.
import { useEffect, useState } from "react";
import { checkProject } from "../api/client";
import type { CheckReport, Diagnostic } from "../generated/api";

export const CHECK_DELAY_MS = 400;

export function useSavedCheck(project: string, revision: string | null, unsaved: boolean, check: (project: string) => Promise<CheckReport> = checkProject): Diagnostic[] {
  const [diagnostics, setDiagnostics] = useState<Diagnostic[]>([]);
  useEffect(() => {
    if (unsaved) return;
    let live = true;
    const timer = setTimeout(() => {
      check(project).then(
        (report) => live && setDiagnostics(report.diagnostics),
        () => live && setDiagnostics([]),
      );
    }, CHECK_DELAY_MS);
    return () => {
      live = false;
      clearTimeout(timer);
    };
  }, [project, revision, unsaved, check]);
  return diagnostics;
}
