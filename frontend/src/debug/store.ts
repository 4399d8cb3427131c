// The breakpoints of the open project and the halted-scan commands (continue, step). Breakpoints
// live in the browser and are sent to the simulation as they change; a new connection (compile,
// reconnect) gets all of them again, since a new simulation starts with none.
import { useStore } from "zustand";
import { createStore, type StoreApi } from "zustand/vanilla";
import type { ClientMessage } from "../online/protocol";
import { onlineStore, type OnlineState } from "../online/store";
import { clearMessage, sameBreakpoint, setMessage, toggle, type Breakpoint, type StepGranularity } from "./breakpoints";

export interface DebugState {
  breakpoints: Breakpoint[];
  toggle(bp: Breakpoint): void;
  remove(bp: Breakpoint): void;
  clearAll(): void;
  resume(): void;
  step(granularity: StepGranularity): void;
}

/** `send` delivers a message to the simulation (false when not connected: the list still changes). */
export function createDebugStore(send: (msg: ClientMessage) => boolean, online: StoreApi<OnlineState> | null = null): StoreApi<DebugState> {
  const store = createStore<DebugState>()((set, get) => ({
    breakpoints: [],
    toggle(bp) {
      const { list, message } = toggle(get().breakpoints, bp);
      set({ breakpoints: list });
      send(message);
    },
    remove(bp) {
      const rest = get().breakpoints.filter((b) => !sameBreakpoint(b, bp));
      if (rest.length === get().breakpoints.length) return;
      set({ breakpoints: rest });
      send(clearMessage(bp));
    },
    clearAll() {
      const had = get().breakpoints.length > 0;
      set({ breakpoints: [] });
      if (had) send({ type: "breakpoint_clear" });
    },
    resume: () => void send({ type: "continue" }),
    step: (granularity) => void send({ type: "step", granularity }),
  }));
  online?.subscribe((state, previous) => {
    if (state.phase === "online" && previous.phase !== "online") for (const bp of store.getState().breakpoints) send(setMessage(bp));
  });
  return store;
}

export const debugStore = createDebugStore((msg) => onlineStore.getState().send(msg), onlineStore);

export function useDebug<T>(selector: (state: DebugState) => T): T {
  return useStore(debugStore, selector);
}
