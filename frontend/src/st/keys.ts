// The ST editor's keys (scope "st" of src/keys/keymap.ts) as a CodeMirror keymap: what each command
// of the table runs. They take precedence over CodeMirror's standard keymaps (which stay for plain
// text editing: arrows, Home/End, selection).
import { findReferencesAtCursor } from "../xref/stReferences";
import { startCompletion } from "@codemirror/autocomplete";
import { indentLess, indentMore, redo, undo } from "@codemirror/commands";
import { foldCode, unfoldCode } from "@codemirror/language";
import { forEachDiagnostic } from "@codemirror/lint";
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
    declare: declareAtCursor,
  };
  return KEYMAP.filter((b) => b.scope === "st").flatMap((b) =>
    codeMirrorKeys(b.keys).map((key) => ({ key, run: commands[b.command as CommandOf<"st">], preventDefault: true })),
  );
}

/** Runs the "Declare ..." quick fix of the diagnostic under the cursor (an unknown variable), if there is one. */
const declareAtCursor: Command = (view) => {
  const head = view.state.selection.main.head;
  let fix: (() => void) | null = null;
  forEachDiagnostic(view.state, (d, from, to) => {
    const action = d.actions?.find((a) => a.name.startsWith("Declare "));
    if (!fix && action && from <= head && head <= to) fix = () => action.apply(view, from, to);
  });
  if (!fix) return false;
  (fix as () => void)();
  return true;
};
