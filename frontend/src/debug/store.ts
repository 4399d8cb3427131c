// The breakpoints of the open project and the halted-scan commands (continue, step). Breakpoints
// live in the browser and are sent to the simulation as they change; a new connection (compile,
// reconnect) gets every enabled one again, since a new simulation starts with none. A disabled
// breakpoint stays listed but is cleared in the simulation; enabling it sends it again. Each
// project's breakpoints are kept in localStorage, so they survive a page reload.
import { useStore } from "zustand";
import { createStore, type StoreApi } from "zustand/vanilla";
import type { ClientMessage } from "../online/protocol";
import { onlineStore, type OnlineState } from "../online/store";
import {
  breakpointKey,
  clearMessage,
  sameBreakpoint,
  setMessage,
  toggle,
  type Breakpoint,
  type StepGranularity,
} from "./breakpoints";

export interface DebugState {
  /** The project the breakpoints belong to (null: none open yet). */
  project: string | null;
  /** Every breakpoint, enabled or not, in the order they were set. */
  breakpoints: Breakpoint[];
  /** `breakpointKey`s of the disabled ones. */
  disabled: string[];
  /** Adds `bp` (enabled) or removes it when it is there. */
  toggle(bp: Breakpoint): void;
  /** Switches to `project`'s breakpoints as they were last kept, or to none for no project (the open
   * simulation's are cleared). */
  open(project: string | null): void;
  remove(bp: Breakpoint): void;
  clearAll(): void;
  /** Enables (sent to the simulation) or disables (cleared there, kept in the list) a listed breakpoint. */
  setEnabled(bp: Breakpoint, enabled: boolean): void;
  resume(): void;
  step(granularity: StepGranularity): void;
  /** Why breakpoints were removed without the user asking (their POU, network, element or line is gone). */
  notice: string | null;
  dismissNotice(): void;
  /** Rewrites every breakpoint by `follow` (null: it is gone, `why` says so in the notice), keeping each one's
   * enabled state; the simulation is told of those that changed. */
  follow(follow: (bp: Breakpoint) => Breakpoint | null, why: (bp: Breakpoint) => string): void;
}

/** Whether a listed breakpoint is enabled (one not listed counts as enabled: it has no state yet). */
export const isEnabled = (state: { readonly disabled: readonly string[] }, bp: Breakpoint): boolean =>
  !state.disabled.includes(breakpointKey(bp));

const storageKey = (project: string) => `ladderlab:breakpoints:${project}`;

/** A kept breakpoint as the store holds it, or null for anything else (the entry is the browser's, not ours). */
function asBreakpoint(value: unknown): Breakpoint | null {
  if (typeof value !== "object" || value === null) return null;
  const { pou, network, element, line, body } = value as Record<string, unknown>;
  if (typeof pou !== "string") return null;
  const part = typeof body === "string" ? { body } : {};
  if (typeof network === "string") return { pou, ...part, network };
  if (typeof element === "string") return { pou, ...part, element };
  return typeof line === "number" && Number.isInteger(line) ? { pou, ...part, line } : null;
}

/** `project`'s kept breakpoints; nothing (not an error) when none were kept or the entry is unreadable. */
export function loadBreakpoints(project: string, storage: Storage): Pick<DebugState, "breakpoints" | "disabled"> {
  try {
    const kept = JSON.parse(storage.getItem(storageKey(project)) ?? "null") as {
      breakpoints?: unknown;
      disabled?: unknown;
    } | null;
    const breakpoints: Breakpoint[] = [];
    const keys = new Set<string>();
    for (const bp of Array.isArray(kept?.breakpoints) ? kept.breakpoints.map(asBreakpoint) : []) {
      if (bp && !keys.has(breakpointKey(bp))) {
        keys.add(breakpointKey(bp));
        breakpoints.push(bp);
      }
    }
    const disabled = Array.isArray(kept?.disabled)
      ? kept.disabled.filter((k): k is string => typeof k === "string" && keys.has(k))
      : [];
    return { breakpoints, disabled };
  } catch {
    return { breakpoints: [], disabled: [] };
  }
}

function keepBreakpoints(project: string, state: Pick<DebugState, "breakpoints" | "disabled">, storage: Storage): void {
  try {
    if (state.breakpoints.length === 0) storage.removeItem(storageKey(project));
    else
      storage.setItem(
        storageKey(project),
        JSON.stringify({ breakpoints: state.breakpoints, disabled: state.disabled }),
      );
  } catch {
    // storage full or refused: the breakpoints still work until the page is reloaded
  }
}

