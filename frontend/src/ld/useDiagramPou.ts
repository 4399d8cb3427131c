// What an LD or FBD POU's editor takes from the workspace and the panels: the library, the POU's
// symbols, its diagnostics (symbols table and the live check of the working copy, those naming a network), the place a
// clicked diagnostic asks to reveal, the members the operand editor offers after a qualifier, and declaring a
// variable typed but not declared.
import { useMemo } from "react";
import type { Diagnostic, LibraryEntry, SymbolInfo } from "../generated/api";
import type { VariableDeclaration } from "./editor/declare";
import { usePanels, type Focus } from "../store/panels";
import { useLiveCheck } from "../store/useLiveCheck";
import { diagramDiagnostics, symbolsOf, useWorkspace } from "../store/project";
import { useOperandMembers } from "../st/useOperandMembers";
import type { MembersAfter } from "../ui/OperandEditor";

export interface DiagramPou {
  library: LibraryEntry[];
  symbols: SymbolInfo[];
  /** The symbol table has arrived: operands can be told apart as the POU's variables or globals. */
  symbolsLoaded: boolean;
  diagnostics: Diagnostic[];
  /** What the operand editor offers after a qualifier (`T1.`, `Prog.`, `Color.`). */
  members: MembersAfter;
  focus: Focus | null;
  declare(declaration: VariableDeclaration): void;
}

export function useDiagramPou(name: string): DiagramPou {
  const library = useWorkspace((s) => s.library);
  const table = useWorkspace((s) => s.symbols[name]);
  const declareIn = useWorkspace((s) => s.declare);
  const project = useWorkspace((s) => s.project);
  // The working copy is checked as it is edited (debounced): its problems show on the elements at once.
  const live = useLiveCheck(project);
  const focus = usePanels((s) => (s.focus?.pou.toUpperCase() === name.toUpperCase() ? s.focus : null));
  const symbols = useMemo(() => symbolsOf(table), [table]);
  const diagnostics = useMemo(() => diagramDiagnostics(table, live, name), [table, live, name]);
  const members = useOperandMembers(symbols);
  return {
    library,
    symbols,
    symbolsLoaded: table !== undefined,
    diagnostics,
    members,
    focus,
    declare: (declaration) => declareIn(name, declaration),
  };
}
