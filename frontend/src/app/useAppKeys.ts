// The app's own keys (scope "app" of src/keys/keymap.ts): saving, checking, online mode and
// debugging, CODESYS style, wherever the focus is. One window listener for all of them; the editors
// handle their own keys first (a key they took is not seen here).
import { useEffect } from "react";
import { debugStore } from "../debug/store";
import { commandsFor, RESERVED_KEYS, type CommandOf } from "../keys/keymap";
import { checkWorkingCopy, compileSaved } from "../online/SimulationBar";
import { onlineStore } from "../online/store";
import { workspaceStore } from "../store/project";

/** What each app key does now; false when it does not apply (e.g. a step while offline). */
export function appKeyActions(): Record<CommandOf<"app">, () => boolean> {
  const online = () => onlineStore.getState();
  const connected = () => online().phase === "online";
  const when = (ok: boolean, run: () => unknown) => {
    if (ok) void run();
    return ok;
  };
  return {
    save: () => when(workspaceStore.getState().name !== null, () => workspaceStore.getState().save()),
    check: () => when(true, checkWorkingCopy),
    "go-online": () => when(true, compileSaved),
    "go-offline": () => when(online().phase !== "offline", online().goOffline),
    run: () => when(connected(), online().monitor.state === "halted" ? debugStore.getState().resume : online().run),
    stop: () => when(connected(), online().stop),
    "single-cycle": () => when(connected(), online().singleCycle),
    "force-prepared": () => when(connected(), () => online().applyPrepared("force")),
    "write-prepared": () => when(connected(), () => online().applyPrepared("write")),
    "release-forces": () => when(connected(), online().unforceAll),
    "step-over": () => when(connected(), () => debugStore.getState().step("over")),
    "step-into": () => when(connected(), () => debugStore.getState().step("statement")),
    "step-out": () => when(connected(), () => debugStore.getState().step("out")),
    "step-transition": () => when(connected(), () => debugStore.getState().step("transition")),
  };
}

/** Handles one key press on the window: the app's command bound to it, if any applies. */
export function onAppKey(event: KeyboardEvent): void {
  if (event.defaultPrevented) return; // an editor or dialog took it
  // F5 must never reload the page (nor Ctrl+F5 etc.), whatever the state: the session would be lost.
  if (RESERVED_KEYS.has(event.key)) event.preventDefault();
  const actions = appKeyActions();
  for (const command of commandsFor("app", event)) {
    if (actions[command]()) {
      event.preventDefault();
      return;
    }
  }
}

export function useAppKeys(): void {
  useEffect(() => {
    window.addEventListener("keydown", onAppKey);
    return () => window.removeEventListener("keydown", onAppKey);
  }, []);
}