/** `send` delivers a message to the simulation (false when not connected: the list still changes);
 * `storage` keeps each project's breakpoints across page reloads. */
export function createDebugStore(
  send: (msg: ClientMessage) => boolean,
  online: StoreApi<OnlineState> | null = null,
  storage: Storage | null = null,
): StoreApi<DebugState> {
  const store = createStore<DebugState>()((set, get) => {
    const listed = (bp: Breakpoint) => get().breakpoints.find((b) => sameBreakpoint(b, bp));
    const without = (bp: Breakpoint) => ({
      breakpoints: get().breakpoints.filter((b) => !sameBreakpoint(b, bp)),
      disabled: get().disabled.filter((key) => key !== breakpointKey(bp)),
    });
    return {
      project: null,
      breakpoints: [],
      disabled: [],
      open(project) {
        if (get().breakpoints.some((b) => isEnabled(get(), b))) send({ type: "breakpoint_clear" });
        set({
          project,
          ...(storage && project !== null ? loadBreakpoints(project, storage) : { breakpoints: [], disabled: [] }),
        });
      },
      toggle(bp) {
        const found = listed(bp);
        if (found && !isEnabled(get(), found)) {
          set(without(found)); // the simulation does not have it: nothing to clear
          return;
        }
        const { list, message } = toggle(get().breakpoints, bp);
        set({ breakpoints: list, disabled: without(bp).disabled });
        send(message);
      },
      remove(bp) {
        const found = listed(bp);
        if (!found) return;
        const enabled = isEnabled(get(), found);
        set(without(found));
        if (enabled) send(clearMessage(bp));
      },
      clearAll() {
        const anyEnabled = get().breakpoints.some((b) => isEnabled(get(), b));
        set({ breakpoints: [], disabled: [] });
        if (anyEnabled) send({ type: "breakpoint_clear" });
      },
      setEnabled(bp, enabled) {
        const found = listed(bp);
        if (!found || isEnabled(get(), found) === enabled) return;
        const key = breakpointKey(found);
        set({ disabled: enabled ? get().disabled.filter((k) => k !== key) : [...get().disabled, key] });
        send(enabled ? setMessage(found) : clearMessage(found));
      },
      notice: null,
      dismissNotice: () => set({ notice: null }),
      follow(follow, why) {
        const { breakpoints } = get();
        const next: Breakpoint[] = [];
        const disabled: string[] = [];
        const reasons: string[] = [];
        let changed = false;
        for (const bp of breakpoints) {
          const enabled = isEnabled(get(), bp);
          const moved = follow(bp);
          const same = moved !== null && sameBreakpoint(moved, bp) && moved.pou === bp.pou;
          if (!same) {
            changed = true;
            if (enabled) send(clearMessage(bp));
          }
          if (!moved) reasons.push(why(bp));
          // moved onto another one: one is enough
          if (!moved || next.some((b) => sameBreakpoint(b, moved))) continue;
          const kept = same ? bp : moved;
          next.push(kept);
          if (!enabled) disabled.push(breakpointKey(kept));
          else if (!same) send(setMessage(kept));
        }
        if (!changed) return;
        set({ breakpoints: next, disabled, ...(reasons.length ? { notice: reasons.join(" ") } : {}) });
      },
      resume: () => void send({ type: "continue" }),
      step: (granularity) => void send({ type: "step", granularity }),
    };
  });
  store.subscribe((state, previous) => {
    const changed = state.breakpoints !== previous.breakpoints || state.disabled !== previous.disabled;
    if (storage && state.project !== null && state.project === previous.project && changed)
      keepBreakpoints(state.project, state, storage);
  });
  online?.subscribe((state, previous) => {
    if (state.phase !== "online" || previous.phase === "online") return;
    const debug = store.getState();
    for (const bp of debug.breakpoints) if (isEnabled(debug, bp)) send(setMessage(bp));
  });
  return store;
}

/** Sends only while connected: offline changes are kept and sent when a simulation connects. */
export const debugStore = createDebugStore(
  (msg) => onlineStore.getState().phase === "online" && onlineStore.getState().send(msg),
  onlineStore,
  localStorage,
);

export function useDebug<T>(selector: (state: DebugState) => T): T {
  return useStore(debugStore, selector);
}
