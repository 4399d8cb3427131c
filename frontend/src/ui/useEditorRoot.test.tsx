// @vitest-environment jsdom
// The diagram editors' root wiring (issue 19): keys run through the keymap to the editor's handlers,
// fields and overlays keep their keys, clipboard keys are left to the browser's clipboard events, and
// Ctrl+wheel zooms. A small editor of the "fbd" scope stands for LD, FBD and SFC, which all use the hook.
import { createEvent, fireEvent, render, within } from "@testing-library/react";
import { useRef } from "react";
import { describe, expect, it, vi } from "vitest";
import type { KeyHandlers } from "./useEditorRoot";
import { useEditorRoot } from "./useEditorRoot";
import type { ZoomStep } from "./zoom";

function setup(options: { busy?: boolean; deleteActs?: boolean } = {}) {
  const calls: string[] = [];
  const handler =
    (name: string, acts = true) =>
    () => (calls.push(name), acts);
  const handlers: KeyHandlers<"fbd"> = {
    delete: handler("delete", options.deleteActs ?? true),
    undo: handler("undo"),
    redo: handler("redo"),
    "run-earlier": handler("run-earlier"),
    "run-later": handler("run-later"),
    "clear-selection": handler("clear-selection"),
    "toggle-breakpoint": handler("toggle-breakpoint", false),
    "zoom-fit": handler("zoom-fit"),
  };
  const take = vi.fn((cut: boolean) => (cut ? "cut-clip" : "clip"));
  const paste = vi.fn();
  const zoom = vi.fn<(step: ZoomStep) => void>();
  function Editor() {
    const root = useRef<HTMLDivElement>(null);
    const editor = useEditorRoot({
      root,
      scope: "fbd",
      handlers: () => handlers,
      busy: options.busy,
      clipboard: { take, paste, isClip: () => true, locked: false },
      last: { text: null },
      onZoom: zoom,
    });
    return (
      <div {...editor.rootProps} role="application" aria-label="editor">
        <input aria-label="field" />
      </div>
    );
  }
  const view = render(<Editor />);
  const root = within(view.container).getByRole("application");
  const key = (target: HTMLElement, key: string, mods: Partial<KeyboardEventInit> = {}) => {
    const event = createEvent.keyDown(target, { key, ...mods });
    fireEvent(target, event);
    return event.defaultPrevented;
  };
  return { calls, root, field: within(view.container).getByLabelText("field"), key, take, paste, zoom };
}

describe("useEditorRoot", () => {
  it("runs the handler of the pressed key and keeps the browser from acting on it", () => {
    const t = setup();
    expect(t.root.tabIndex).toBe(0);
    expect(t.key(t.root, "Delete")).toBe(true);
    expect(t.key(t.root, "ArrowUp", { altKey: true })).toBe(true);
    expect(t.key(t.root, "H", { ctrlKey: true, shiftKey: true })).toBe(true);
    expect(t.calls).toEqual(["delete", "run-earlier", "zoom-fit"]);
  });

  it("lets the key go on when its handler does not act, or no command has it", () => {
    const t = setup({ deleteActs: false });
    expect(t.key(t.root, "Delete")).toBe(false);
    expect(t.key(t.root, "F9")).toBe(false);
    expect(t.key(t.root, "q")).toBe(false);
    expect(t.calls).toEqual(["delete", "toggle-breakpoint"]);
  });

  it("leaves keys typed into a field, or while an overlay is open, alone", () => {
    const t = setup();
    expect(t.key(t.field, "Delete")).toBe(false);
    const busy = setup({ busy: true });
    expect(busy.key(busy.root, "Delete")).toBe(false);
    expect([...t.calls, ...busy.calls]).toEqual([]);
  });

  it("leaves Ctrl+C, X and V to the browser, whose clipboard events carry the editor's clip", () => {
    const t = setup();
    expect(t.key(t.root, "c", { ctrlKey: true })).toBe(false);
    expect(t.key(t.root, "v", { ctrlKey: true })).toBe(false);
    const data = new Map<string, string>();
    const clipboardData = { setData: (f: string, v: string) => data.set(f, v), getData: () => "pasted" };
    fireEvent.copy(t.root, { clipboardData });
    expect(data.get("text/plain")).toBe("clip");
    fireEvent.cut(t.root, { clipboardData });
    expect([t.take.mock.calls, data.get("text/plain")]).toEqual([[[false], [true]], "cut-clip"]);
    fireEvent.paste(t.root, { clipboardData });
    expect(t.paste).toHaveBeenCalledWith("pasted");
  });

  it("zooms on Ctrl+wheel instead of the page, and leaves the plain wheel to scrolling", () => {
    const t = setup();
    const wheel = (deltaY: number, ctrlKey: boolean) => {
      const event = new WheelEvent("wheel", { deltaY, ctrlKey, cancelable: true });
      t.root.dispatchEvent(event);
      return event.defaultPrevented;
    };
    expect(wheel(-100, true)).toBe(true);
    expect(wheel(100, true)).toBe(true);
    expect(wheel(100, false)).toBe(false);
    expect(t.zoom.mock.calls).toEqual([["in"], ["out"]]);
  });
});
