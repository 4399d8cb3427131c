// Connects one LD editor to the debug store: the breakpoints of its POU and the halt as diagram
// marks, and toggling from the diagram. The LD view knows nothing of the store.
import { useMemo } from "react";
import type { LdDebugging } from "../ld/editor/LdEditor";
import { locate, type LdBody } from "../ld/model";
import type { DebugMarks } from "../ld/view/types";
import type { At } from "../online/protocol";
import { haltedAt } from "../online/monitor";
import { useOnline } from "../online/store";
import type { Breakpoint } from "./breakpoints";
import { debugStore, isEnabled, useDebug } from "./store";

const samePou = (a: string, b: string) => a.toUpperCase() === b.toUpperCase();

/** The marks of POU `pou`: its network and element breakpoints (enabled or not) and where `halted` stands in it. */
export function ldDebugMarks(
  pou: string,
  body: LdBody,
  breakpoints: readonly Breakpoint[],
  disabled: readonly string[],
  halted: At | null,
): DebugMarks {
  const networks: Record<string, boolean> = {};
  const elements: Record<string, boolean> = {};
  for (const bp of breakpoints) {
    if (!samePou(bp.pou, pou)) continue;
    if ("network" in bp) networks[bp.network] = isEnabled({ disabled }, bp);
    else if ("element" in bp) elements[bp.element] = isEnabled({ disabled }, bp);
  }
  const element = halted?.element ?? null;
  const network =
    halted && samePou(halted.pou, pou)
      ? (halted.network ?? (element ? locate(body, element)?.network : undefined))
      : undefined;
  return { networks, elements, halted: network ? { network, element } : null };
}

/** The editor's `debugging` prop for POU `pou` showing `body`. */
export function useLdDebugging(pou: string, body: LdBody): LdDebugging {
  const breakpoints = useDebug((s) => s.breakpoints);
  const disabled = useDebug((s) => s.disabled);
  const halted = useOnline((s) => haltedAt(s.monitor));
  return useMemo(
    () => ({
      marks: ldDebugMarks(pou, body, breakpoints, disabled, halted),
      toggle: (target) => debugStore.getState().toggle({ pou, ...target }),
    }),
    [pou, body, breakpoints, disabled, halted],
  );
}
