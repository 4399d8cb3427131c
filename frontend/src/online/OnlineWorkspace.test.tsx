// @vitest-environment jsdom
// The app with online mode, the bottom panels and the ST view, over a faked server and websocket.
import { act, fireEvent, render, screen, waitFor, within } from "@testing-library/react";
import { beforeEach, describe, expect, it, vi } from "vitest";
import App from "../app/App";
import type { Diagnostic } from "../generated/api";
import { motorMain } from "../ld/fixtures";
import { emptyPanels, panelsStore } from "../store/panels";
import { emptyWorkspace, plainSymbol, workspaceStore } from "../store/project";
import { appStore, initialData } from "../store/workspace";
import { offline, onlineStore } from "./store";
import { stubFetch, type SentRequest } from "../test/fetchStub";

const json = (body: unknown, status = 200) =>
  new Response(JSON.stringify(body), { status, headers: { "Content-Type": "application/json" } });
const sym = (name: string, type = "BOOL") => plainSymbol(name, type);
const project = {
  name: "plant",
  pous: [
    {
      name: "Main",
      kind: "program",
      language: "ld",
      declarations: "VAR\n    Start : BOOL;\n    Stop : BOOL;\n    Motor : BOOL;\nEND_VAR",
      body: motorMain,
    },
    {
      name: "Pump",
      kind: "function_block",
      language: "ld",
      declarations: "VAR_INPUT\n    Run : BOOL;\nEND_VAR\nVAR_OUTPUT\n    Out : BOOL;\nEND_VAR",
      body: {
        networks: [
          {
            id: "n1",
            elements: [
              { type: "contact", id: "r1", var: "Run", mode: "no" },
              { type: "coil", id: "q1", var: "Out", mode: "normal" },
            ],
          },
        ],
      },
    },
  ],
};
const simulation = {
  id: "s1",
  project: "plant",
  revision: "r1",
  state: "stopped",
  scan_count: 0,
  time_ms: 0,
  real_time_ms: 0,
  scan_ms: { min: 0, avg: 0, max: 0, last: 0 },
  overruns: 0,
  fault: null,
  clients: 0,
  created: "2024-05-01T10:00:00Z",
};

class FakeSocket {
  static all: FakeSocket[] = [];
  readyState = 0;
  sent: Record<string, unknown>[] = [];
  onopen: ((e: Event) => void) | null = null;
  onmessage: ((e: MessageEvent) => void) | null = null;
  onclose: ((e: CloseEvent) => void) | null = null;
  closed = false;
  constructor(readonly url: string) {
    FakeSocket.all.push(this);
  }
  send(data: string) {
    this.sent.push(JSON.parse(data) as Record<string, unknown>);
  }
  close() {
    this.closed = true;
  }
  open() {
    act(() => {
      this.readyState = 1;
      this.onopen?.(new Event("open"));
    });
  }
  receive(msg: unknown) {
    act(() => this.onmessage?.({ data: JSON.stringify(msg) } as MessageEvent));
  }
}

function serve(routes: Record<string, (request: SentRequest) => Response> = {}) {
  return stubFetch((request) => {
    const { path: url, method } = request;
    const key = `${method} ${url}`;
    if (routes[key]) return routes[key]!(request);
    if (url === "/api/health") return json({ status: "ok", version: "0.1.0" });
    if (url === "/api/projects")
      return json([{ name: "plant", revision: "r1", modified: "2024-05-01T10:00:00Z", pou_count: 1 }]);
    if (url === "/api/projects/plant")
      return json({ name: "plant", revision: "r1", modified: "2024-05-01T10:00:00Z", project });
    if (url.startsWith("/api/library")) return json([]);
    if (url.endsWith("/symbols"))
      return json({ pou: "Main", symbols: [sym("Start"), sym("Stop"), sym("Motor")], globals: [], diagnostics: [] });
    if (key === "POST /api/projects/plant/simulations") return json(simulation, 201);
    if (url.startsWith("/api/simulations/s1"))
      return method === "DELETE" ? new Response(null, { status: 204 }) : json(simulation);
    throw new Error(`unexpected fetch ${key}`);
  });
}

beforeEach(() => {
  localStorage.clear();
  FakeSocket.all = [];
  vi.stubGlobal("WebSocket", FakeSocket);
  appStore.setState(initialData);
  workspaceStore.setState(emptyWorkspace);
  onlineStore.setState({ ...offline, watch: [], instances: {} });
  panelsStore.setState(emptyPanels);
});

async function openMain() {
  render(<App />);
  fireEvent.click(await screen.findByRole("button", { name: /plant/ }));
  const tree = await screen.findByRole("navigation", { name: "Project tree" });
  fireEvent.click(within(tree).getByRole("button", { name: /^Main/ }));
  await waitFor(() => expect(workspaceStore.getState().symbols.Main).toBeDefined());
  return screen.getByRole("application", { name: "Ladder diagram editor" });
}

