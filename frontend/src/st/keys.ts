// The ST editor's keys (scope "st" of src/keys/keymap.ts) as a CodeMirror keymap: what each command
// of the table runs. They take precedence over CodeMirror's standard keymaps (which stay for plain
// text editing: arrows, Home/End, selection).
import { findReferencesAtCursor } from "../xref/stReferences";
import { startCompletion } from "@codemirror/autocomplete";
import { indentLess, indentMore, redo, undo } from "@codemirror/commands";
import { foldCode, unfoldCode } from "@codemirror/language";
import type { Command, KeyBinding } from "@codemirror/view";
import { codeMirrorKeys, KEYMAP, type CommandOf } from "../keys/keymap";

/** The keymap's ST bindings; `toggleBreakpoint` (F9, the cursor's line) only where breakpoints can be set. */
export function stKeys(toggleBreakpoint: ((line: number) => void) | null): KeyBinding[] {
  const commands: Record<CommandOf<"st">, Command> = {
    "toggle-breakpoint": (view) => {
      if (!toggleBreakpoint) return false;
      toggleBreakpoint(view.state.doc.lineAt(view.state.selection.main.head).number);
      return true;
    },
    complete: startCompletion,
    undo,
    redo,
    fold: foldCode,
    unfold: unfoldCode,
    indent: indentMore,
    unindent: indentLess,
    "find-references": findReferencesAtCursor,
  };
  return KEYMAP.filter((b) => b.scope === "st").flatMap((b) =>
    codeMirrorKeys(b.keys).map((key) => ({ key, run: commands[b.command as CommandOf<"st">], preventDefault: true })),
  );
}
