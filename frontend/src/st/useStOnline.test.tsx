// @vitest-environment jsdom
import { act, fireEvent, render, renderHook, screen } from "@testing-library/react";
import { afterEach, describe, expect, it, vi } from "vitest";
import type { LibraryEntry } from "../generated/api";
import type { Pou } from "../generated/api";
import { emptyMonitor } from "../online/monitor";
import { offline, onlineStore } from "../online/store";
import { structTypes, type Scope } from "./members";
import { useStOnline } from "./useStOnline";
import { symbol } from "../test/symbols";

const counter: Pou = { name: "Counter", kind: "function_block", language: "st", declarations: "", body: "" };
const BODY = "IF Enable THEN\n    Count := Count + 1;\nEND_IF;";
const scope: Scope = {
  symbols: [symbol("Enable", "BOOL", "VAR_INPUT"), symbol("Count", "INT", "VAR_OUTPUT")],
  library: [] as LibraryEntry[],
  structs: structTypes(""),
};
const paths = () => onlineStore.getState().views["st:Counter"]?.paths ?? null;

afterEach(() => onlineStore.setState({ ...offline, instances: {} }));

describe("useStOnline (issue 9: ST online values, values of the halt)", () => {
  it("subscribes nothing offline, the chosen FB instance online, and the halted instance while halted here", () => {
    const { result, unmount } = renderHook(() => useStOnline(counter, BODY, scope));
    expect(paths()).toBeNull();
    expect(result.current.view).toBeUndefined();
    act(() => onlineStore.setState({ phase: "online", instances: { Counter: "MAIN.C1" } }));
    expect(result.current.instance).toBe("MAIN.C1");
    expect(paths()).toEqual(["MAIN.C1.ENABLE", "MAIN.C1.COUNT"]);
    act(() =>
      onlineStore.setState({
        monitor: { ...emptyMonitor, state: "halted", at: { pou: "COUNTER", instance: "MAIN.C2", line: 2 } },
      }),
    );
    expect(result.current.instance).toBe("MAIN.C2");
    expect(paths()).toEqual(["MAIN.C2.ENABLE", "MAIN.C2.COUNT"]);
    act(() =>
      onlineStore.setState({
        monitor: { ...emptyMonitor, state: "halted", at: { pou: "MAIN", instance: "MAIN", line: 1 } },
      }),
    );
    expect(result.current.instance).toBe("MAIN.C1");
    unmount();
    expect(paths()).toBeNull();
  });

  it("marks the monitor's values, hides them when toggled off, and writes from the menu", () => {
    act(() =>
      onlineStore.setState({
        phase: "online",
        instances: { Counter: "MAIN.C1" },
        monitor: { ...emptyMonitor, values: { "MAIN.C1.COUNT": 3, "MAIN.C1.ENABLE": true } },
      }),
    );
    const write = vi.fn();
    onlineStore.setState({ write }); // the store's own write needs a socket; this one records the call
    const { result } = renderHook(() => useStOnline(counter, BODY, scope));
    expect(result.current.view?.marks.map((m) => m.shown.text)).toEqual(["TRUE", "3", "3"]);
    expect(result.current.view?.describe(result.current.view.occurrences[1]!)).toBe("Count : INT = 3");
    act(() => result.current.setShowValues(false));
    expect(result.current.view?.marks).toEqual([]);

    // The menu of an INT offers no Force TRUE/FALSE; a value typed into the prompt is written.
    const count = result.current.view!.occurrences[1]!;
    act(() => result.current.view!.onMenu(count, 10, 10));
    const { rerender } = render(<>{result.current.overlay}</>);
    expect(screen.getAllByRole("menuitem").map((m) => m.textContent)).toEqual([
      "Write value of Count…",
      "Force value…",
      "Release force",
      "Add to watch list",
    ]);
    fireEvent.click(screen.getByRole("menuitem", { name: "Write value of Count…" }));
    rerender(<>{result.current.overlay}</>);
    fireEvent.change(screen.getByLabelText("Value"), { target: { value: "42" } });
    fireEvent.click(screen.getByRole("button", { name: "OK" }));
    expect(write).toHaveBeenCalledWith("MAIN.C1.COUNT", 42);
  });
});