const element = (editor: HTMLElement, id: string) => editor.querySelector(`[data-id="${id}"]`)!;

describe("online LD in the app (issue 7 online mode)", () => {
  it("compiles, subscribes the diagram, colours from the engine, prepares and writes, watches by drag and goes offline", async () => {
    const { sent } = serve();
    const editor = await openMain();
    fireEvent.click(screen.getByRole("button", { name: "Compile & simulate" }));
    await waitFor(() => expect(FakeSocket.all).toHaveLength(1));
    const socket = FakeSocket.all[0]!;
    expect(socket.url).toMatch(/\/api\/simulations\/s1\/ws$/);
    socket.open();
    const subscribe = socket.sent.find((m) => m.type === "subscribe")!;
    expect(subscribe.paths).toEqual(expect.arrayContaining(["MAIN.START", "MAIN.STOP", "MAIN.MOTOR"]));
    expect(subscribe.elements).toEqual([
      { pou_instance: "MAIN", ids: expect.arrayContaining(["start", "seal", "stop", "motor"]) },
    ]);

    // Online: editing is off with a way back; the state is shown.
    expect(screen.getByRole("button", { name: "Go offline to edit" })).toBeTruthy();
    expect((screen.getByRole("button", { name: "Contact" }) as HTMLButtonElement).disabled).toBe(true);
    socket.receive({ type: "status", state: "running" });
    expect(screen.getByRole("status", { name: "Online state" }).textContent).toBe("Online · running");

    socket.receive({
      type: "values",
      scan: 42,
      time_ms: 420,
      changed: { "MAIN.START": true, "MAIN.STOP": false, "MAIN.MOTOR": true },
      forced: ["MAIN.STOP"],
      power: { "MAIN/start": true, "MAIN/seal": true, "MAIN/stop": true, "MAIN/motor": true, "MAIN/ton": null },
    });
    expect(element(editor, "motor").getAttribute("class")).toContain("ld-on");
    expect(element(editor, "ton").getAttribute("class")).toContain("ld-not-executed");
    expect(element(editor, "stop").querySelector(".ld-forced")).not.toBeNull();
    expect(screen.getByTestId("scan-count").textContent).toBe("42");
    expect(screen.getByText("0:00:00.420")).toBeTruthy();

    // Double-click prepares FALSE for Start (TRUE now), shown as <FALSE>; Ctrl+F7 writes it (CODESYS).
    fireEvent.doubleClick(element(editor, "start"));
    expect(element(editor, "start").querySelector(".ld-prepared")!.textContent).toBe("<FALSE>");
    expect(screen.getByRole("status", { name: "Prepared values" }).textContent).toContain("1 prepared");
    fireEvent.keyDown(window, { key: "F7", ctrlKey: true });
    expect(socket.sent.at(-1)).toEqual({ type: "write", path: "MAIN.START", value: false });
    expect(element(editor, "start").querySelector(".ld-prepared")).toBeNull();

    // Drag Motor from the diagram onto the panels: it joins the watch list with its value.
    fireEvent.mouseDown(element(editor, "motor").querySelector(".ld-hit")!);
    fireEvent.mouseUp(screen.getByRole("region", { name: "Panels" }));
    expect(screen.getByLabelText("Value of MAIN.MOTOR").textContent).toBe("TRUE");

    // Write and force from the watch list.
    fireEvent.change(screen.getByLabelText("New value for MAIN.MOTOR"), { target: { value: "false" } });
    fireEvent.click(screen.getByRole("button", { name: "Force" }));
    expect(socket.sent.at(-1)).toEqual({ type: "force", path: "MAIN.MOTOR", value: false });

    socket.receive({ type: "log", level: "info", message: "forced MAIN.MOTOR := FALSE", scan: 43 });
    fireEvent.click(screen.getByRole("tab", { name: "Online log (1)" }));
    expect(screen.getByRole("list", { name: "Online log" }).textContent).toContain("forced MAIN.MOTOR := FALSE");

    fireEvent.click(screen.getByRole("button", { name: "Go offline to edit" }));
    await waitFor(() => expect(sent.some((r) => r.path === "/api/simulations/s1" && r.method === "DELETE")).toBe(true));
    expect(socket.closed).toBe(true);
    expect((screen.getByRole("button", { name: "Contact" }) as HTMLButtonElement).disabled).toBe(false);
    expect(element(editor, "motor").getAttribute("class")).not.toContain("ld-on");
  }, 20_000); // a long user session in jsdom; slow when the machine is busy

  it("runs the simulation commands from their keys (CODESYS's, exact modifiers only) and the toolbar", async () => {
    serve();
    await openMain();
    fireEvent.keyDown(window, { key: "F8", altKey: true });
    await waitFor(() => expect(FakeSocket.all).toHaveLength(1));
    const socket = FakeSocket.all[0]!;
    socket.open();
    socket.receive({ type: "status", state: "stopped" });
    fireEvent.keyDown(window, { key: "F5", ctrlKey: true });
    fireEvent.keyDown(window, { key: "F5" });
    fireEvent.keyDown(window, { key: "F5", shiftKey: true });
    fireEvent.keyDown(window, { key: "F8" }); // not bound: nothing
    fireEvent.keyDown(window, { key: "F8", altKey: true, ctrlKey: true }); // not bound either
    fireEvent.click(screen.getByRole("button", { name: "Run" }));
    fireEvent.click(screen.getByRole("button", { name: "Single cycle" }));
    expect(socket.sent.filter((m) => m.type !== "subscribe").map((m) => m.type)).toEqual([
      "single_cycle",
      "run",
      "stop",
      "run",
      "single_cycle",
    ]);
    socket.receive({ type: "status", state: "running" });
    expect((screen.getByRole("button", { name: "Run" }) as HTMLButtonElement).disabled).toBe(true);
    // Single cycle while running (issue 9): stop, then exactly one scan
    fireEvent.click(screen.getByRole("button", { name: "Single cycle" }));
    expect(socket.sent.slice(-2)).toEqual([{ type: "stop" }, { type: "single_cycle" }]);
    // Halted: Stop is available, F5 continues instead of Run
    socket.receive({ type: "status", state: "halted", at: { pou: "MAIN", instance: "MAIN", network: "n1" } });
    expect((screen.getAllByRole("button", { name: "Stop" })[0] as HTMLButtonElement).disabled).toBe(false);
    const before = socket.sent.length;
    fireEvent.keyDown(window, { key: "F5" });
    expect(socket.sent.slice(before)).toEqual([{ type: "continue" }]);
    fireEvent.keyDown(window, { key: "F8", ctrlKey: true });
    await waitFor(() => expect(screen.getByRole("status", { name: "Online state" }).textContent).toBe("Offline"));
  }, 20_000);

  it("shows a function block's diagram for the instance the user names", async () => {
    serve();
    await openMain();
    fireEvent.click(screen.getByRole("button", { name: "Compile & simulate" }));
    await waitFor(() => expect(FakeSocket.all).toHaveLength(1));
    const socket = FakeSocket.all[0]!;
    socket.open();
    fireEvent.click(
      within(screen.getByRole("navigation", { name: "Project tree" })).getByRole("button", { name: /^Pump/ }),
    );
    expect(screen.getByText(/name the instance of Pump to show/)).toBeTruthy();
    fireEvent.change(screen.getByLabelText("Instance of Pump"), { target: { value: "Main.P1" } });
    fireEvent.click(screen.getByRole("button", { name: "Show" }));
    // once Pump's symbols have arrived (its operands are then known as its own variables)
    await waitFor(() =>
      expect(socket.sent.at(-1)).toMatchObject({
        type: "subscribe",
        paths: ["MAIN.P1.OUT", "MAIN.P1.RUN"],
        elements: [{ pou_instance: "MAIN.P1", ids: ["q1", "r1"] }],
      }),
    );
    socket.receive({
      type: "values",
      scan: 3,
      time_ms: 30,
      changed: { "MAIN.P1.RUN": true, "MAIN.P1.OUT": true },
      forced: [],
      power: { "MAIN.P1/r1": true, "MAIN.P1/q1": true },
    });
    const editor = screen.getByRole("application", { name: "Ladder diagram editor" });
    expect(element(editor, "q1").getAttribute("class")).toContain("ld-on");
    expect(screen.getByText(/Online: the diagram shows the running simulation/)).toBeTruthy();
  }, 20_000);

  it("shows a refused compile's diagnostics in the Diagnostics panel", async () => {
    const diagnostics: Diagnostic[] = [
      {
        severity: "error",
        code: "ST-UNKNOWN-VAR",
        message: "unknown variable 'Lamp'",
        pou: "Main",
        network: "lamp",
        element: "lamp_coil",
      },
    ];
    serve({
      "POST /api/projects/plant/simulations": () =>
        json({ detail: { message: "project 'plant' does not compile", diagnostics } }, 422),
    });
    await openMain();
    fireEvent.click(screen.getByRole("button", { name: "Compile & simulate" }));
    const list = await screen.findByRole("list", { name: "Diagnostics" });
    expect(list.textContent).toContain("unknown variable 'Lamp'");
    expect(screen.getByText("project 'plant' does not compile")).toBeTruthy();
    expect(FakeSocket.all).toHaveLength(0);
  });
});

