// The Variables view of a POU (ON-10): the instance the online views show (a program is its own; a
// function block the instance picked) as a tree of its variables, FB instances, structures and
// arrays, with values, types, forced marks and in-place write, like CODESYS's declaration view online.
import { useState, type ReactNode } from "react";
import type { Pou } from "../generated/api";
import { pathKey } from "../online/monitor";
import { useOnline } from "../online/store";
import { useShownInstance } from "../online/editorOnline";
import { ChildRows, TreeHead, type Expansion } from "../panels/VariableTree";

export function VariablesView({ pou, instancePicker }: { pou: Pou; instancePicker?: ReactNode }) {
  const phase = useOnline((s) => s.phase);
  const instance = useShownInstance(pou);
  const [open, setOpen] = useState<ReadonlySet<string>>(new Set());
  const expansion: Expansion = {
    isOpen: (path) => open.has(pathKey(path)),
    toggle: (path) => {
      const next = new Set(open);
      if (!next.delete(pathKey(path))) next.add(pathKey(path));
      setOpen(next);
    },
  };
  if (phase !== "online")
    return (
      <div className="variables-view">
        <p className="panel-empty">
          Go online (Compile &amp; simulate) to see the variables of {pou.name} with their values.
        </p>
      </div>
    );
  return (
    <div className="variables-view">
      {pou.kind === "function_block" ? <div className="variables-instance">{instancePicker}</div> : null}
      {instance ? (
        <table className="watch-table" aria-label={`Variables of ${instance}`}>
          <TreeHead />
          <tbody>
            <ChildRows path={instance} depth={0} expansion={expansion} />
          </tbody>
        </table>
      ) : (
        <p className="panel-empty">
          {pou.kind === "function"
            ? "A function keeps no variables between calls."
            : `Pick the instance of ${pou.name} to show.`}
        </p>
      )}
    </div>
  );
}
