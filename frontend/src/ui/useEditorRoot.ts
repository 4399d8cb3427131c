// The wiring every diagram editor (LD, FBD, SFC) needs on its root element, in one hook (issue 19):
// focusable, its keys looked up in the keymap (src/keys/keymap.ts) and run by the editor's handlers,
// copy/cut/paste as the browser's clipboard events (they reach the system clipboard; toolbar and menu
// go through navigator.clipboard, ui/systemClipboard.ts), and Ctrl+wheel zooming the diagram instead
// of the page.
import { useEffect, useRef, type KeyboardEvent, type RefObject } from "react";
import { commandsFor, type CommandOf, type KeyScope } from "../keys/keymap";
import { clipboardActions, type DiagramClipboard, type LastClip } from "./systemClipboard";
import type { ZoomStep } from "./zoom";

type ClipboardCommand = "copy" | "cut" | "paste";
/** A scope's commands besides the clipboard's, each returning whether it acted (false: the key goes on). */
export type KeyHandlers<S extends KeyScope> = Record<Exclude<CommandOf<S>, ClipboardCommand>, () => boolean>;

const CLIPBOARD_COMMANDS: ReadonlySet<string> = new Set<ClipboardCommand>(["copy", "cut", "paste"]);
/** Keys typed into these belong to them, not to the diagram. */
const FIELDS = "input, select, textarea, .ld-context-menu";

export interface EditorRootOptions<S extends KeyScope> {
  /** The editor's root element (the editor keeps the ref: its effects focus it). */
  root: RefObject<HTMLDivElement | null>;
  scope: S;
  /** The handlers for this key press (some need its key, e.g. the arrows' direction). */
  handlers(event: KeyboardEvent<HTMLElement>): KeyHandlers<S>;
  /** An overlay (operand editor, picker) has the keys: the diagram ignores them. */
  busy?: boolean;
  clipboard: DiagramClipboard;
  /** The editor kind's last clip in this tab (one box per kind: LD never pastes FBD). */
  last: LastClip;
  /** Ctrl+wheel over the editor (none: the wheel is left alone). */
  onZoom?(step: ZoomStep): void;
}

/**
 * Runs the first handler of the commands bound to this key press that acts, and keeps the browser from
 * acting on the key too; a clipboard key is left to the browser, which fires the clipboard event.
 * Returns whether a handler acted.
 */
export function runKey<S extends KeyScope>(
  scope: S,
  event: KeyboardEvent<HTMLElement>,
  handlers: KeyHandlers<S>,
): boolean {
  for (const command of commandsFor(scope, event)) {
    if (CLIPBOARD_COMMANDS.has(command)) return false;
    if (handlers[command as Exclude<CommandOf<S>, ClipboardCommand>]()) {
      event.preventDefault();
      return true;
    }
  }
  return false;
}

export function useEditorRoot<S extends KeyScope>(options: EditorRootOptions<S>) {
  const { root } = options;
  const clipboard = clipboardActions(options.clipboard, options.last);
  const onZoom = useRef(options.onZoom);
  useEffect(() => {
    onZoom.current = options.onZoom;
  });
  const zooms = options.onZoom !== undefined;

  // A native listener: React's wheel listeners are passive and cannot stop the browser's page zoom.
  useEffect(() => {
    const editor = root.current;
    if (!editor || !zooms) return;
    const onWheel = (event: WheelEvent) => {
      if (!event.ctrlKey || event.deltaY === 0) return;
      event.preventDefault();
      onZoom.current?.(event.deltaY < 0 ? "in" : "out");
    };
    editor.addEventListener("wheel", onWheel, { passive: false });
    return () => editor.removeEventListener("wheel", onWheel);
  }, [root, zooms]);

  const onKeyDown = (event: KeyboardEvent<HTMLElement>) => {
    if (options.busy || (event.target as HTMLElement).closest(FIELDS)) return;
    // Enter and Space on a focused button (a toolbar's, its More) press that button, not the editor's command
    if ((event.key === "Enter" || event.key === " ") && (event.target as HTMLElement).closest("button")) return;
    runKey(options.scope, event, options.handlers(event));
  };

  return {
    /** Spread on the editor's root element. */
    rootProps: { ref: root, tabIndex: 0, onKeyDown, ...clipboard.events },
    /** Toolbar and menu Copy/Cut and Paste. */
    copy: clipboard.copy,
    paste: clipboard.paste,
    /** Gives the keys back to the diagram (after an overlay closes). */
    focus: () => root.current?.focus(),
  };
}