describe("Check and the Diagnostics panel", () => {
  it("lists the check's diagnostics of the working copy (nothing saved), marks the elements live, and a click reveals the element, or the declaration row", async () => {
    const diagnostics: Diagnostic[] = [
      {
        severity: "warning",
        code: "LD-X",
        message: "coil without effect",
        pou: "Main",
        network: "lamp",
        element: "lamp_coil",
      },
      {
        severity: "error",
        code: "ST-UNKNOWN-TYPE",
        message: "unknown type 'NOPE'",
        file: "Main/declarations",
        pou: "Main",
        line: 3,
        column: 12,
      },
    ];
    let saved = false;
    serve({
      "POST /api/check": () => json({ diagnostics }),
      "PUT /api/projects/plant": () => ((saved = true), json({ revision: "r2", modified: "2024-05-02T10:00:00Z" })),
    });
    const editor = await openMain();
    fireEvent.click(screen.getByRole("button", { name: "Check" }));
    const list = await screen.findByRole("list", { name: "Diagnostics" });
    // Each diagnostic: the button that reveals it, then its code (which opens the catalogue entry).
    const buttons = within(list).getAllByRole("button");
    expect(buttons.map((b) => b.textContent)).toEqual([
      "errorMain, declarations, line 3:12unknown type 'NOPE'",
      "ST-UNKNOWN-TYPE",
      "warningMain, network lamp, element lamp_coilcoil without effect",
      "LD-X",
    ]);
    const items = [buttons[0]!, buttons[2]!];
    await waitFor(() => expect(element(editor, "lamp_coil").getAttribute("class")).toContain("ld-has-diagnostic"));
    expect(saved).toBe(false); // Check never saves

    fireEvent.click(items[1]!);
    expect(element(editor, "lamp_coil").getAttribute("class")).toContain("ld-selected");

    fireEvent.click(items[0]!);
    const row = ((await screen.findByLabelText("Name of Stop")) as HTMLInputElement).closest("tr")!; // the Declarations tab loads on first use
    expect(row.className).toContain("focused");
    expect(within(row).getByRole("alert").textContent).toBe("unknown type 'NOPE'");
  });
});

