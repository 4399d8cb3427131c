// @vitest-environment jsdom
import type { ClientMessage } from "../online/protocol";
import fc from "fast-check";
import { describe, expect, it, vi } from "vitest";
import type { SimulationInfo } from "../generated/api";
import { createOnlineStore, type SocketLike } from "../online/store";
import {
  breakpointKey,
  clearMessage,
  describeBreakpoint,
  describeHalt,
  sameBreakpoint,
  setMessage,
  toggle,
  type Breakpoint,
} from "./breakpoints";
import { createDebugStore, isEnabled, loadBreakpoints } from "./store";

const arbBreakpoint: fc.Arbitrary<Breakpoint> = fc.oneof(
  fc.record({ pou: fc.constantFrom("Main", "MAIN", "Fb"), network: fc.constantFrom("n1", "n2") }),
  fc.record({ pou: fc.constantFrom("Main", "Fb"), element: fc.constantFrom("c1", "q1") }),
  fc.record({ pou: fc.constantFrom("Main", "st"), line: fc.integer({ min: 1, max: 3 }) }),
);

describe("breakpoint list (issue 9: toggle a breakpoint on a network or element)", () => {
  it("toggles: set when absent, clear when present, with the matching protocol message", () => {
    const first = toggle([], { pou: "Main", network: "n2" });
    expect(first).toEqual({
      list: [{ pou: "Main", network: "n2" }],
      message: { type: "breakpoint_set", pou: "Main", network: "n2" },
    });
    const second = toggle(first.list, { pou: "MAIN", network: "n2" });
    expect(second).toEqual({ list: [], message: { type: "breakpoint_clear", pou: "MAIN", network: "n2" } });
    expect(toggle(first.list, { pou: "Main", element: "n2" }).message.type).toBe("breakpoint_set");
  });

  it("toggling twice restores any list and never holds duplicates", () => {
    fc.assert(
      fc.property(fc.array(arbBreakpoint, { maxLength: 12 }), arbBreakpoint, (steps, bp) => {
        const list = steps.reduce<Breakpoint[]>((acc, b) => toggle(acc, b).list, []);
        for (let i = 0; i < list.length; i++)
          for (let j = i + 1; j < list.length; j++) expect(sameBreakpoint(list[i]!, list[j]!)).toBe(false);
        const twice = toggle(toggle(list, bp).list, bp).list;
        expect(twice.filter((b) => !sameBreakpoint(b, bp))).toEqual(list.filter((b) => !sameBreakpoint(b, bp)));
        expect(twice.some((b) => sameBreakpoint(b, bp))).toBe(list.some((b) => sameBreakpoint(b, bp)));
      }),
    );
  });

  it("keys are equal exactly when breakpoints are the same; messages carry only the location", () => {
    fc.assert(
      fc.property(arbBreakpoint, arbBreakpoint, (a, b) => {
        expect(breakpointKey(a) === breakpointKey(b)).toBe(sameBreakpoint(a, b));
      }),
    );
    const richer = { pou: "Main", network: "n1", label: "shown in a panel" } as Breakpoint;
    expect(setMessage(richer)).toEqual({ type: "breakpoint_set", pou: "Main", network: "n1" });
    expect(clearMessage({ pou: "Calc", line: 4 })).toEqual({ type: "breakpoint_clear", pou: "Calc", line: 4 });
  });

  it("describes breakpoints and halts with network positions", () => {
    expect(describeBreakpoint({ pou: "Main", network: "n7" }, ["n3", "n7"])).toBe("Main, network 2");
    expect(describeBreakpoint({ pou: "Main", network: "zz" }, ["n3"])).toBe("Main, network zz");
    expect(describeBreakpoint({ pou: "Main", element: "c1" })).toBe("Main, element c1");
    expect(describeHalt({ pou: "Blink", instance: "MAIN.B1", network: "n3", element: "c2" }, ["n3"])).toBe(
      "Blink (MAIN.B1), network 1, element c2",
    );
    expect(describeHalt({ pou: "Main", instance: "MAIN", line: 4 })).toBe("Main, line 4");
    // in an SFC action: the network's position among the action's networks
    expect(describeHalt({ pou: "Seq", body: "actions/Lamp", network: "copy" }, ["blink", "copy"])).toBe(
      "Seq, action Lamp, network 2",
    );
  });
});

