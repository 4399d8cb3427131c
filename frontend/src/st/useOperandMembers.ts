// The operand editor's members after a qualifier (operandScope.ts) for an LD/FBD POU's symbols: the module is
// loaded when an operand editor first asks (it brings the ST tokenizer, kept out of the app's opening scripts);
// until then nothing is offered after a qualifier, and the editor asks again once it has come.
import { useMemo, useState } from "react";
import type { SymbolInfo } from "../generated/api";
import { useWorkspace } from "../store/project";
import type { MembersAfter } from "../ui/OperandEditor";
import type { operandMembers } from "./operandScope";

type Build = typeof operandMembers;
let loaded: Build | null = null;
let loading: Promise<Build> | null = null;

export function useOperandMembers(symbols: readonly SymbolInfo[]): MembersAfter {
  const project = useWorkspace((s) => s.project);
  const saved = useWorkspace((s) => s.library);
  const [build, setBuild] = useState<Build | null>(() => loaded);
  const pous = project?.pous;
  const types = project?.types ?? "";
  const gvls = project?.gvls;
  return useMemo((): MembersAfter => {
    if (build) return build(symbols, saved, pous ?? [], types, gvls ?? []);
    return () => {
      loading ??= import("./operandScope").then((m) => (loaded = m.operandMembers));
      void loading.then((b) => setBuild(() => b));
      return null; // the names only, until it has come
    };
  }, [build, symbols, saved, pous, types, gvls]);
}
