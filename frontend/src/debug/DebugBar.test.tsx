// @vitest-environment jsdom
import type { ClientMessage } from "../online/protocol";
import { act, fireEvent, render, screen } from "@testing-library/react";
import { afterEach, describe, expect, it, vi } from "vitest";
import { emptyMonitor } from "../online/monitor";
import { offline, onlineStore } from "../online/store";
import { DebugBar } from "./DebugBar";
import { debugStore } from "./store";

const networksOf = (pou: string) => (pou.toUpperCase() === "MAIN" ? ["n1", "n2"] : []);
const realSend = onlineStore.getState().send;
const realStop = onlineStore.getState().stop;

afterEach(() => {
  onlineStore.setState({ ...offline, send: realSend, stop: realStop });
  debugStore.setState({ breakpoints: [], disabled: [] });
});

const halt = (at: { pou: string; instance?: string; network?: string; element?: string; line?: number }) =>
  act(() => onlineStore.setState({ monitor: { ...emptyMonitor, state: "halted", at } }));

describe("DebugBar (issue 9: stepping a halted scan)", () => {
  it("when halted, reveals the location and offers Continue / Step over, into, out / Step network / Step cycle / Stop", () => {
    const send = vi.fn((_msg: ClientMessage) => true);
    const stop = vi.fn();
    onlineStore.setState({ phase: "online", send, stop });
    const reveal = vi.fn();
    render(<DebugBar networksOf={networksOf} reveal={reveal} />);
    expect(screen.queryByRole("region", { name: "Debugging" })).toBeNull();
    halt({ pou: "MAIN", instance: "MAIN", network: "n2" });
    expect(screen.getByRole("status").textContent).toBe("Halted at MAIN, network 2");
    expect(reveal).toHaveBeenLastCalledWith({
      pou: "MAIN",
      network: "n2",
      element: undefined,
      line: undefined,
      body: null,
    });
    for (const name of ["Step over", "Step into", "Step out", "Step network", "Step cycle", "Continue"])
      fireEvent.click(screen.getByRole("button", { name }));
    expect(send.mock.calls.map(([m]) => m)).toEqual([
      { type: "step", granularity: "over" },
      { type: "step", granularity: "statement" },
      { type: "step", granularity: "out" },
      { type: "step", granularity: "network" },
      { type: "step", granularity: "cycle" },
      { type: "continue" },
    ]);
    expect(screen.getByRole("button", { name: "Step out" }).getAttribute("title")).toBe("Step out (Shift+F11)");
    fireEvent.click(screen.getByRole("button", { name: "Stop" }));
    expect(stop).toHaveBeenCalledTimes(1);
    act(() => onlineStore.setState({ monitor: { ...emptyMonitor, state: "running", at: null } }));
    expect(screen.queryByRole("region", { name: "Debugging" })).toBeNull();
  });

  it("names the instance and line of a halt in an ST function block and reveals the line", () => {
    onlineStore.setState({ phase: "online", send: vi.fn(() => true) });
    const reveal = vi.fn();
    render(<DebugBar networksOf={networksOf} reveal={reveal} />);
    halt({ pou: "Calc", instance: "MAIN.C1", line: 4 });
    expect(screen.getByRole("status").textContent).toBe("Halted at Calc (MAIN.C1), line 4");
    expect(reveal).toHaveBeenLastCalledWith({
      pou: "Calc",
      network: undefined,
      element: undefined,
      line: 4,
      body: null,
    });
  });

  it("reveals a halt point once: not again when a status repeats it (a write while halted), again when it moves", () => {
    onlineStore.setState({ phase: "online", send: vi.fn(() => true) });
    const reveal = vi.fn();
    render(<DebugBar networksOf={networksOf} reveal={reveal} />);
    halt({ pou: "Calc", instance: "MAIN.C1", line: 4 });
    halt({ pou: "Calc", instance: "MAIN.C1", line: 4 }); // the same point, a new message: the call opened stays
    expect(reveal).toHaveBeenCalledTimes(1);
    halt({ pou: "Calc", instance: "MAIN.C1", line: 5 });
    expect(reveal).toHaveBeenCalledTimes(2);
    expect(reveal).toHaveBeenLastCalledWith({
      pou: "Calc",
      network: undefined,
      element: undefined,
      line: 5,
      body: null,
    });
  });

  it("lists the call stack outermost first; choosing a call opens its POU where it stands", () => {
    onlineStore.setState({ phase: "online", send: vi.fn(() => true) });
    const reveal = vi.fn();
    render(<DebugBar networksOf={networksOf} reveal={reveal} />);
    const stack = [
      { kind: "program" as const, at: { pou: "MAIN", instance: "MAIN", network: "n1" } },
      { kind: "method" as const, at: { pou: "MOTOR.START", instance: "MAIN.M", line: 19 } },
      { kind: "function" as const, at: { pou: "CLAMP", line: 8 } },
    ];
    act(() => onlineStore.setState({ monitor: { ...emptyMonitor, state: "halted", at: stack[2]!.at, stack } }));
    const calls = screen.getByRole("navigation", { name: "Call stack" });
    const items = [...calls.querySelectorAll("li")];
    expect(items.map((li) => li.textContent)).toEqual([
      "MAIN, network 1",
      "MOTOR.START (MAIN.M), line 19",
      "CLAMP, line 8",
    ]);
    expect(items.map((li) => li.getAttribute("aria-current"))).toEqual([null, null, "step"]);
    fireEvent.click(screen.getByRole("button", { name: "MOTOR.START (MAIN.M), line 19" }));
    expect(reveal).toHaveBeenLastCalledWith({
      pou: "MOTOR.START",
      network: undefined,
      element: undefined,
      line: 19,
      body: null,
    });
  });
});
