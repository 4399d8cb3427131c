// @vitest-environment jsdom
import { act, fireEvent, render, screen, within } from "@testing-library/react";
import { afterEach, beforeEach, describe, expect, it, vi } from "vitest";
import { debugStore } from "../debug/store";
import type { SymbolTable } from "../generated/api";
import type { Pou, Project } from "../generated/api";
import { motorMain } from "../ld/fixtures";
import type { ClientMessage } from "../online/protocol";
import { emptyMonitor } from "../online/monitor";
import { offline, onlineStore } from "../online/store";
import { emptyWorkspace, workspaceStore } from "../store/project";
import { breakpointBody, describePlace } from "../breakpointPlaces/place";
import { BreakpointsPanel } from "./BreakpointsPanel";
import { emptyPanels, panelsStore } from "../store/panels";

const project: Project = {
  name: "motor",
  pous: [
    { name: "Main", kind: "program", language: "ld", declarations: "", body: motorMain },
    {
      name: "Blinker",
      kind: "function_block",
      language: "st",
      declarations: "",
      body: "Count := Count + 1;\n  Q := Count > 10;",
    },
  ],
};
const noSymbols = { symbols: [], globals: [], diagnostics: [] } as unknown as SymbolTable;
const realSend = onlineStore.getState().send;
let send = vi.fn((_msg: ClientMessage) => true);

beforeEach(() => {
  send = vi.fn((_msg: ClientMessage) => true);
  onlineStore.setState({ phase: "online", send });
  workspaceStore.setState({
    ...emptyWorkspace,
    name: "motor",
    project,
    symbols: { Main: noSymbols, Blinker: noSymbols },
  });
  const { toggle, setEnabled } = debugStore.getState();
  toggle({ pou: "MAIN", network: "count_starts" });
  toggle({ pou: "Main", element: "motor" });
  toggle({ pou: "Blinker", line: 2 });
  setEnabled({ pou: "Main", element: "motor" }, false);
  send.mockClear();
});

afterEach(() => {
  onlineStore.setState({ ...offline, send: realSend });
  debugStore.setState({ breakpoints: [], disabled: [] });
  workspaceStore.setState(emptyWorkspace);
  panelsStore.setState(emptyPanels);
});

const rows = () => within(screen.getByRole("table", { name: "Breakpoints" })).getAllByRole("row");

describe("Breakpoints panel (issue 9: every breakpoint of the project, enable/disable/remove)", () => {
  it("lists LD network and element breakpoints and ST lines by what they are", () => {
    render(<BreakpointsPanel />);
    expect(rows().map((r) => r.textContent)).toEqual([
      "Main network 3 Count rising edges of Start; Stop with a full count resets×",
      "Main element motor (coil Motor)×",
      "Blinker line 2: Q := Count > 10;×",
    ]);
    const checks = screen.getAllByRole("checkbox") as HTMLInputElement[];
    expect(checks.map((c) => c.checked)).toEqual([true, false, true]);
    expect(describePlace({ pou: "Main", network: "gone" }, project.pous![0], motorMain)).toBe(
      "network gone (not in the POU)",
    );
  });

  it("names the SFC action or transition a line, network or element is in, and describes it in its language", () => {
    const seq: Pou = {
      name: "Seq",
      kind: "program",
      language: "sfc",
      declarations: "",
      body: {
        chart: { elements: [] },
        actions: [
          { name: "Fill", language: "st", body: "n := n + 1;\nm := m + n;" },
          { name: "Lamp", language: "ld", body: motorMain },
        ],
        transitions: [],
      },
    };
    const place = (bp: Parameters<typeof describePlace>[0]) => {
      const { body, language } = breakpointBody(bp, seq);
      return describePlace(bp, seq, body, language);
    };
    expect(place({ pou: "Seq", body: "actions/Fill", line: 2 })).toBe("action Fill, line 2: m := m + n;");
    expect(place({ pou: "Seq", body: "actions/Lamp", element: "motor" })).toBe(
      "action Lamp, element motor (coil Motor)",
    );
    expect(place({ pou: "Seq", body: "actions/Lamp", network: "gone" })).toBe(
      "action Lamp, network gone (not in the action)",
    );
    expect(place({ pou: "Seq", body: "actions/Gone", line: 1 })).toBe("action Gone, line 1");
  });

  it("disables and enables (the simulation is told), removes one and all", () => {
    render(<BreakpointsPanel />);
    fireEvent.click(screen.getByRole("checkbox", { name: "Enable breakpoint Blinker, line 2: Q := Count > 10;" }));
    fireEvent.click(screen.getByRole("checkbox", { name: "Enable breakpoint Main, element motor (coil Motor)" }));
    expect(rows()).toHaveLength(3); // a disabled breakpoint stays listed
    expect(rows()[2]!.className).toContain("breakpoint-disabled");
    fireEvent.click(
      screen.getByRole("button", {
        name: "Remove breakpoint Main, network 3 Count rising edges of Start; Stop with a full count resets",
      }),
    );
    expect(rows()).toHaveLength(2);
    fireEvent.click(screen.getByRole("button", { name: "Remove all breakpoints" }));
    expect(screen.getByText(/No breakpoints\./)).toBeTruthy();
    expect(send.mock.calls.map(([m]) => m)).toEqual([
      { type: "breakpoint_clear", pou: "Blinker", line: 2 },
      { type: "breakpoint_set", pou: "Main", element: "motor" },
      { type: "breakpoint_clear", pou: "MAIN", network: "count_starts" },
      { type: "breakpoint_clear" },
    ]);
  });

  it("a click opens the POU and asks its editor to reveal the place; the halted row is marked", () => {
    render(<BreakpointsPanel />);
    fireEvent.click(screen.getByRole("button", { name: /^Main network 3/ }));
    expect(workspaceStore.getState().active).toBe("Main");
    expect(panelsStore.getState().focus).toMatchObject({
      pou: "Main",
      network: "count_starts",
      element: null,
      line: null,
      part: "body",
    });
    fireEvent.click(screen.getByRole("button", { name: "Blinker line 2: Q := Count > 10;" }));
    expect(workspaceStore.getState().active).toBe("Blinker");
    expect(panelsStore.getState().focus).toMatchObject({ pou: "Blinker", line: 2 });
    act(() =>
      onlineStore.setState({
        monitor: { ...emptyMonitor, state: "halted", at: { pou: "MAIN", instance: "MAIN", network: "count_starts" } },
      }),
    );
    expect(rows().map((r) => r.className.includes("breakpoint-hit"))).toEqual([true, false, false]);
    expect(rows()[0]!.textContent).toContain("halted here");
  });
});
