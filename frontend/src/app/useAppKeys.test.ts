// @vitest-environment jsdom
import { afterEach, beforeEach, describe, expect, it, vi } from "vitest";
import { debugStore } from "../debug/store";
import { emptyMonitor } from "../online/monitor";
import type { ClientMessage } from "../online/protocol";
import { offline, onlineStore } from "../online/store";
import { onAppKey } from "./useAppKeys";

const realSend = onlineStore.getState().send;
let sent: ClientMessage[] = [];

beforeEach(() => {
  sent = [];
  onlineStore.setState({
    phase: "online",
    monitor: { ...emptyMonitor, state: "stopped" },
    send: (msg) => (sent.push(msg), true),
  });
  window.addEventListener("keydown", onAppKey);
});
afterEach(() => {
  window.removeEventListener("keydown", onAppKey);
  onlineStore.setState({ ...offline, send: realSend });
  debugStore.setState({ breakpoints: [], disabled: [] });
});

/** Presses a key on the window; whether the browser's own action was prevented. */
function press(key: string, mods: Partial<Pick<KeyboardEvent, "ctrlKey" | "altKey" | "shiftKey">> = {}): boolean {
  const event = new KeyboardEvent("keydown", { key, cancelable: true, ...mods });
  window.dispatchEvent(event);
  return event.defaultPrevented;
}

describe("the app's keys (issue 17: CODESYS's keys, one keymap)", () => {
  it("runs, stops and single-cycles; F5 continues a halted scan", () => {
    press("F5");
    press("F5", { shiftKey: true });
    press("F5", { ctrlKey: true });
    onlineStore.setState({ monitor: { ...emptyMonitor, state: "halted", at: { pou: "MAIN" } } });
    press("F5");
    expect(sent).toEqual([{ type: "run" }, { type: "stop" }, { type: "single_cycle" }, { type: "continue" }]);
  });

  it("steps over (F10), into (F11) and out (Shift+F11)", () => {
    press("F10");
    press("F11");
    press("F11", { shiftKey: true });
    expect(sent).toEqual([
      { type: "step", granularity: "over" },
      { type: "step", granularity: "statement" },
      { type: "step", granularity: "out" },
    ]);
  });

  it("forces (F7) or writes (Ctrl+F7) the prepared values, and releases every force (Alt+F7)", () => {
    onlineStore.getState().prepare("MAIN.START", true);
    press("F7");
    onlineStore.getState().prepare("MAIN.SPEED", 7);
    press("F7", { ctrlKey: true });
    press("F7", { altKey: true });
    expect(sent).toEqual([
      { type: "force", path: "MAIN.START", value: true },
      { type: "write", path: "MAIN.SPEED", value: 7 },
      { type: "unforce_all" },
    ]);
  });

  it("never lets F5 reload the page, online or offline, with any modifiers, and does nothing for unlisted ones", () => {
    expect(press("F5", { altKey: true })).toBe(true);
    expect(press("F5", { ctrlKey: true, shiftKey: true })).toBe(true);
    expect(sent).toEqual([]);
    onlineStore.setState({ ...offline });
    for (const mods of [{}, { shiftKey: true }, { ctrlKey: true }]) expect(press("F5", mods)).toBe(true);
    expect(press("F10", { ctrlKey: true })).toBe(true); // reserved, unbound: nothing
    expect(sent).toEqual([]);
    expect(press("a")).toBe(false); // other keys stay the browser's
  });

  it("leaves a key an editor or dialog took alone", () => {
    const event = new KeyboardEvent("keydown", { key: "F5", cancelable: true });
    event.preventDefault();
    window.dispatchEvent(event);
    expect(sent).toEqual([]);
  });

  it("goes offline on Ctrl+F8", async () => {
    const goOffline = vi.fn(async () => undefined);
    onlineStore.setState({ goOffline });
    press("F8", { ctrlKey: true });
    expect(goOffline).toHaveBeenCalledTimes(1);
  });
});
