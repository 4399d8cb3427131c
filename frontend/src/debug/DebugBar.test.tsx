import type { ClientMessage } from "../online/protocol";
import { act, fireEvent, render, screen } from "@testing-library/react";
import { afterEach, describe, expect, it, vi } from "vitest";
import type { Pou } from "../generated/project";
import { emptyMonitor } from "../online/monitor";
import { offline, onlineStore } from "../online/store";
import { DebugBar } from "./DebugBar";
import { debugStore } from "./store";

const main: Pou = { name: "Main", kind: "program", language: "ld", declarations: "", body: { networks: [{ id: "n1", elements: [] }, { id: "n2", elements: [] }] } };
const networksOf = (pou: string) => (pou.toUpperCase() === "MAIN" ? ["n1", "n2"] : []);
const realSend = onlineStore.getState().send;

afterEach(() => {
  onlineStore.setState({ ...offline, send: realSend });
  debugStore.setState({ breakpoints: [] });
});

describe("DebugBar (issue 9: LD breakpoints and stepping while online)", () => {
  it("toggles a breakpoint on a network, lists it and removes it", () => {
    const send = vi.fn((_msg: ClientMessage) => true);
    onlineStore.setState({ phase: "online", send });
    const reveal = vi.fn();
    render(<DebugBar pou={main} networksOf={networksOf} reveal={reveal} />);
    fireEvent.change(screen.getByLabelText("Breakpoint network"), { target: { value: "n2" } });
    fireEvent.click(screen.getByRole("button", { name: "Toggle breakpoint" }));
    expect(send).toHaveBeenLastCalledWith({ type: "breakpoint_set", pou: "Main", network: "n2" });
    fireEvent.click(screen.getByRole("button", { name: "Main, network 2" }));
    expect(reveal).toHaveBeenLastCalledWith({ pou: "Main", network: "n2", element: null });
    fireEvent.change(screen.getByLabelText("Breakpoint element"), { target: { value: " q1 " } });
    fireEvent.click(screen.getByRole("button", { name: "Toggle breakpoint" }));
    expect(send).toHaveBeenLastCalledWith({ type: "breakpoint_set", pou: "Main", element: "q1" });
    fireEvent.click(screen.getByRole("button", { name: "Remove breakpoint Main, network 2" }));
    expect(send).toHaveBeenLastCalledWith({ type: "breakpoint_clear", pou: "Main", network: "n2" });
    expect(debugStore.getState().breakpoints).toEqual([{ pou: "Main", element: "q1" }]);
  });

  it("when halted, reveals the location and offers Continue / Step network / Step cycle", () => {
    const send = vi.fn((_msg: ClientMessage) => true);
    onlineStore.setState({ phase: "online", send });
    const reveal = vi.fn();
    render(<DebugBar pou={main} networksOf={networksOf} reveal={reveal} />);
    expect(screen.queryByText(/Halted at/)).toBeNull();
    act(() => onlineStore.setState({ monitor: { ...emptyMonitor, state: "halted", at: { pou: "MAIN", instance: "MAIN", network: "n2" } } }));
    expect(screen.getByRole("status").textContent).toContain("Halted at MAIN, network 2");
    expect(reveal).toHaveBeenLastCalledWith({ pou: "MAIN", network: "n2", element: undefined });
    fireEvent.click(screen.getByRole("button", { name: "Step network" }));
    fireEvent.click(screen.getByRole("button", { name: "Step cycle" }));
    fireEvent.click(screen.getByRole("button", { name: "Continue" }));
    expect(send.mock.calls.map(([m]) => m)).toEqual([{ type: "step", granularity: "network" }, { type: "step", granularity: "cycle" }, { type: "continue" }]);
    act(() => onlineStore.setState({ monitor: { ...emptyMonitor, state: "running", at: null } }));
    expect(screen.queryByText(/Halted at/)).toBeNull();
  });

  it("offers Step statement when halted on an ST line", () => {
    const send = vi.fn((_msg: ClientMessage) => true);
    onlineStore.setState({ phase: "online", send, monitor: { ...emptyMonitor, state: "halted", at: { pou: "Calc", instance: "MAIN.C1", line: 4 } } });
    render(<DebugBar pou={main} networksOf={networksOf} reveal={vi.fn()} />);
    expect(screen.getByRole("status").textContent).toContain("Halted at Calc (MAIN.C1), line 4");
    fireEvent.click(screen.getByRole("button", { name: "Step statement" }));
    expect(send).toHaveBeenLastCalledWith({ type: "step", granularity: "statement" });
  });

  it("is hidden offline without breakpoints", () => {
    const { container } = render(<DebugBar pou={main} networksOf={networksOf} reveal={vi.fn()} />);
    expect(container.innerHTML).toBe("");
  });
});
