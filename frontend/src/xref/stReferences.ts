// "Find all references" in the ST editor: Shift+F12 (src/keys/keymap.ts) on a variable lists its references
// in the Cross references panel (the word at the cursor, resolved in the open POU like any operand).
import type { EditorView } from "@codemirror/view";
import { xrefStore } from "./store";

export function findReferencesAtCursor(view: EditorView): boolean {
  const { state } = view;
  const word = state.wordAt(state.selection.main.head);
  if (!word) return false;
  void xrefStore.getState().find(state.sliceDoc(word.from, word.to));
  return true;
}
