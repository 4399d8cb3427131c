// What the LD/FBD operand editor offers after a qualifier (`T1.`, `Prog.`, `Color.`, `Color#`): the same answer as
// ST completion's (members.ts `membersAfter`), over the POU's symbols and the working copy's function blocks,
// STRUCTs, INTERFACEs, enumerations and programs.
import { useMemo } from "react";
import type { SymbolInfo } from "../generated/api";
import { useWorkspace } from "../store/project";
import type { MembersAfter } from "../ui/OperandEditor";
import { membersAfter, type Scope } from "./members";
import { projectScope } from "./qualifiers";
import { workingLibrary } from "./scope";

export function useOperandMembers(symbols: readonly SymbolInfo[]): MembersAfter {
  const project = useWorkspace((s) => s.project);
  const saved = useWorkspace((s) => s.library);
  const pous = project?.pous;
  const types = project?.types ?? "";
  return useMemo(() => {
    const scope: Scope = { symbols, library: workingLibrary(saved, pous ?? []), ...projectScope(pous ?? [], types) };
    return (chain, separator) => membersAfter(chain, scope, separator);
  }, [symbols, saved, pous, types]);
}
