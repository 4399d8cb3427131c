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

  it("shows a method's FB instance variables live and its own from the halted call, the own ones read only (issue 25 item 6; ON-03, ON-09)", () => {
    const member = {
      name: "Bump",
      declarations: "VAR_INPUT\n    Inc : INT;\nEND_VAR",
      call: "Counter.Bump",
      file: "Counter.Bump/body",
    };
    const text = "Count := Count + Inc;";
    const incOf = (value: number) => ({ name: "Inc", kind: "input" as const, type: { name: "INT" }, value });
    act(() =>
      onlineStore.setState({
        phase: "online",
        instances: { Counter: "MAIN.C1" },
        monitor: { ...emptyMonitor, values: { "MAIN.C1.COUNT": 4 } },
      }),
    );
    const write = vi.fn();
    onlineStore.setState({ write });
    const { result } = renderHook(() => useStOnline(counter, text, scope, member));
    expect(onlineStore.getState().views["st:Counter.Bump/body"]?.paths).toEqual(["MAIN.C1.COUNT"]);
    expect(result.current.view?.marks.map((m) => [m.pos, m.shown.text])).toEqual([
      [5, "4"],
      [14, "4"],
    ]); // not halted: no value for the call's own Inc
    // halted in the method on instance MAIN.C2: its Count, and Inc = 2 from the call stack
    act(() =>
      onlineStore.setState({
        monitor: {
          ...emptyMonitor,
          state: "halted",
          at: { pou: "COUNTER.BUMP", instance: "MAIN.C2", line: 1 },
          stack: [{ kind: "method", at: { pou: "COUNTER.BUMP", instance: "MAIN.C2", line: 1 }, variables: [incOf(2)] }],
          values: { "MAIN.C2.COUNT": 9 },
        },
      }),
    );
    expect(result.current.instance).toBe("MAIN.C2");
    expect(result.current.callShown).toBe(true);
    expect(result.current.view?.marks.map((m) => [m.pos, m.shown.text])).toEqual([
      [5, "9"],
      [14, "9"],
      [20, "2"],
    ]);
    const [, , inc] = result.current.view!.occurrences;
    expect(result.current.view?.describe(inc!)).toBe("Inc : INT = 2 (this call's input)");
    act(() => result.current.view?.onMenu(inc!, 10, 10));
    expect(result.current.overlay).toBeTruthy();
    const { rerender, unmount } = render(<>{result.current.overlay}</>);
    expect(screen.queryByRole("menuitem")).toBeNull(); // the call's own variable has no path: no write or force
    // the instance's Count is written from the method body as from the FB body: the halted call's instance's
    act(() => result.current.view!.onMenu(result.current.view!.occurrences[0]!, 10, 10));
    rerender(<>{result.current.overlay}</>);
    fireEvent.click(screen.getByRole("menuitem", { name: "Write value of Count…" }));
    rerender(<>{result.current.overlay}</>);
    fireEvent.change(screen.getByLabelText("Value"), { target: { value: "42" } });
    fireEvent.click(screen.getByRole("button", { name: "OK" }));
    expect(write).toHaveBeenCalledWith("MAIN.C2.COUNT", 42);
    unmount();
  });
});
