// @vitest-environment jsdom
import { act, fireEvent, render, screen, within } from "@testing-library/react";
import { useState } from "react";
import { afterEach, beforeEach, describe, expect, it, vi } from "vitest";
import { LdEditor } from "../ld/editor/LdEditor";
import { LIBRARY, motorMain } from "../ld/fixtures";
import { historyOf } from "../store/history";
import type { LdBody } from "../ld/model";
import { emptyMonitor } from "../online/monitor";
import type { ClientMessage } from "../online/protocol";
import { offline, onlineStore } from "../online/store";
import { ldDebugMarks, useLdDebugging } from "./ldDebugging";
import { debugStore } from "./store";

const realSend = onlineStore.getState().send;
let send = vi.fn((_msg: ClientMessage) => true);

beforeEach(() => {
  send = vi.fn((_msg: ClientMessage) => true);
  onlineStore.setState({ phase: "online", send });
});
afterEach(() => {
  onlineStore.setState({ ...offline, send: realSend });
  debugStore.setState({ breakpoints: [], disabled: [] });
});

/** The Main POU of the motor example in the LD editor, wired to the debug store as in the app. */
function setup(body: LdBody = motorMain) {
  function Host() {
    const [history, setHistory] = useState(() => historyOf(body));
    const debugging = useLdDebugging("Main", history.present);
    return <LdEditor history={history} onHistoryChange={setHistory} library={LIBRARY} debugging={debugging} />;
  }
  const view = render(<Host />);
  const network = (n: number) => view.container.querySelectorAll("svg.ld-network")[n - 1]!;
  const dots = () =>
    [...view.container.querySelectorAll(".ld-breakpoint")].map(
      (d) => `${d.getAttribute("aria-label")}${d.classList.contains("ld-breakpoint-disabled") ? " hollow" : ""}`,
    );
  const hit = (id: string) => view.container.querySelector(`[data-id="${id}"] .ld-hit`)!;
  const editor = screen.getByRole("application", { name: "Ladder diagram editor" });
  return { ...view, network, dots, hit, editor };
}

const sent = () => send.mock.calls.map(([m]) => m);

describe("breakpoints in the LD diagram (issue 9)", () => {
  it("a click on a network number toggles a breakpoint on that network, drawn as a dot", () => {
    const t = setup();
    fireEvent.click(screen.getByRole("button", { name: "Toggle breakpoint on network 2" }));
    expect(debugStore.getState().breakpoints).toEqual([{ pou: "Main", network: "run_timer" }]);
    expect(t.dots()).toEqual(["Breakpoint on network 2"]);
    expect(within(t.network(2) as HTMLElement).getAllByRole("img", { name: "Breakpoint on network 2" })).toHaveLength(
      1,
    );
    act(() => debugStore.getState().setEnabled({ pou: "Main", network: "run_timer" }, false));
    expect(t.dots()).toEqual(["Breakpoint on network 2 (disabled) hollow"]);
    fireEvent.click(screen.getByRole("button", { name: "Toggle breakpoint on network 2" }));
    expect(t.dots()).toEqual([]);
    expect(sent()).toEqual([
      { type: "breakpoint_set", pou: "Main", network: "run_timer" },
      { type: "breakpoint_clear", pou: "Main", network: "run_timer" },
    ]);
  });

  it("Alt+click, F9 and the context menu toggle a breakpoint on an element; F9 on a network toggles the network's", () => {
    const t = setup();
    fireEvent.mouseDown(t.hit("motor"), { altKey: true });
    expect(t.dots()).toEqual(["Breakpoint on element motor"]);
    fireEvent.mouseDown(t.hit("stop"));
    fireEvent.keyDown(t.editor, { key: "F9" });
    fireEvent.contextMenu(t.hit("ton"));
    fireEvent.click(screen.getByRole("menuitem", { name: /Toggle breakpoint on element/ }));
    fireEvent.keyDown(t.editor, { key: "F9" }); // ton is selected: toggles it off again
    fireEvent.mouseDown(t.network(4).querySelector(".ld-header-bg")!);
    fireEvent.keyDown(t.editor, { key: "F9" });
    expect(sent()).toEqual([
      { type: "breakpoint_set", pou: "Main", element: "motor" },
      { type: "breakpoint_set", pou: "Main", element: "stop" },
      { type: "breakpoint_set", pou: "Main", element: "ton" },
      { type: "breakpoint_clear", pou: "Main", element: "ton" },
      { type: "breakpoint_set", pou: "Main", network: "lamp" },
    ]);
    expect(t.dots()).toEqual(["Breakpoint on element stop", "Breakpoint on element motor", "Breakpoint on network 4"]);
  });

  it("highlights the network (and element) where the scan halted, and moves with a step", () => {
    const t = setup();
    const halted = () =>
      [...t.container.querySelectorAll(".ld-network.ld-halted, .ld-element.ld-halted")].map(
        (e) => e.getAttribute("data-network") ?? e.getAttribute("data-id"),
      );
    expect(halted()).toEqual([]);
    act(() =>
      onlineStore.setState({
        monitor: { ...emptyMonitor, state: "halted", at: { pou: "MAIN", instance: "MAIN", network: "count_starts" } },
      }),
    );
    expect(halted()).toEqual(["count_starts"]);
    act(() =>
      onlineStore.setState({
        monitor: {
          ...emptyMonitor,
          state: "halted",
          at: { pou: "MAIN", instance: "MAIN", network: "seal_in", element: "motor" },
        },
      }),
    );
    expect(halted()).toEqual(["seal_in", "motor"]);
    act(() => onlineStore.setState({ monitor: { ...emptyMonitor, state: "running", at: null } }));
    expect(halted()).toEqual([]);
  });
});

describe("ldDebugMarks", () => {
  it("keeps the POU's breakpoints only, with their enabled state, and finds the network of a halted element", () => {
    const marks = ldDebugMarks(
      "Main",
      motorMain,
      [
        { pou: "MAIN", network: "lamp" },
        { pou: "Main", element: "ton" },
        { pou: "Other", network: "lamp" },
        { pou: "Main", line: 3 },
      ],
      ["MAIN|element:ton"],
      { pou: "main", instance: "MAIN", element: "running" },
    );
    expect(marks).toEqual({
      networks: { lamp: true },
      elements: { ton: false },
      halted: { network: "run_timer", element: "running" },
    });
    expect(
      ldDebugMarks("Main", motorMain, [], [], { pou: "Blinker", instance: "MAIN.BLINK", line: 2 }).halted,
    ).toBeNull();
  });
});
