// The plumbing between a diagram editor's clipboard (LD, FBD and SFC alike) and the browser's: the copy,
// cut and paste events on the editor, and toolbar/menu Copy and Paste through navigator.clipboard,
// which fall back to the last clip copied in this tab when the browser keeps its clipboard closed.
import type { ClipboardEvent } from "react";

export interface DiagramClipboard {
  /** The selection as clip text (cut: the selection is also deleted); null when nothing is selected. */
  take(cut: boolean): string | null;
  /** Pastes clip text (null: the clipboard had none); the editor says what is wrong with it. */
  paste(text: string | null): void;
  /** Whether `text` is this editor's clip format. */
  isClip(text: string): boolean;
  /** Pasting is refused (read-only). */
  locked: boolean;
}

/** The last clip an editor kind copied in this tab (one box per kind: LD never pastes FBD). */
export interface LastClip {
  text: string | null;
}

const inField = (event: ClipboardEvent<HTMLElement>) =>
  (event.target as HTMLElement).closest("input, textarea") !== null;

export function clipboardActions(editor: DiagramClipboard, last: LastClip) {
  const copyWith = (cut: boolean, write: (text: string) => void) => {
    const text = editor.take(cut);
    if (text === null) return;
    last.text = text;
    write(text);
  };
  /** The editor's onCopy/onCut: the clip goes to the event's clipboard (text fields keep their own). */
  const onCopy = (event: ClipboardEvent<HTMLElement>, cut: boolean) => {
    if (inField(event)) return;
    event.preventDefault();
    copyWith(cut, (text) => event.clipboardData.setData("text/plain", text));
  };
  const onPaste = (event: ClipboardEvent<HTMLElement>) => {
    if (inField(event)) return;
    event.preventDefault();
    if (!editor.locked) editor.paste(event.clipboardData.getData("text/plain"));
  };
  return {
    /** The editor root's clipboard event props (LD, FBD and SFC spread them on their root element). */
    events: {
      onCopy: (event: ClipboardEvent<HTMLElement>) => onCopy(event, false),
      onCut: (event: ClipboardEvent<HTMLElement>) => onCopy(event, true),
      onPaste,
    },
    /** Toolbar or menu Copy/Cut. */
    copy(cut: boolean) {
      copyWith(cut, (text) => void navigator.clipboard?.writeText(text).catch(() => undefined));
    },
    /** Toolbar or menu Paste. */
    paste() {
      const read = navigator.clipboard?.readText?.();
      if (!read) editor.paste(last.text);
      else
        read.then(
          (text) => editor.paste(editor.isClip(text) ? text : last.text),
          () => editor.paste(last.text),
        );
    },
  };
}