describe("debug store (issue 9: breakpoints, continue, step)", () => {
  it("sends set/clear/continue/step messages", () => {
    const send = vi.fn((_msg: ClientMessage) => true);
    const store = createDebugStore(send).getState();
    store.toggle({ pou: "Main", network: "n1" });
    store.toggle({ pou: "Main", element: "q1" });
    store.remove({ pou: "main", network: "n1" });
    store.remove({ pou: "Main", network: "n9" });
    store.resume();
    store.step("network");
    store.step("cycle");
    store.clearAll();
    store.clearAll();
    expect(send.mock.calls.map(([m]) => m)).toEqual([
      { type: "breakpoint_set", pou: "Main", network: "n1" },
      { type: "breakpoint_set", pou: "Main", element: "q1" },
      { type: "breakpoint_clear", pou: "main", network: "n1" },
      { type: "continue" },
      { type: "step", granularity: "network" },
      { type: "step", granularity: "cycle" },
      { type: "breakpoint_clear" },
    ]);
  });

  it("disables (cleared in the simulation, still listed) and enables (sent again) a breakpoint", () => {
    const send = vi.fn((_msg: ClientMessage) => true);
    const store = createDebugStore(send);
    const { toggle, setEnabled, remove, clearAll } = store.getState();
    toggle({ pou: "Main", network: "n1" });
    toggle({ pou: "Main", element: "q1" });
    setEnabled({ pou: "MAIN", network: "n1" }, false);
    setEnabled({ pou: "Main", network: "n1" }, false); // already disabled: nothing sent
    expect(store.getState().breakpoints).toEqual([
      { pou: "Main", network: "n1" },
      { pou: "Main", element: "q1" },
    ]);
    expect(isEnabled(store.getState(), { pou: "Main", network: "n1" })).toBe(false);
    expect(isEnabled(store.getState(), { pou: "Main", element: "q1" })).toBe(true);
    setEnabled({ pou: "Main", network: "n1" }, true);
    setEnabled({ pou: "Main", element: "q1" }, false);
    remove({ pou: "Main", element: "q1" }); // disabled: the simulation does not have it
    setEnabled({ pou: "Main", element: "q1" }, true); // no longer listed: nothing happens
    setEnabled({ pou: "Main", network: "n1" }, false);
    toggle({ pou: "Main", network: "n1" }); // removes the disabled one without a message
    expect(store.getState()).toMatchObject({ breakpoints: [], disabled: [] });
    toggle({ pou: "Main", line: 2 });
    setEnabled({ pou: "Main", line: 2 }, false);
    clearAll(); // only disabled ones: the simulation has none to clear
    expect(send.mock.calls.map(([m]) => m)).toEqual([
      { type: "breakpoint_set", pou: "Main", network: "n1" },
      { type: "breakpoint_set", pou: "Main", element: "q1" },
      { type: "breakpoint_clear", pou: "Main", network: "n1" },
      { type: "breakpoint_set", pou: "Main", network: "n1" },
      { type: "breakpoint_clear", pou: "Main", element: "q1" },
      { type: "breakpoint_clear", pou: "Main", network: "n1" },
      { type: "breakpoint_set", pou: "Main", line: 2 },
      { type: "breakpoint_clear", pou: "Main", line: 2 },
    ]);
  });

  it("the simulation holds exactly the enabled breakpoints after any sequence of operations", () => {
    type Op = { kind: "toggle" | "remove" | "enable" | "disable"; bp: Breakpoint } | { kind: "clearAll" };
    const arbOp: fc.Arbitrary<Op> = fc.oneof(
      fc.record({
        kind: fc.constantFrom("toggle" as const, "remove" as const, "enable" as const, "disable" as const),
        bp: arbBreakpoint,
      }),
      fc.constant({ kind: "clearAll" as const }),
    );
    fc.assert(
      fc.property(fc.array(arbOp, { maxLength: 25 }), (ops) => {
        const server = new Map<string, Breakpoint>(); // what the simulation holds, from the messages alone
        const send = (msg: ClientMessage) => {
          if (msg.type === "breakpoint_set") server.set(breakpointKey(msg as Breakpoint), msg as Breakpoint);
          if (msg.type === "breakpoint_clear") {
            if (msg.pou == null) server.clear();
            else {
              expect(server.has(breakpointKey(msg as Breakpoint))).toBe(true); // never clears what it does not have
              server.delete(breakpointKey(msg as Breakpoint));
            }
          }
          return true;
        };
        const store = createDebugStore(send);
        for (const op of ops) {
          const s = store.getState();
          if (op.kind === "clearAll") s.clearAll();
          else if (op.kind === "toggle") s.toggle(op.bp);
          else if (op.kind === "remove") s.remove(op.bp);
          else s.setEnabled(op.bp, op.kind === "enable");
        }
        const state = store.getState();
        expect([...server.keys()].sort()).toEqual(
          state.breakpoints
            .filter((b) => isEnabled(state, b))
            .map(breakpointKey)
            .sort(),
        );
        expect(state.disabled.every((key) => state.breakpoints.some((b) => breakpointKey(b) === key))).toBe(true);
      }),
    );
  });

  it("keeps breakpoints set offline and sends the enabled ones on every new connection", async () => {
    const sockets: { sent: unknown[]; readyState: number; onopen: SocketLike["onopen"] }[] = [];
    const info = { id: "s1" } as SimulationInfo;
    const online = createOnlineStore(
      {
        createSimulation: async () => info,
        getSimulation: async () => info,
        listSimulations: async () => [info],
        resetSimulation: async () => info,
        deleteSimulation: async () => undefined,
        seekScan: async () => info,
        goLive: async () => info,
      },
      () => {
        const s = {
          sent: [] as unknown[],
          readyState: 0,
          onopen: null,
          onmessage: null,
          onclose: null,
          send: (d: string) => s.sent.push(JSON.parse(d)),
          close: () => undefined,
        };
        sockets.push(s);
        return s as unknown as SocketLike;
      },
    );
    const debug = createDebugStore((msg) => online.getState().send(msg), online);
    debug.getState().toggle({ pou: "Main", network: "n2" });
    debug.getState().toggle({ pou: "Main", line: 3 });
    debug.getState().toggle({ pou: "Fb", element: "q1" });
    debug.getState().setEnabled({ pou: "Main", line: 3 }, false);
    expect(debug.getState().breakpoints).toHaveLength(3);
    const connect = async () => {
      await online.getState().compile("demo");
      const socket = sockets[sockets.length - 1]!;
      socket.readyState = 1;
      socket.onopen?.call(socket as unknown as WebSocket, new Event("open"));
      return socket;
    };
    const breakpointMessages = (socket: { sent: unknown[] }) =>
      socket.sent.filter((m) => (m as { type: string }).type.startsWith("breakpoint"));
    const first = await connect();
    expect(breakpointMessages(first)).toEqual([
      { type: "breakpoint_set", pou: "Main", network: "n2" },
      { type: "breakpoint_set", pou: "Fb", element: "q1" },
    ]);
    // A reconnect (a new simulation): the same enabled breakpoints again, the disabled one still listed and disabled.
    const second = await connect();
    expect(second).not.toBe(first);
    expect(breakpointMessages(second)).toEqual(breakpointMessages(first));
    expect(isEnabled(debug.getState(), { pou: "Main", line: 3 })).toBe(false);
    debug.getState().setEnabled({ pou: "Main", line: 3 }, true);
    expect(breakpointMessages(second).at(-1)).toEqual({ type: "breakpoint_set", pou: "Main", line: 3 });
    await online.getState().goOffline();
  });
});

