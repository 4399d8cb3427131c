import { afterEach, beforeEach, describe, expect, it, vi } from "vitest";
import { ApiError } from "../api/client";
import type { SimulationInfo } from "../generated/api";
import type { SimulationApi } from "./api";
import { createOnlineStore, mergeSubscriptions, type SocketLike } from "./store";

class FakeSocket {
  readyState = 0;
  sent: unknown[] = [];
  closed = false;
  onopen: SocketLike["onopen"] = null;
  onmessage: SocketLike["onmessage"] = null;
  onclose: SocketLike["onclose"] = null;
  constructor(readonly url: string) {}
  send(data: string) {
    this.sent.push(JSON.parse(data));
  }
  close() {
    this.closed = true;
    this.readyState = 3;
  }
  open() {
    this.readyState = 1;
    this.onopen?.call(this as unknown as WebSocket, new Event("open"));
  }
  receive(msg: unknown) {
    this.onmessage?.call(this as unknown as WebSocket, { data: JSON.stringify(msg) } as MessageEvent);
  }
  drop() {
    this.readyState = 3;
    this.onclose?.call(this as unknown as WebSocket, {} as CloseEvent);
  }
}

const info = (scan_count: number, last: number): SimulationInfo => ({
  id: "s1",
  project: "demo",
  revision: "r1",
  state: "stopped",
  scan_count,
  time_ms: scan_count * 10,
  real_time_ms: 0,
  scan_ms: { min: last, avg: last, max: last, last },
  overruns: 0,
  fault: null,
  clients: 0,
  created: "2024-01-01T00:00:00Z",
});

function setup(overrides: Partial<SimulationApi> = {}) {
  const sockets: FakeSocket[] = [];
  const api: SimulationApi = {
    createSimulation: vi.fn(async () => info(0, 0)),
    getSimulation: vi.fn(async () => info(3, 0.4)),
    resetSimulation: vi.fn(async () => info(0, 0)),
    deleteSimulation: vi.fn(async () => undefined),
    ...overrides,
  };
  const store = createOnlineStore(
    api,
    (url) => {
      const s = new FakeSocket(url);
      sockets.push(s);
      return s as unknown as SocketLike;
    },
    (id) => `ws://test/api/simulations/${id}/ws`,
  );
  return { store, api, sockets };
}

const MOTOR = { paths: ["main.start", "MAIN.MOTOR"], elements: [{ pou_instance: "MAIN", ids: ["c1", "q1"] }] };

beforeEach(() => vi.useFakeTimers());
afterEach(() => vi.useRealTimers());

