// Shows a place of the project in its editor: opens the POU (named in any case: the simulation
// reports halts in the compiled spelling) and asks the editor to select and scroll to the place.
import { panelsStore } from "../store/panels";
import { workspaceStore } from "../store/project";

export interface Place {
  pou: string;
  network?: string | null;
  element?: string | null;
  line?: number | null;
  /** The SFC action or named transition it is in ("actions/Fill"). */
  body?: string | null;
}

export function revealPlace(target: Place): void {
  const ws = workspaceStore.getState();
  const pou = ws.project?.pous?.find((p) => p.name.toUpperCase() === target.pou.toUpperCase())?.name ?? target.pou;
  ws.openPou(pou);
  panelsStore.getState().reveal({ ...target, pou, part: "body" });
}
