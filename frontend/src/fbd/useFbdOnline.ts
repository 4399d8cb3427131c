// Connects the FBD editor to online mode, as useLdOnline does for LD: subscribes the probes and
// variables of the POU's instance, turns the monitor into the diagram's online view, and offers
// the operand commands (write, force, release, watch) on simulation paths.
import { useCallback, useMemo, useState } from "react";
import type { SymbolInfo } from "../generated/api";
import type { Pou } from "../generated/api";
import type { LdOnlineActions } from "../online/operandCommands";
import { partMonitor } from "../online/parts";
import { useOnline } from "../online/store";
import { useDiagramSubscription, useShownInstance, onlineReadOnly, operandActions } from "../online/editorOnline";
import type { FbdBody, Lookup } from "./model";
import { bindFbd, fbdOnlineView, type FbdOnlineView } from "./online";

export interface FbdOnline {
  online?: FbdOnlineView;
  readOnly: string | null;
  actions?: LdOnlineActions;
  onVisibleChange(networks: readonly string[]): void;
  /** The editor's feedback pins (order.ts feedbackPins over the reported order), shown with what they read. */
  onFeedbackChange(pins: ReadonlySet<string>): void;
}

/** `symbols` null: not arrived yet, nothing is bound (see useLdOnline). */
export function useFbdOnline(
  pou: Pou,
  body: FbdBody,
  lookup: Lookup,
  symbols: readonly SymbolInfo[] | null,
  /** The body is an SFC action or transition of the POU ("actions/Fill", online/parts.ts). */
  part?: string,
): FbdOnline {
  const phase = useOnline((s) => s.phase);
  const monitor = useOnline((s) => s.monitor);
  const prepared = useOnline((s) => s.prepared);
  const instance = useShownInstance(pou);
  const key = part ? `fbd:${pou.name}/${part}` : `fbd:${pou.name}`;
  const live = phase !== "offline";

  const [visible, setVisible] = useState<ReadonlySet<string> | null>(null);
  const onVisibleChange = useCallback((networks: readonly string[]) => setVisible(new Set(networks)), []);
  const [feedback, setFeedback] = useState<ReadonlySet<string>>(new Set());
  const onFeedbackChange = useCallback(
    (pins: ReadonlySet<string>) =>
      setFeedback((old) => (old.size === pins.size && [...pins].every((p) => old.has(p)) ? old : pins)),
    [],
  );
  const binding = useMemo(
    () => (instance && symbols ? bindFbd(body, instance, lookup, symbols, visible ?? undefined, feedback) : null),
    [body, instance, lookup, symbols, visible, feedback],
  );
  useDiagramSubscription(key, live, binding, part);

  const online = useMemo(
    () => (live && binding ? fbdOnlineView(partMonitor(monitor, instance, part), binding, prepared) : undefined),
    [live, binding, monitor, prepared, instance, part],
  );
  const actions = useMemo(
    () => (live && instance && symbols ? operandActions(instance, symbols) : undefined),
    [live, instance, symbols],
  );
  return { online, readOnly: onlineReadOnly(pou, live, instance), actions, onVisibleChange, onFeedbackChange };
}
