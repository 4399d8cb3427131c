// @vitest-environment jsdom
import { fireEvent, render, screen, within } from "@testing-library/react";
import { afterEach, beforeEach, describe, expect, it } from "vitest";
import type { IoPoint } from "../generated/api";
import { emptyMonitor } from "../online/monitor";
import { offline, onlineStore } from "../online/store";
import { IO_VIEW, IoPanel } from "./IoPanel";

const io: IoPoint[] = [
  { area: "I", address: "%IX0.1", type: "BOOL", names: ["MAIN.START"] },
  { area: "I", address: "%IW2", type: "INT", names: [] },
  { area: "Q", address: "%QX3.0", type: "BOOL", names: ["MAIN.LAMP", "MAIN.COPY"] },
  { area: "M", address: "%MW10", type: "INT", names: [] },
];
const real = onlineStore.getState();
const sent: unknown[] = [];

beforeEach(() => {
  sent.length = 0;
  onlineStore.setState({
    phase: "online",
    write: (path, value) => void sent.push(["write", path, value]),
    force: (path, value) => void sent.push(["force", path, value]),
    unforce: (path) => void sent.push(["unforce", path]),
    io,
    watch: [],
    monitor: {
      ...emptyMonitor,
      values: { "%IX0.1": true, "%IW2": 17, "%QX3.0": true, "%MW10": -4 },
      forced: new Set(["%IW2"]),
    },
  });
});

afterEach(() =>
  onlineStore.setState({ ...offline, write: real.write, force: real.force, unforce: real.unforce, watch: [] }),
);

const rows = () =>
  within(screen.getByRole("table", { name: "Process image" }))
    .getAllByRole("row")
    .slice(1);

describe("the I/O view (issue 16: the process image by area, address, declared name and value)", () => {
  it("lists every address with its area, names, type and live value, and subscribes to them", () => {
    render(<IoPanel />);
    const cells = rows().map((r) => [...r.querySelectorAll("td")].slice(0, 5).map((c) => c.textContent));
    expect(cells).toEqual([
      ["Input", "%IX0.1", "MAIN.START", "TRUE", "BOOL"],
      ["Input", "%IW2", "—", "17F", "INT"],
      ["Output", "%QX3.0", "MAIN.LAMP, MAIN.COPY", "TRUE", "BOOL"],
      ["Memory", "%MW10", "—", "-4", "INT"],
    ]);
    expect(onlineStore.getState().views[IO_VIEW]?.paths).toEqual(["%IX0.1", "%IW2", "%QX3.0", "%MW10"]);
  });

  it("writes, forces and watches an address itself", () => {
    render(<IoPanel />);
    const input = screen.getByRole("textbox", { name: "New value for %IX0.1" });
    fireEvent.change(input, { target: { value: "FALSE" } });
    fireEvent.click(within(rows()[0]!).getByRole("button", { name: "Write" }));
    fireEvent.change(screen.getByRole("textbox", { name: "New value for %IW2" }), { target: { value: "300" } });
    fireEvent.click(within(rows()[1]!).getByRole("button", { name: "Force" }));
    fireEvent.click(within(rows()[1]!).getByRole("button", { name: "Release" }));
    expect(sent).toEqual([
      ["write", "%IX0.1", false],
      ["force", "%IW2", 300],
      ["unforce", "%IW2"],
    ]);
    fireEvent.click(screen.getByRole("button", { name: "Watch %MW10" }));
    expect(onlineStore.getState().watch).toEqual(["%MW10"]);
  });

  it("says what to do offline and when the program uses no address", () => {
    onlineStore.setState({ phase: "offline" });
    const { unmount } = render(<IoPanel />);
    expect(screen.getByText(/Go online to see/)).toBeTruthy();
    expect(onlineStore.getState().views[IO_VIEW]).toBeUndefined();
    unmount();
    onlineStore.setState({ phase: "online", io: [] });
    render(<IoPanel />);
    expect(screen.getByText(/uses no direct addresses/)).toBeTruthy();
  });
});
