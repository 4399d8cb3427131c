// @vitest-environment jsdom
import { act, fireEvent, render, screen, within } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { initialTrace, traceStore } from "./store";
import { statusText, TracePanel } from "./TracePanel";

afterEach(() => traceStore.setState(initialTrace));

const addPath = (text: string) => {
  const input = screen.getByLabelText("Variable to trace");
  fireEvent.change(input, { target: { value: text } });
  fireEvent.submit(input.closest("form")!);
};

describe("TracePanel", () => {
  it("lists the variables added, refuses the 21st with the reason and removes one on ×", () => {
    render(<TracePanel />);
    act(() => {
      for (let i = 1; i <= 19; i++) traceStore.getState().addPath(`Main.V${i}`);
    });
    addPath("Main.V20");
    const list = screen.getByRole("list", { name: "Traced variables" });
    expect(within(list).getAllByRole("listitem")).toHaveLength(20);
    addPath("Main.V21");
    expect(screen.getByRole("alert").textContent).toBe(
      "a trace records at most 20 variables: remove one before adding Main.V21",
    );
    fireEvent.click(screen.getByRole("button", { name: "Stop tracing Main.V1" }));
    expect(within(list).getAllByRole("listitem")).toHaveLength(19);
    expect(screen.getByRole("button", { name: "Start trace" })).toHaveProperty("disabled", false);
  });

  it("shows the streamed samples in the table relative to the first sample, and the state", () => {
    render(<TracePanel />);
    act(() =>
      traceStore.setState({
        paths: ["Main.Q", "Main.ET"],
        phase: "waiting",
        id: 4,
        trigger: { path: "Main.Go", condition: "rising", level: "" },
      }),
    );
    expect(screen.getByRole("status", { name: "Trace state" }).textContent).toBe(
      "Waiting for the trigger: Main.Go rising",
    );
    act(() =>
      traceStore.getState().receive({
        type: "trace_data",
        id: 4,
        state: "recording",
        scans: [3, 4, 5],
        time_ms: [30, 40, 50],
        values: { "MAIN.Q": [false, false, true], "MAIN.ET": [0, 10, 20] },
        triggered: { scan: 3, time_ms: 30 },
        lost: 0,
      }),
    );
    expect(screen.getByRole("status", { name: "Trace state" }).textContent).toBe(
      "Recording · 3 samples · triggered at scan 3",
    );
    expect(screen.getByRole("button", { name: "Stop trace" })).toBeTruthy();
    fireEvent.click(screen.getByLabelText("Table"));
    const rows = within(screen.getByRole("table", { name: "Trace samples" }))
      .getAllByRole("row")
      .map((r) => Array.from(r.children, (c) => c.textContent));
    expect(rows).toEqual([
      ["t (ms)", "scan", "MAIN.Q", "MAIN.ET"],
      ["0", "3", "FALSE", "0"],
      ["10", "4", "FALSE", "10"],
      ["20", "5", "TRUE", "20"],
    ]);
  });

  it("says when a full continuous buffer holds only the newest samples and how many were lost", () => {
    traceStore.setState({ paths: ["Main.N"], phase: "recording", id: 2, capacity: 2 });
    traceStore.getState().receive({
      type: "trace_data",
      id: 2,
      state: "done",
      scans: [1, 2, 3],
      time_ms: [10, 20, 30],
      values: { "MAIN.N": [1, 2, 3] },
      triggered: null,
      lost: 7,
    });
    expect(statusText(traceStore.getState())).toBe(
      "Done · 2 samples (the newest of 3) · 7 samples lost (the connection was too slow)",
    );
  });
});