describe("View as ST", () => {
  it("shows the export highlighted, links network blocks to the diagram and offers the download", async () => {
    const text =
      "PROGRAM Main\nVAR\n    Start : BOOL;\nEND_VAR\n(* Network 1: Start/stop with seal-in *)\nMotor := (Start OR Motor) AND NOT Stop;\nEND_PROGRAM\n";
    serve({
      "GET /api/projects/plant/export/st?pou=Main": () =>
        json({
          text,
          source_map: [
            { line: 5, network: "seal_in", element: null },
            { line: 6, network: "seal_in", element: "motor" },
          ],
        }),
    });
    await openMain();
    fireEvent.click(screen.getByRole("tab", { name: "View as ST" }));
    const code = await screen.findByLabelText("Exported ST");
    expect(code.textContent).toContain("Motor := (Start OR Motor) AND NOT Stop;");
    expect(within(code).getAllByText("AND")[0]!.className).toBe("st-keyword");
    const block = code.querySelector('[data-network="seal_in"]')!;
    expect(block.textContent).toBe("5(* Network 1: Start/stop with seal-in *)6Motor := (Start OR Motor) AND NOT Stop;");
    expect((screen.getByRole("button", { name: "Download Main.st" }) as HTMLButtonElement).disabled).toBe(false);

    fireEvent.click(block);
    const editor = screen.getByRole("application", { name: "Ladder diagram editor" });
    expect(editor.querySelector('[data-network="seal_in"]')!.getAttribute("class")).toContain("ld-selected");
  });

  it("names the problems when the POU cannot be exported", async () => {
    const diagnostics: Diagnostic[] = [
      {
        code: "ST-UNKNOWN-VAR",
        message: "unknown variable 'Lamp'",
        pou: "Main",
        network: "lamp",
        element: "lamp_coil",
      },
    ];
    serve({
      "GET /api/projects/plant/export/st?pou=Main": () =>
        json(
          { detail: { message: "the project cannot be exported as ST until these errors are fixed", diagnostics } },
          422,
        ),
    });
    await openMain();
    fireEvent.click(screen.getByRole("tab", { name: "View as ST" }));
    const alert = await screen.findByText(/The export failed/);
    expect(alert.parentElement!.textContent).toBe(
      "The export failed: the project cannot be exported as ST until these errors are fixedMain, network lamp, element lamp_coil: unknown variable 'Lamp'",
    );
    expect((screen.getByRole("button", { name: "Download Main.st" }) as HTMLButtonElement).disabled).toBe(true);
  });
});
