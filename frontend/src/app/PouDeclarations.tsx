// The Declarations tab of a POU: its declarations table and text, with the types to offer and the problems
// of its declaration text. Loaded when first opened, with the IEC vocabulary it offers (issue 22 item 8).
import { useMemo } from "react";
import type { Diagnostic, Pou } from "../generated/api";
import { DeclarationsEditor } from "../declarations/DeclarationsEditor";
import { usePanels } from "../store/panels";
import { useDeclarableTypes } from "../store/declarableTypes";
import { useWorkspace } from "../store/project";

const NO_DIAGNOSTICS: Diagnostic[] = [];

/** Declarations of one POU with the types to offer and the problems of its declaration text. */
export function PouDeclarations({
  pou,
  readOnly,
  focus,
}: {
  pou: Pou;
  readOnly: string | null;
  focus: { line: number; seq: number } | null;
}) {
  const setDeclarations = useWorkspace((s) => s.setDeclarations);
  const types = useDeclarableTypes();
  const table = useWorkspace((s) => s.symbols[pou.name]);
  const checked = usePanels((s) => s.diagnostics) ?? NO_DIAGNOSTICS;
  const file = `${pou.name}/declarations`.toUpperCase();
  const diagnostics = useMemo(() => {
    const all = [...(table?.diagnostics ?? []), ...checked].filter((d) => d.file?.toUpperCase() === file);
    const seen = new Set<string>();
    return all.filter((d) => {
      const key = `${d.line}:${d.column}:${d.code}:${d.message}`;
      return seen.has(key) ? false : (seen.add(key), true);
    });
  }, [table, checked, file]);
  return (
    <DeclarationsEditor
      text={pou.declarations ?? ""}
      onChange={(text) => setDeclarations(pou.name, text)}
      diagnostics={diagnostics}
      types={types}
      focus={focus}
      readOnly={readOnly}
    />
  );
}
