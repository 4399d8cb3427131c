// What the node components need from the editor, shared through React context so xyflow's node
// data holds only the model node (nodes re-render when the editor's state changes).
import { createContext, useContext, type MouseEvent } from "react";
import type { Diagnostic, SymbolInfo } from "../../generated/api";
import type { MembersAfter } from "../../ui/OperandEditor";
import type { FbdNetwork, FbdNode, NodePins } from "../model";
import type { FbdOnlineView } from "../online";

export interface NodeView {
  pins: NodePins;
  /** 1-based place in the execution order (undefined until known, and for connectors). */
  order?: number;
  diagnostics: readonly Diagnostic[];
  breakpoint: boolean;
  halted: boolean;
  /** A function block: the instance name is shown (and edited) above it. */
  fb: boolean;
  /** The last test run with coverage never executed or never energised it. */
  coverage?: "never-executed" | "never-energised";
}

export interface FbdEditorApi {
  readOnly: boolean;
  symbols: readonly SymbolInfo[];
  /** What a variable node's autocomplete offers after a qualifier. */
  members?: MembersAfter;
  online?: FbdOnlineView;
  /** The node whose text is being edited. */
  editing: string | null;
  view(network: FbdNetwork, node: FbdNode): NodeView;
  startEdit(id: string): void;
  commitEdit(id: string, text: string): void;
  cancelEdit(): void;
  pinMenu(node: FbdNode, pin: string, side: "in" | "out", event: MouseEvent): void;
  /** Online double-click on a variable node (ON-08): prepares a value (a BOOL toggles, others ask for one). */
  valueDoubleClick(node: FbdNode): void;
  /** Online double-click on a block pin's value: prepares a value for the FB instance's pin or the pin's variable. */
  pinDoubleClick(node: FbdNode, side: "in" | "out", pin: string): void;
}

export const FbdEditorContext = createContext<FbdEditorApi | null>(null);

export function useFbdEditor(): FbdEditorApi {
  const api = useContext(FbdEditorContext);
  if (!api) throw new Error("FBD nodes render inside the FBD editor");
  return api;
}
