// Connects one LD editor to online mode: subscribes the networks in view of a program's POU, turns
// the monitor into the diagram's online view (power, values of operands and box pins, ld/online.ts),
// and maps the diagram's operand commands onto simulation paths (online/editorOnline.ts).
import { useCallback, useMemo, useState } from "react";
import type { LibraryEntry, Pou, SymbolInfo } from "../generated/api";
import {
  onlineReadOnly,
  operandActions,
  useDiagramSubscription,
  useLibraryLookup,
  useShownInstance,
} from "../online/editorOnline";
import type { LdOnlineActions } from "../online/operandCommands";
import { partMonitor } from "../online/parts";
import { blockEntry } from "../store/calls";
import { useOnline } from "../online/store";
import type { LdBody } from "./model";
import { bindLd, ldOnlineView } from "./online";
import type { OnlineView } from "./view/types";

export interface LdOnline {
  online?: OnlineView;
  readOnly: string | null;
  actions?: LdOnlineActions;
  onVisibleChange(networks: readonly string[]): void;
}

/**
 * `symbols` null: the POU's symbol table has not arrived, so its operands cannot be told apart as
 * its own variables or globals yet; nothing is bound (no wrong paths) until it has. `part`: the body is
 * an SFC action or transition of the POU ("actions/Fill", online/parts.ts).
 */
export function useLdOnline(
  pou: Pou,
  body: LdBody,
  symbols: readonly SymbolInfo[] | null,
  library: readonly LibraryEntry[],
  part?: string,
): LdOnline {
  const phase = useOnline((s) => s.phase);
  const monitor = useOnline((s) => s.monitor);
  const prepared = useOnline((s) => s.prepared);
  const [visible, setVisible] = useState<ReadonlySet<string> | null>(null);
  const instance = useShownInstance(pou);
  const key = part ? `ld:${pou.name}/${part}` : `ld:${pou.name}`;
  const live = phase !== "offline";
  const libraryEntry = useLibraryLookup(library);
  const lookup = useCallback(
    (call: string) => blockEntry(call, libraryEntry, symbols ?? []), // `inst.M` binds its method's pins
    [libraryEntry, symbols],
  );

  const binding = useMemo(
    () => (instance && symbols ? bindLd(body, instance, symbols, lookup, visible ?? undefined) : null),
    [body, instance, symbols, lookup, visible],
  );

  useDiagramSubscription(key, live, binding, part);

  const onVisibleChange = useCallback((networks: readonly string[]) => setVisible(new Set(networks)), []);
  const online = useMemo(
    () => (live && binding ? ldOnlineView(partMonitor(monitor, instance, part), binding, prepared) : undefined),
    [live, binding, monitor, prepared, instance, part],
  );

  const actions = useMemo(
    () => (live && instance && symbols ? operandActions(instance, symbols) : undefined),
    [live, instance, symbols],
  );
  const readOnly = onlineReadOnly(pou, live, instance);
  return { online, readOnly, actions, onVisibleChange };
}
