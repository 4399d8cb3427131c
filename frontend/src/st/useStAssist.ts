// What the ST editor of one POU needs from the workspace while the user types: live diagnostics
// of the working copy, the completions (variables, functions, FB types, members) and the scope
// that inline values resolve variables in.
import { useMemo } from "react";
import type { Diagnostic } from "../generated/api";
import type { Pou } from "../generated/api";
import { useWorkspace } from "../store/project";
import { memberCompletions, stCompletions, type StCompletions } from "./completion";
import type { Scope } from "./members";
import { projectScope, withSelf } from "./qualifiers";
import { chartSymbols, stScope, withInherited, workingLibrary } from "./scope";
import { useLiveCheck } from "../store/useLiveCheck";

export function useStAssist(pou: Pou): { diagnostics: Diagnostic[]; completions: StCompletions; scope: Scope } {
  const project = useWorkspace((s) => s.project);
  const saved = useWorkspace((s) => s.library);
  const table = useWorkspace((s) => s.symbols[pou.name]);
  const types = project?.types ?? "";
  const declarations = pou.declarations ?? "";
  const pous = project?.pous;
  const gvls = project?.gvls;
  const library = useMemo(() => workingLibrary(saved, pous ?? []), [saved, pous]);
  const diagnostics = useLiveCheck(project);
  // a function block's instance holds the variables of the FBs it EXTENDS too; programs, enumerations, THIS^ and
  // SUPER^ qualify members; an interface variable has its interface's; an SFC's steps and actions are variables
  const scope = useMemo(() => {
    const own = stScope(table, declarations, types, library);
    const chart = chartSymbols(pou).filter(
      (s) => !own.symbols.some((o) => o.name.toUpperCase() === s.name.toUpperCase()),
    );
    const inherited = withInherited({ ...own, symbols: [...chart, ...own.symbols] }, pou, pous ?? []);
    const project = projectScope(pous ?? [], types, gvls ?? []);
    return { ...inherited, ...project, qualifiers: withSelf(project.qualifiers, pou, pous ?? []) };
  }, [table, declarations, types, library, pou, pous, gvls]);
  const completions = useMemo(
    (): StCompletions => ({
      options: stCompletions([...scope.symbols], library, scope),
      members: (chain, separator) => memberCompletions(chain, scope, separator),
    }),
    [scope, library],
  );
  return { diagnostics, completions, scope };
}
