import type { ClientMessage } from "../online/protocol";
import fc from "fast-check";
import { describe, expect, it, vi } from "vitest";
import type { SimulationInfo } from "../generated/api";
import { createOnlineStore, type SocketLike } from "../online/store";
import { describeBreakpoint, describeHalt, sameBreakpoint, toggle, type Breakpoint } from "./breakpoints";
import { createDebugStore } from "./store";

const arbBreakpoint: fc.Arbitrary<Breakpoint> = fc.oneof(
  fc.record({ pou: fc.constantFrom("Main", "MAIN", "Fb"), network: fc.constantFrom("n1", "n2") }),
  fc.record({ pou: fc.constantFrom("Main", "Fb"), element: fc.constantFrom("c1", "q1") }),
  fc.record({ pou: fc.constantFrom("Main", "st"), line: fc.integer({ min: 1, max: 3 }) }),
);

describe("breakpoint list (issue 9: toggle a breakpoint on a network or element)", () => {
  it("toggles: set when absent, clear when present, with the matching protocol message", () => {
    const first = toggle([], { pou: "Main", network: "n2" });
    expect(first).toEqual({ list: [{ pou: "Main", network: "n2" }], message: { type: "breakpoint_set", pou: "Main", network: "n2" } });
    const second = toggle(first.list, { pou: "MAIN", network: "n2" });
    expect(second).toEqual({ list: [], message: { type: "breakpoint_clear", pou: "MAIN", network: "n2" } });
    expect(toggle(first.list, { pou: "Main", element: "n2" }).message.type).toBe("breakpoint_set");
  });

  it("toggling twice restores any list and never holds duplicates", () => {
    fc.assert(
      fc.property(fc.array(arbBreakpoint, { maxLength: 12 }), arbBreakpoint, (steps, bp) => {
        const list = steps.reduce<Breakpoint[]>((acc, b) => toggle(acc, b).list, []);
        for (let i = 0; i < list.length; i++) for (let j = i + 1; j < list.length; j++) expect(sameBreakpoint(list[i]!, list[j]!)).toBe(false);
        const twice = toggle(toggle(list, bp).list, bp).list;
        expect(twice.filter((b) => !sameBreakpoint(b, bp))).toEqual(list.filter((b) => !sameBreakpoint(b, bp)));
        expect(twice.some((b) => sameBreakpoint(b, bp))).toBe(list.some((b) => sameBreakpoint(b, bp)));
      }),
    );
  });

  it("describes breakpoints and halts with network positions", () => {
    expect(describeBreakpoint({ pou: "Main", network: "n7" }, ["n3", "n7"])).toBe("Main, network 2");
    expect(describeBreakpoint({ pou: "Main", network: "zz" }, ["n3"])).toBe("Main, network zz");
    expect(describeBreakpoint({ pou: "Main", element: "c1" })).toBe("Main, element c1");
    expect(describeHalt({ pou: "Blink", instance: "MAIN.B1", network: "n3", element: "c2" }, ["n3"])).toBe("Blink (MAIN.B1), network 1, element c2");
    expect(describeHalt({ pou: "Main", instance: "MAIN", line: 4 })).toBe("Main, line 4");
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

  it("keeps breakpoints set offline and sends them all when a simulation connects", async () => {
    const sockets: { sent: unknown[]; readyState: number; onopen: SocketLike["onopen"] }[] = [];
    const info = { id: "s1" } as SimulationInfo;
    const online = createOnlineStore(
      { createSimulation: async () => info, getSimulation: async () => info, resetSimulation: async () => info, deleteSimulation: async () => undefined },
      () => {
        const s = { sent: [] as unknown[], readyState: 0, onopen: null, onmessage: null, onclose: null, send: (d: string) => s.sent.push(JSON.parse(d)), close: () => undefined };
        sockets.push(s);
        return s as unknown as SocketLike;
      },
    );
    const debug = createDebugStore((msg) => online.getState().send(msg), online);
    debug.getState().toggle({ pou: "Main", network: "n2" });
    debug.getState().toggle({ pou: "Main", line: 3 });
    expect(debug.getState().breakpoints).toHaveLength(2);
    await online.getState().compile("demo");
    const socket = sockets[0]!;
    socket.readyState = 1;
    socket.onopen?.call(socket as unknown as WebSocket, new Event("open"));
    expect(socket.sent.filter((m) => (m as { type: string }).type.startsWith("breakpoint"))).toEqual([
      { type: "breakpoint_set", pou: "Main", network: "n2" },
      { type: "breakpoint_set", pou: "Main", line: 3 },
    ]);
    await online.getState().goOffline();
  });
});