describe("breakpoints survive a page reload (kept per project in localStorage)", () => {
  const storage = () => {
    const items = new Map<string, string>();
    return {
      getItem: (key: string) => items.get(key) ?? null,
      setItem: (key: string, value: string) => void items.set(key, value),
      removeItem: (key: string) => void items.delete(key),
      items,
    } as unknown as Storage & { items: Map<string, string> };
  };

  it("a reloaded page gets each project's breakpoints back, enabled and disabled as they were", () => {
    const kept = storage();
    const before = createDebugStore(() => false, null, kept).getState();
    before.open("motor");
    before.toggle({ pou: "Main", network: "run_timer" });
    before.toggle({ pou: "Main", line: 4 });
    before.setEnabled({ pou: "Main", line: 4 }, false);
    before.open("tank");
    before.toggle({ pou: "Fill", element: "valve" });

    const reloaded = createDebugStore(() => false, null, kept);
    expect(reloaded.getState().breakpoints).toEqual([]);
    reloaded.getState().open("motor");
    expect(reloaded.getState().breakpoints).toEqual([
      { pou: "Main", network: "run_timer" },
      { pou: "Main", line: 4 },
    ]);
    expect(isEnabled(reloaded.getState(), { pou: "Main", line: 4 })).toBe(false);
    reloaded.getState().open("tank");
    expect(reloaded.getState().breakpoints).toEqual([{ pou: "Fill", element: "valve" }]);
    reloaded.getState().clearAll();
    expect(kept.items.has("ladderlab:breakpoints:tank")).toBe(false);
    reloaded.getState().open(null); // no project: none shown, the kept ones stay
    expect(reloaded.getState().breakpoints).toEqual([]);
    expect(kept.items.has("ladderlab:breakpoints:motor")).toBe(true);
  });

  it("switching projects clears the open simulation's breakpoints; restored ones are sent when it connects", () => {
    const kept = storage();
    const sent: ClientMessage[] = [];
    const debug = createDebugStore((msg) => sent.push(msg) > 0, null, kept).getState();
    debug.open("motor");
    debug.toggle({ pou: "Main", network: "n1" });
    debug.open("tank");
    expect(sent).toEqual([{ type: "breakpoint_set", pou: "Main", network: "n1" }, { type: "breakpoint_clear" }]);
    debug.open("motor");
    expect(sent).toHaveLength(2); // tank had none enabled: nothing to clear
  });

  it("an unreadable or foreign entry gives no breakpoints instead of an error", () => {
    const kept = storage();
    for (const text of [
      "{not json",
      "[1, 2]",
      JSON.stringify({
        breakpoints: [
          { pou: 3 },
          { pou: "Main" },
          { pou: "Main", line: 2.5 },
          { pou: "Main", line: 2, note: "x" },
          { pou: "MAIN", line: 2 },
        ],
        disabled: ["MAIN|line:2", "MAIN|line:9", 7],
      }),
    ]) {
      kept.setItem("ladderlab:breakpoints:p", text);
      const debug = createDebugStore(() => false, null, kept).getState();
      debug.open("p");
      const { breakpoints, disabled } = loadBreakpoints("p", kept);
      expect(breakpoints).toEqual(text.startsWith('{"') ? [{ pou: "Main", line: 2 }] : []);
      expect(disabled).toEqual(text.startsWith('{"') ? ["MAIN|line:2"] : []);
    }
  });
});
