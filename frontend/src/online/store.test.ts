import { afterEach, beforeEach, describe, expect, it, vi } from "vitest";
import { ApiError } from "../api/client";
import type { SimulationInfo } from "../generated/api";
import type { SimulationApi } from "./api";
import { createOnlineStore, mergeSubscriptions, RECONNECT_DELAYS_MS, type SocketLike } from "./store";

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
    listSimulations: vi.fn(async () => [info(3, 0.4)]),
    resetSimulation: vi.fn(async () => info(0, 0)),
    deleteSimulation: vi.fn(async () => undefined),
    seekScan: vi.fn(async () => info(3, 0.4)),
    goLive: vi.fn(async () => info(3, 0.4)),
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

  it("reconnects after a dropped connection while the simulation still runs, keeping the views", async () => {
    const { store, api, sockets } = setup();
    store.getState().subscribe("ld:Main", MOTOR);
    await store.getState().compile("demo");
    sockets[0]!.open();
    sockets[0]!.drop();
    expect(store.getState()).toMatchObject({ phase: "connecting", simulation: "s1" });
    expect(store.getState().monitor.log.at(-1)?.message).toBe("connection to the simulation lost");
    await vi.advanceTimersByTimeAsync(RECONNECT_DELAYS_MS[0]!);
    expect(api.listSimulations).toHaveBeenCalled();
    expect(sockets).toHaveLength(2);
    sockets[1]!.open();
    expect(store.getState()).toMatchObject({ phase: "online", error: null, connection: 2 });
    expect(sockets[1]!.sent[0]).toMatchObject({ type: "subscribe", paths: ["MAIN.MOTOR", "MAIN.START"] });
  });

  it("goes offline when the dropped simulation is gone from the server", async () => {
    const { store, sockets } = setup({ listSimulations: vi.fn(async () => []) });
    await store.getState().compile("demo");
    sockets[0]!.open();
    sockets[0]!.drop();
    await vi.advanceTimersByTimeAsync(RECONNECT_DELAYS_MS[0]!);
    expect(store.getState()).toMatchObject({ phase: "offline", simulation: null });
    expect(store.getState().error).toMatch(/simulation is gone/);
    expect(sockets).toHaveLength(1);
  });

  it("gives up after the last reconnect attempt fails", async () => {
    const { store, sockets } = setup();
    await store.getState().compile("demo");
    sockets[0]!.open();
    sockets[0]!.drop();
    for (let i = 0; i < RECONNECT_DELAYS_MS.length; i++) {
      await vi.advanceTimersByTimeAsync(RECONNECT_DELAYS_MS[i]!);
      sockets.at(-1)!.drop(); // the server lists it but the websocket does not open
    }
    expect(store.getState()).toMatchObject({ phase: "offline", error: "The connection to the simulation was lost." });
  });

  it("attaches to a simulation of the project that still runs (after a page reload)", async () => {
    const { store, api, sockets } = setup();
    expect(await store.getState().attach("other", "s1")).toBe(false); // s1 runs project demo
    expect(sockets).toHaveLength(0);
    expect(await store.getState().attach("demo", "s1")).toBe(true);
    expect(api.listSimulations).toHaveBeenCalled();
    expect(store.getState()).toMatchObject({ phase: "connecting", project: "demo", simulation: "s1" });
    sockets[0]!.open();
    expect(store.getState().phase).toBe("online");
    expect(api.createSimulation).not.toHaveBeenCalled();
  });

  it("attaches to nothing when the simulation is gone", async () => {
    const { store, sockets } = setup({ listSimulations: vi.fn(async () => [{ ...info(1, 0), id: "s2" }]) });
    expect(await store.getState().attach("demo", "s1")).toBe(false);
    expect(store.getState().phase).toBe("offline");
    expect(sockets).toHaveLength(0);
  });

  it("forces or writes every prepared value at once and then forgets them (CODESYS F7 / Ctrl+F7)", async () => {
    const { store, sockets } = setup();
    await store.getState().compile("demo");
    sockets[0]!.open();
    const s = store.getState();
    s.prepare("Main.Start", true);
    s.prepare("MAIN.SPEED", "T#5s");
    s.prepare("main.start", false); // prepared again: the new value replaces the old one
    expect(store.getState().prepared).toEqual({ "MAIN.START": false, "MAIN.SPEED": "T#5s" });
    store.getState().applyPrepared("force");
    expect(sockets[0]!.sent.slice(1)).toEqual([
      { type: "force", path: "MAIN.START", value: false },
      { type: "force", path: "MAIN.SPEED", value: "T#5s" },
    ]);
    expect(store.getState().prepared).toEqual({});
    store.getState().prepare("MAIN.X", 3);
    store.getState().prepare("MAIN.Y", 4);
    store.getState().prepare("MAIN.Y", null);
    store.getState().applyPrepared("write");
    expect(sockets[0]!.sent.slice(3)).toEqual([{ type: "write", path: "MAIN.X", value: 3 }]);
    store.getState().applyPrepared("write");
    expect(sockets[0]!.sent).toHaveLength(4);
    expect(store.getState().monitor.log.at(-1)?.message).toBe("no prepared values to write");
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

describe("going to a past scan (issue 23: REST seek, refused in words)", () => {
  /** A seek the test answers when it wants: `answer(i)` ends the i-th, `refuse(i, why)` refuses it. */
  function pending() {
    const calls: { what: string; resolve: () => void; reject: (err: Error) => void }[] = [];
    const call = (what: string) =>
      new Promise<SimulationInfo>((resolve, reject) => {
        calls.push({ what, resolve: () => resolve(info(3, 0.4)), reject });
      });
    return {
      calls,
      seekScan: vi.fn((_id: string, scan: number) => call(`seek ${scan}`)),
      goLive: vi.fn(() => call("live")),
    };
  }

  it("sends one seek at a time in the order asked, the newest of those asked meanwhile, then back to live", async () => {
    const server = pending();
    const { store, sockets } = setup({ seekScan: server.seekScan, goLive: server.goLive });
    await store.getState().compile("demo");
    sockets[0]!.open();
    const first = store.getState().seek(4);
    void store.getState().seek(5); // a drag of the slider: 5 and 6 asked while 4 runs; only 6 is sent
    void store.getState().seek(6);
    await vi.advanceTimersByTimeAsync(0);
    expect(server.calls.map((c) => c.what)).toEqual(["seek 4"]);
    server.calls[0]!.resolve();
    await vi.advanceTimersByTimeAsync(0);
    expect(server.calls.map((c) => c.what)).toEqual(["seek 4", "seek 6"]);
    const live = store.getState().goLive();
    server.calls[1]!.resolve();
    await vi.advanceTimersByTimeAsync(0);
    expect(server.calls.map((c) => c.what)).toEqual(["seek 4", "seek 6", "live"]);
    server.calls[2]!.resolve();
    await Promise.all([first, live]);
    expect(server.seekScan).toHaveBeenCalledWith("s1", 6);
    expect(sockets[0]!.sent.filter((m) => (m as { type: string }).type !== "subscribe")).toEqual([]);
    expect(store.getState().historyError).toBeNull();
  });

  it("keeps the server's words when a seek is refused, until a seek is answered", async () => {
    const server = pending();
    const { store, sockets } = setup({ seekScan: server.seekScan, goLive: server.goLive });
    await store.getState().compile("demo");
    sockets[0]!.open();
    const why =
      "the seek to scan 2 did not end within 30 s (the server's history_timeout_s): scan 2 is shown once it ends";
    const refused = store.getState().seek(2);
    await vi.advanceTimersByTimeAsync(0);
    server.calls[0]!.reject(new ApiError(why, 409, { message: why }));
    await refused;
    expect(store.getState().historyError).toBe(why);
    const next = store.getState().seek(1);
    await vi.advanceTimersByTimeAsync(0);
    server.calls[1]!.resolve();
    await next;
    expect(store.getState().historyError).toBeNull();
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

describe("the online log across connections (ON-15: history first, then live entries)", () => {
  /** A simulation's log as the server keeps it: every connection gets the whole history first. */
  class FakeSimulationLog {
    entries: unknown[] = [];
    add(socket: FakeSocket, kind: string, message: string, scan: number) {
      const entry = { type: "log", kind, level: "info", message, scan, time_ms: scan * 10 };
      this.entries.push(entry);
      socket.receive(entry);
    }
    connect(socket: FakeSocket) {
      socket.open();
      for (const entry of this.entries) socket.receive(entry);
    }
  }

  const logOf = (store: ReturnType<typeof setup>["store"]) =>
    store.getState().monitor.log.map((e) => [e.origin, e.kind, e.message, e.scan, e.timeMs]);

  it("shows each entry once after a reconnect, in the server's order, and keeps this browser's own notes", async () => {
    const { store, sockets } = setup();
    const server = new FakeSimulationLog();
    await store.getState().compile("demo");
    server.connect(sockets[0]!);
    server.add(sockets[0]!, "state", "run", 0);
    server.add(sockets[0]!, "force", "forced MAIN.STOP := TRUE", 12);
    sockets[0]!.receive({ type: "error", code: "bad_path", message: "no variable MAIN.NOPE" });
    sockets[0]!.drop();
    server.entries.push({
      type: "log",
      kind: "release",
      level: "info",
      message: "released MAIN.STOP",
      scan: 40,
      time_ms: 400,
    });
    await vi.advanceTimersByTimeAsync(RECONNECT_DELAYS_MS[0]!);
    server.connect(sockets[1]!);
    server.add(sockets[1]!, "state", "stop", 55);
    expect(logOf(store)).toEqual([
      // This browser's notes carry the scan of the last values received (none here).
      ["client", "system", "bad_path: no variable MAIN.NOPE", 0, 0],
      ["client", "system", "connection to the simulation lost", 0, 0],
      ["server", "state", "run", 0, 0],
      ["server", "force", "forced MAIN.STOP := TRUE", 12, 120],
      ["server", "release", "released MAIN.STOP", 40, 400],
      ["server", "state", "stop", 55, 550],
    ]);
  });

  it("shows the whole history of a simulation it attaches to", async () => {
    const { store, sockets } = setup();
    const server = new FakeSimulationLog();
    server.entries.push(
      { type: "log", kind: "state", level: "info", message: "run", scan: 0, time_ms: 0 },
      { type: "log", kind: "fault", level: "error", message: "division by zero", scan: 7, time_ms: 70 },
    );
    await store.getState().attach("demo", "s1");
    server.connect(sockets[0]!);
    expect(logOf(store)).toEqual([
      ["server", "state", "run", 0, 0],
      ["server", "fault", "division by zero", 7, 70],
    ]);
  });
});
