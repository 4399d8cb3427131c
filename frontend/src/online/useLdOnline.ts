// Connects one LD editor to online mode: subscribes the networks in view of a program's POU,
// turns the monitor into the diagram's online view, and maps the diagram's operand commands
// (toggle, write, force, watch) onto simulation paths.
import { useCallback, useEffect, useMemo, useState } from "react";
import type { SymbolInfo } from "../generated/api";
import type { Pou } from "../generated/project";
import type { LdOnlineActions } from "../ld/editor/LdEditor";
import type { LdBody } from "../ld/model";
import type { OnlineView } from "../ld/view/types";
import { bindLd, ldOnlineView, operandPath } from "./ldBinding";
import { parseValue, pathKey } from "./monitor";
import { onlineStore, useOnline } from "./store";

/** The instance whose values an LD POU shows: a program is its own instance; FBs and functions have none here. */
export const instanceOf = (pou: Pick<Pou, "kind" | "name">): string | null => (pou.kind === "program" ? pou.name.toUpperCase() : null);

export const GO_OFFLINE_TO_EDIT = "Online: the diagram shows the running simulation. Go offline to edit.";

export interface LdOnline {
  online?: OnlineView;
  readOnly: string | null;
  actions?: LdOnlineActions;
  onVisibleChange(networks: readonly string[]): void;
}

export function useLdOnline(pou: Pou, body: LdBody, symbols: readonly SymbolInfo[]): LdOnline {
  const phase = useOnline((s) => s.phase);
  const monitor = useOnline((s) => s.monitor);
  const [visible, setVisible] = useState<ReadonlySet<string> | null>(null);
  const instance = instanceOf(pou);
  const key = `ld:${pou.name}`;
  const live = phase !== "offline";

  const binding = useMemo(() => (instance ? bindLd(body, instance, symbols, visible ?? undefined) : null), [body, instance, symbols, visible]);

  useEffect(() => {
    onlineStore.getState().subscribe(key, live && binding ? { paths: binding.paths, elements: binding.elements } : null);
  }, [key, live, binding]);
  useEffect(() => () => onlineStore.getState().subscribe(key, null), [key]);

  const onVisibleChange = useCallback((networks: readonly string[]) => setVisible(new Set(networks)), []);
  const online = useMemo(() => (live && binding ? ldOnlineView(monitor, binding) : undefined), [live, binding, monitor]);

  const actions = useMemo((): LdOnlineActions | undefined => {
    if (!live || !instance) return undefined;
    const path = (operand: string) => operandPath(operand, instance, symbols);
    const store = () => onlineStore.getState();
    return {
      toggle(operand) {
        const p = path(operand);
        if (p) store().write(p, store().monitor.values[pathKey(p)] !== true);
      },
      write(operand, text) {
        const p = path(operand);
        if (p) store().write(p, parseValue(text));
      },
      force(operand, value) {
        const p = path(operand);
        if (p) store().force(p, typeof value === "boolean" ? value : parseValue(value));
      },
      unforce(operand) {
        const p = path(operand);
        if (p) store().unforce(p);
      },
      watch(operand) {
        const p = path(operand);
        if (p) store().addWatch(p);
      },
    };
  }, [live, instance, symbols]);

  return {
    online,
    readOnly: live ? (instance ? GO_OFFLINE_TO_EDIT : `Online: live values are shown for programs; ${pou.name} is a ${pou.kind.replace("_", " ")}. Go offline to edit.`) : null,
    actions,
    onVisibleChange,
  };
}