describe("online store", () => {
  it("compiles, connects and subscribes every view and the watch list once the socket opens", async () => {
    const { store, api, sockets } = setup();
    store.getState().subscribe("ld:Main", MOTOR);
    store.getState().addWatch("Main.Count");
    await store.getState().compile("demo");
    expect(api.createSimulation).toHaveBeenCalledWith("demo");
    expect(store.getState().phase).toBe("connecting");
    expect(sockets[0]!.url).toBe("ws://test/api/simulations/s1/ws");
    sockets[0]!.open();
    expect(store.getState().phase).toBe("online");
    expect(sockets[0]!.sent).toEqual([
      {
        type: "subscribe",
        paths: ["MAIN.COUNT", "MAIN.MOTOR", "MAIN.START"],
        elements: [{ pou_instance: "MAIN", ids: ["c1", "q1"] }],
        interval_ms: 100,
      },
    ]);
  });

  it("folds server messages into the monitor state", async () => {
    const { store, sockets } = setup();
    store.getState().subscribe("ld:Main", MOTOR);
    await store.getState().compile("demo");
    sockets[0]!.open();
    sockets[0]!.receive({ type: "status", state: "running" });
    sockets[0]!.receive({
      type: "values",
      scan: 12,
      time_ms: 120,
      changed: { "MAIN.START": true },
      forced: [],
      power: { "MAIN/c1": true },
    });
    const { monitor } = store.getState();
    expect(monitor.state).toBe("running");
    expect(monitor.scan).toBe(12);
    expect(monitor.values).toEqual({ "MAIN.START": true });
    expect(monitor.power).toEqual({ "MAIN/c1": true });
  });

  it("hands every server message to listeners, trace chunks too, until they unsubscribe", async () => {
    const { store, sockets } = setup();
    const heard: string[] = [];
    const unlisten = store.getState().listen((msg) => heard.push(msg.type));
    await store.getState().compile("demo");
    sockets[0]!.open();
    const before = store.getState().monitor;
    sockets[0]!.receive({
      type: "trace_data",
      id: 1,
      state: "recording",
      scans: [1],
      time_ms: [10],
      values: { "MAIN.N": [1] },
      triggered: null,
      lost: 0,
    });
    expect(store.getState().monitor).toBe(before); // the trace panel keeps the samples, not the monitor
    sockets[0]!.receive({ type: "status", state: "running" });
    sockets[0]!.receive({ type: "nonsense" });
    unlisten();
    sockets[0]!.receive({ type: "status", state: "stopped" });
    expect(heard).toEqual(["trace_data", "status"]);
  });

  it("sends a new subscription only when the merged one changes", async () => {
    const { store, sockets } = setup();
    await store.getState().compile("demo");
    sockets[0]!.open();
    store.getState().subscribe("a", MOTOR);
    store.getState().subscribe("b", { paths: ["MAIN.START"], elements: [{ pou_instance: "main", ids: ["q1"] }] });
    store.getState().addWatch("main.motor"); // already subscribed by view a
    expect(sockets[0]!.sent.filter((m) => (m as { type: string }).type === "subscribe")).toHaveLength(2);
    store.getState().subscribe("a", null);
    expect(sockets[0]!.sent.at(-1)).toMatchObject({
      paths: ["MAIN.MOTOR", "MAIN.START"],
      elements: [{ pou_instance: "MAIN", ids: ["q1"] }],
    });
  });

  it("sends write, force, unforce and the run commands", async () => {
    const { store, sockets } = setup();
    await store.getState().compile("demo");
    sockets[0]!.open();
    const s = store.getState();
    s.run();
    s.write("MAIN.START", true);
    s.force("MAIN.STOP", true);
    s.unforce("MAIN.STOP");
    s.unforceAll();
    s.singleCycle();
    s.stop();
    expect(sockets[0]!.sent.slice(1)).toEqual([
      { type: "run" },
      { type: "write", path: "MAIN.START", value: true },
      { type: "force", path: "MAIN.STOP", value: true },
      { type: "unforce", path: "MAIN.STOP" },
      { type: "unforce_all" },
      { type: "single_cycle" },
      { type: "stop" },
    ]);
  });

  it("logs a command it could not send instead of dropping it silently", () => {
    const { store } = setup();
    store.getState().write("MAIN.START", true);
    expect(store.getState().monitor.log.map((e) => e.message)).toEqual(["not connected: write was not sent"]);
  });

  it("keeps the compile diagnostics of a refused project", async () => {
    const diagnostics = [
      { code: "ST-UNDECLARED", message: "Motor is not declared", pou: "Main", network: "n1", element: "q1" },
    ];
    const { store, sockets } = setup({
      createSimulation: vi.fn(async () => {
        throw new ApiError("the project does not compile", 422, {
          message: "the project does not compile",
          diagnostics,
        });
      }),
    });
    await store.getState().compile("demo");
    expect(store.getState()).toMatchObject({
      phase: "offline",
      error: "the project does not compile",
      compileDiagnostics: diagnostics,
    });
    expect(sockets).toHaveLength(0);
  });

  it("goes offline: closes the socket and deletes the simulation, keeping the views and the watch list", async () => {
    const { store, api, sockets } = setup();
    store.getState().subscribe("ld:Main", MOTOR);
    store.getState().addWatch("MAIN.COUNT");
    await store.getState().compile("demo");
    sockets[0]!.open();
    await store.getState().goOffline();
    expect(sockets[0]!.closed).toBe(true);
    expect(api.deleteSimulation).toHaveBeenCalledWith("s1");
    expect(store.getState()).toMatchObject({
      phase: "offline",
      simulation: null,
      watch: ["MAIN.COUNT"],
      views: { "ld:Main": MOTOR },
    });
  });

  it("reports a lost connection and goes offline", async () => {
    const { store, sockets } = setup();
    await store.getState().compile("demo");
    sockets[0]!.open();
    sockets[0]!.drop();
    expect(store.getState().phase).toBe("offline");
    expect(store.getState().error).toMatch(/connection to the simulation was lost/);
    expect(store.getState().monitor.log.at(-1)?.message).toBe("connection to the simulation lost");
  });

  it("polls the scan statistics while online and stops when offline", async () => {
    const { store, api, sockets } = setup();
    await store.getState().compile("demo");
    sockets[0]!.open();
    await vi.advanceTimersByTimeAsync(2100);
    expect(api.getSimulation).toHaveBeenCalledTimes(2);
    expect(store.getState().lastScanMs).toBe(0.4);
    await store.getState().goOffline();
    await vi.advanceTimersByTimeAsync(3000);
    expect(api.getSimulation).toHaveBeenCalledTimes(2);
  });
});

describe("mergeSubscriptions", () => {
  it("joins paths ignoring case and element ids per instance; null ids (all elements) win", () => {
    expect(
      mergeSubscriptions([
        {
          paths: ["a", "B"],
          elements: [
            { pou_instance: "MAIN", ids: ["x"] },
            { pou_instance: "MAIN.FB1", ids: null },
          ],
        },
        {
          paths: ["A"],
          elements: [
            { pou_instance: "main", ids: ["y", "x"] },
            { pou_instance: "MAIN.FB1", ids: ["z"] },
          ],
        },
      ]),
    ).toEqual({
      paths: ["A", "B"],
      elements: [
        { pou_instance: "MAIN", ids: ["x", "y"] },
        { pou_instance: "MAIN.FB1", ids: null },
      ],
    });
  });

  it("takes the shortest interval a view asks for (a panel's 20 ms), none when no view asks", () => {
    const view = (interval_ms?: number) => ({ paths: [], elements: [], ...(interval_ms ? { interval_ms } : {}) });
    expect(mergeSubscriptions([view(), view(20), view(100)]).interval_ms).toBe(20);
    expect(mergeSubscriptions([view(), view()])).not.toHaveProperty("interval_ms");
  });
});
