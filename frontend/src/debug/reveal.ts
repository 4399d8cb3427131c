// Shows a place of the project in its editor: opens the POU (named in any case: the simulation
// reports halts in the compiled spelling) and asks the editor to select and scroll to the place.
import { methodPlace, panelsStore } from "../store/panels";
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
  const named = (name: string) => ws.project?.pous?.find((p) => p.name.toUpperCase() === name.toUpperCase())?.name;
  const method = named(target.pou) ? null : methodPlace(target.pou); // a method's code: its FB's Methods tab
  const pou = named(method?.pou ?? target.pou) ?? target.pou;
  ws.openPou(pou);
  panelsStore
    .getState()
    .reveal({ ...target, pou, part: "body", member: method?.member ?? null, accessor: method?.accessor ?? null });
}
