// @vitest-environment jsdom
import { forEachDiagnostic } from "@codemirror/lint";
import { EditorView } from "@codemirror/view";
import { act, fireEvent, render, renderHook } from "@testing-library/react";
import { afterEach, describe, expect, it, vi } from "vitest";
import type { CheckReport, Diagnostic } from "../generated/api";
import type { Project } from "../generated/api";
import { StEditor } from "./StEditor";
import { CHECK_DELAY_MS, useLiveCheck } from "../store/useLiveCheck";

const viewIn = (container: HTMLElement) =>
  EditorView.findFromDOM(container.querySelector(".cm-editor") as HTMLElement)!;
const marks = (view: EditorView) => {
  const out: [number, number, string][] = [];
  forEachDiagnostic(view.state, (d, from, to) => out.push([from, to, d.message]));
  return out;
};
const unknownY: Diagnostic = {
  code: "ST-UNKNOWN-VAR",
  message: "unknown variable 'y'",
  file: "Main/body",
  line: 1,
  column: 6,
  end_line: 1,
  end_column: 7,
};

const NO_COMPLETIONS = { options: [], members: () => null };

afterEach(() => vi.useRealTimers());

describe("StEditor (issue 9: ST editor)", () => {
  it("reports edits, takes text from outside and underlines the diagnostics of its text", () => {
    const onChange = vi.fn();
    const props = { onChange, file: "Main/body", completions: NO_COMPLETIONS, readOnly: null, label: "Main body" };
    const { container, rerender } = render(<StEditor {...props} text="x := y;" diagnostics={[]} />);
    const view = viewIn(container);
    expect(view.state.doc.toString()).toBe("x := y;");
    act(() => view.dispatch({ changes: { from: 0, insert: "  " } }));
    expect(onChange).toHaveBeenLastCalledWith("  x := y;");
    rerender(
      <StEditor {...props} text="a := y;" diagnostics={[unknownY, { ...unknownY, file: "Main/declarations" }]} />,
    );
    expect(view.state.doc.toString()).toBe("a := y;");
    expect(marks(view)).toEqual([[5, 6, "ST-UNKNOWN-VAR: unknown variable 'y'"]]);
    // An edit before the mark moves it with the text.
    act(() => view.dispatch({ changes: { from: 0, insert: "z := 1;\n" } }));
    expect(marks(view)).toEqual([[13, 14, "ST-UNKNOWN-VAR: unknown variable 'y'"]]);
  });

  it("is read-only while online, with the reason shown", () => {
    const props = {
      text: "x := 1;",
      onChange: vi.fn(),
      file: "Main/body",
      diagnostics: [],
      completions: NO_COMPLETIONS,
      label: "Main body",
    };
    const { container, rerender, getByText } = render(<StEditor {...props} readOnly="Online: go offline to edit." />);
    expect(viewIn(container).state.readOnly).toBe(true);
    getByText("Online: go offline to edit.");
    rerender(<StEditor {...props} readOnly={null} />);
    expect(viewIn(container).state.readOnly).toBe(false);
  });
});

describe("useLiveCheck (issue 9: live diagnostics of the unsaved text, debounced)", () => {
  const copy = (body: string): Project => ({
    name: "plant",
    pous: [{ name: "Main", kind: "program", language: "st", declarations: "VAR\nEND_VAR", body }],
  });

  it("checks the working copy once the user pauses, not at every keystroke", async () => {
    vi.useFakeTimers();
    const check = vi.fn(async (): Promise<CheckReport> => ({ diagnostics: [unknownY] }));
    const { result, rerender } = renderHook(({ project }) => useLiveCheck(project, check), {
      initialProps: { project: copy("x := ") },
    });
    await act(async () => vi.advanceTimersByTime(CHECK_DELAY_MS - 1));
    const typed = copy("x := y;");
    rerender({ project: typed });
    await act(async () => vi.advanceTimersByTime(CHECK_DELAY_MS - 1));
    expect(check).not.toHaveBeenCalled();
    await act(async () => vi.advanceTimersByTime(1));
    expect(check).toHaveBeenCalledTimes(1);
    expect(check).toHaveBeenCalledWith(typed);
    expect(result.current).toEqual([unknownY]);
  });

  it("never lets an older answer that arrives later overwrite a newer one", async () => {
    vi.useFakeTimers();
    const pending: ((r: CheckReport) => void)[] = [];
    const check = vi.fn(() => new Promise<CheckReport>((r) => pending.push(r)));
    const { result, rerender } = renderHook(({ project }) => useLiveCheck(project, check), {
      initialProps: { project: copy("x := y;") },
    });
    await act(async () => vi.advanceTimersByTime(CHECK_DELAY_MS));
    rerender({ project: copy("x := 1;") });
    await act(async () => vi.advanceTimersByTime(CHECK_DELAY_MS));
    expect(check).toHaveBeenCalledTimes(2);
    await act(async () => pending[1]!({ diagnostics: [] }));
    await act(async () => pending[0]!({ diagnostics: [unknownY] }));
    expect(result.current).toEqual([]);
  });

  it("drops an answer for text that changed while it was computed", async () => {
    vi.useFakeTimers();
    let resolve: (r: CheckReport) => void = () => undefined;
    const check = vi.fn(() => new Promise<CheckReport>((r) => (resolve = r)));
    const { result, rerender } = renderHook(({ project }) => useLiveCheck(project, check), {
      initialProps: { project: copy("x := y;") },
    });
    await act(async () => vi.advanceTimersByTime(CHECK_DELAY_MS));
    rerender({ project: copy("x := yy;") });
    await act(async () => resolve({ diagnostics: [unknownY] }));
    expect(result.current).toEqual([]);
  });
});

describe("StEditor debugging marks (issue 9: ST line breakpoints, halted line)", () => {
  it("toggles a breakpoint by a gutter click and shows the breakpoint and halted lines", () => {
    const onToggle = vi.fn();
    const props = {
      onChange: vi.fn(),
      file: "Main/body",
      diagnostics: [],
      completions: NO_COMPLETIONS,
      readOnly: null,
      label: "Main body",
      text: "a := 1;\nb := 2;\nc := 3;",
    };
    const { container, rerender } = render(<StEditor {...props} debug={{ breakpoints: [], halted: null, onToggle }} />);
    const view = viewIn(container);
    const gutterEl = container.querySelector(".cm-breakpoint-gutter") as HTMLElement;
    // The gutter finds the line from the click's height (jsdom lays lines out at their default height).
    const lineHeight = view.defaultLineHeight;
    fireEvent.mouseDown(gutterEl, { clientY: lineHeight * 1.5 });
    expect(onToggle).toHaveBeenCalledWith(2);
    rerender(<StEditor {...props} debug={{ breakpoints: [3, 2, 9], halted: 3, onToggle }} />);
    const visibleDots = () =>
      [...container.querySelectorAll(".cm-breakpoint-gutter .cm-gutterElement")].filter(
        (e) => (e as HTMLElement).style.visibility !== "hidden" && e.querySelector(".cm-breakpoint"),
      );
    expect(visibleDots()).toHaveLength(2);
    const halted = container.querySelectorAll(".cm-halted-line");
    expect([...halted].map((l) => l.textContent)).toEqual(["c := 3;"]);
    rerender(<StEditor {...props} debug={{ breakpoints: [], halted: null, onToggle }} />);
    expect(visibleDots()).toHaveLength(0);
    expect(container.querySelectorAll(".cm-halted-line")).toHaveLength(0);
  });
});
