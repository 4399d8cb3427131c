import { describe, expect, it } from "vitest";
import { createStore } from "zustand/vanilla";
import type { TraceData } from "../generated/monitor";
import type { ClientMessage, ServerMessage } from "../online/protocol";
import { createTraceStore, MAX_PATHS, traceStoreFor } from "./store";

function setup(connected = true) {
  const sent: ClientMessage[] = [];
  const store = createTraceStore({ send: (msg) => (connected ? (sent.push(msg), true) : false) });
  return { store, sent, s: () => store.getState() };
}

const chunk = (fields: Partial<TraceData>): TraceData => ({
  type: "trace_data",
  id: 1,
  state: "recording",
  scans: [],
  time_ms: [],
  values: {},
  triggered: null,
  lost: 0,
  ...fields,
});

describe("trace store", () => {
  it("takes at most 20 distinct paths and says why it refuses one", () => {
    const { s } = setup();
    expect(s().addPath(" ")).toBe("type a variable path, e.g. MAIN.Motor");
    for (let i = 0; i < MAX_PATHS; i++) expect(s().addPath(`Main.V${i}`)).toBeNull();
    expect(s().addPath("main.v3")).toBe("main.v3 is traced already");
    expect(s().addPath("Main.Extra")).toBe("a trace records at most 20 variables: remove one before adding Main.Extra");
    expect(s().paths).toHaveLength(20);
    s().removePath("MAIN.V0");
    expect(s().addPath("Main.Extra")).toBeNull();
    expect(s().paths.at(-1)).toBe("Main.Extra");
  });

  it("starts with the paths, trigger and buffer size, then fills the ring from chunks of its own id", () => {
    const { s, sent } = setup();
    s().addPath("Main.Q");
    s().addPath("Main.ET");
    s().setTrigger({ path: "Main.Go", condition: "rising" });
    s().setCapacity(3);
    s().start();
    expect(sent).toEqual([
      {
        type: "trace_start",
        id: 1,
        paths: ["Main.Q", "Main.ET"],
        samples: 3,
        trigger: { path: "Main.Go", condition: "rising" },
      },
    ]);
    expect(s().phase).toBe("starting");

    s().receive(chunk({ state: "waiting", values: { "MAIN.Q": [], "MAIN.ET": [] } }));
    expect([s().phase, s().recorded, s().ring?.length]).toEqual(["waiting", ["MAIN.Q", "MAIN.ET"], 0]);
    s().receive(chunk({ id: 0, scans: [99], time_ms: [990], values: { "MAIN.Q": [true], "MAIN.ET": [1] } })); // an older trace's
    s().receive(
      chunk({
        scans: [3, 4],
        time_ms: [30, 40],
        values: { "MAIN.Q": [false, false], "MAIN.ET": [0, 10] },
        triggered: { scan: 3, time_ms: 30 },
      }),
    );
    s().receive(chunk({ state: "done", scans: [5], time_ms: [50], values: { "MAIN.Q": [true], "MAIN.ET": [20] } }));
    expect(s().phase).toBe("done");
    expect([s().triggered, s().origin, s().kinds]).toEqual([{ scan: 3, time_ms: 30 }, 30, ["bool", "number"]]);
    const columns = s().ring!.columnsInOrder();
    expect(Array.from(columns.scans)).toEqual([3, 4, 5]);
    expect(columns.values.map((c) => Array.from(c))).toEqual([
      [0, 0, 1],
      [0, 10, 20],
    ]);
    s().receive(chunk({ scans: [6], time_ms: [60], values: { "MAIN.Q": [true], "MAIN.ET": [30] } })); // after done: ignored
    expect(s().ring!.length).toBe(3);
  });

  it("keeps how the first chunk says to show each path (an enumeration's names as declared)", () => {
    const { s } = setup();
    s().addPath("Main.m");
    s().addPath("Main.n");
    s().start();
    const mode = { name: "MODE", names: { "0": "Idle", "5": "Run" } };
    s().receive(
      chunk({ values: { "MAIN.M": [], "MAIN.N": [] }, types: { "MAIN.M": mode, "MAIN.N": { name: "INT" } } }),
    );
    s().receive(chunk({ scans: [1], time_ms: [10], values: { "MAIN.M": [5], "MAIN.N": [1] }, types: {} }));
    expect(s().types).toEqual([mode, { name: "INT" }]);
  });

  it("records until Stop without a buffer limit when Stop when full is off, keeping the newest samples", () => {
    const { s, sent } = setup();
    s().addPath("Main.N");
    s().setCapacity(2);
    s().setStopWhenFull(false);
    s().start();
    expect(sent[0]).toMatchObject({ samples: null, trigger: null });
    s().receive(chunk({ scans: [1, 2, 3], time_ms: [10, 20, 30], values: { "MAIN.N": [1, 2, 3] }, lost: 4 }));
    expect([Array.from(s().ring!.columnsInOrder().scans), s().ring!.total, s().lost, s().origin]).toEqual([
      [2, 3],
      3,
      4,
      10,
    ]);
    s().stop();
    expect(sent[1]).toEqual({ type: "trace_stop" });
    expect(s().phase).toBe("recording"); // until the server's last chunk
  });

  it("shows a refusal of its trace_start and goes back to idle", () => {
    const { s } = setup();
    s().addPath("Main.Name");
    s().start();
    s().receive({ type: "error", code: "bad_path", message: "MAIN.NAME is not a BOOL or numeric variable" });
    expect([s().phase, s().error]).toEqual(["idle", "MAIN.NAME is not a BOOL or numeric variable"]);
    s().receive({ type: "error", code: "bad_state", message: "someone else's" }); // not starting: not ours
    expect(s().error).toBe("MAIN.NAME is not a BOOL or numeric variable");
  });

  it("does not start without paths, with a bad trigger level or offline", () => {
    const { s, sent } = setup();
    s().start();
    expect(s().error).toBe("add a variable to trace first");
    s().addPath("Main.N");
    s().setTrigger({ path: "Main.N", condition: "cross_up", level: "high" });
    s().start();
    expect(s().error).toBe("the trigger level must be a number, not 'high'");
    expect(sent).toEqual([]);
    const offline = setup(false);
    offline.s().addPath("Main.N");
    offline.s().start();
    expect([offline.s().phase, offline.s().error]).toEqual([
      "idle",
      "go online (Compile & simulate) to record a trace",
    ]);
  });

  const onlineFake = () => {
    let listener: ((msg: ServerMessage) => void) | null = null;
    const online = createStore<{
      simulation: string | null;
      connection: number;
      send(msg: ClientMessage): boolean;
      listen(l: (msg: ServerMessage) => void): () => void;
    }>()(() => ({
      simulation: "s1",
      connection: 1,
      send: () => true,
      listen: (l) => ((listener = l), () => undefined),
    }));
    const trace = traceStoreFor(online);
    trace.getState().addPath("Main.N");
    trace.getState().start();
    listener!(chunk({ scans: [1], time_ms: [10], values: { "MAIN.N": [5] } }));
    expect(trace.getState().ring!.length).toBe(1);
    return { online, trace };
  };

  it("ends a trace in progress when the simulation changes, keeping its samples", () => {
    const { online, trace } = onlineFake();
    online.setState({ simulation: null });
    expect([trace.getState().phase, trace.getState().error, trace.getState().ring!.length]).toEqual([
      "done",
      "the simulation went offline: the trace ended",
      1,
    ]);
  });

  it("ends it on a reconnect too: the server keeps a trace per connection", () => {
    const { online, trace } = onlineFake();
    online.setState({ connection: 2 });
    expect([trace.getState().phase, trace.getState().ring!.length]).toEqual(["done", 1]);
  });
});
