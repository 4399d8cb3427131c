// Keeps the breakpoints on what they are on as the working copy changes (issue 22): one whose POU, network,
// element or line is gone is dropped with a message. Renames and ST line edits move them before the change
// arrives here (PouActions' rename, the ST editor's line mapping), so only what is really gone is dropped.
import { debugStore } from "../debug/store";
import { goneBecause } from "../breakpointPlaces/follow";
import { panelsStore } from "../store/panels";
import { onlineStore } from "../online/store";
import { workspaceStore } from "../store/project";

/** Starts following the open project; returns the function that stops it. A new message shows the Breakpoints
 * panel, where it is, and goes into the online log with the session's other events. */
export function followBreakpoints(): () => void {
  const showNotice = debugStore.subscribe((state, previous) => {
    if (!state.notice || state.notice === previous.notice) return;
    panelsStore.getState().show("breakpoints");
    onlineStore.getState().note("warning", state.notice);
  });
  const follow = workspaceStore.subscribe((state, previous) => {
    const next = state.project;
    const before = previous.project;
    if (!next || !before || next === before || state.name !== previous.name) return;
    if (debugStore.getState().project !== state.name || debugStore.getState().breakpoints.length === 0) return;
    debugStore.getState().follow(
      (bp) => (goneBecause(bp, next, before) === null ? bp : null),
      (bp) => goneBecause(bp, next, before) ?? "",
    );
  });
  return () => {
    showNotice();
    follow();
  };
}
