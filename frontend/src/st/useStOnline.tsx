// Connects an ST body to online mode: subscribes the paths of its variable occurrences for the
// POU's instance (the halted instance while a scan halts in this POU, so values are those of the
// halt), turns the monitor's values into inline marks and hover text, prepares a value on a
// double-click (CODESYS) and offers write / force / release from a right click with the LD
// editor's menu and value prompt. An array element `a[i]` acts on the element `i` names now.
// An IL body also shows the accumulator after each line (ilOnline.ts), from the instance's probes. A FUNCTION has
// no instance: its own variables show while the scan is halted in a call of it (callValues.ts). A METHOD's or
// property accessor's body (the Methods tab) shows its FB instance's variables so, and its own from the call stack
// while halted in it (methodScope.ts: its own names hide the FB's).
import { useEffect, useMemo, useState, type ReactNode } from "react";
import type { Pou } from "../generated/api";
import { MenuList } from "../ui/MenuList";
import { OperandValuePrompt } from "../online/ValuePrompt";
import { onlineOperandItems, operandCommands } from "../online/operandCommands";
import { haltedAt } from "../online/monitor";
import { onlineStore, useOnline } from "../online/store";
import { useShownInstance } from "../online/editorOnline";
import {
  concretePath,
  describe,
  inlineMarks,
  variableOccurrences,
  type InlineMark,
  type Occurrence,
  type StOnlineView,
} from "./inlineValues";
import { useCallValues, withCall } from "./callValues";
import { ownNames } from "./methodScope";
import { accumulatorMarks } from "./ilOnline";
import type { Scope } from "./members";

export interface StOnline {
  /** A simulation is open. */
  live: boolean;
  /** The instance shown, e.g. MAIN or MAIN.COUNTER1; null for a function or an FB with none chosen. */
  instance: string | null;
  showValues: boolean;
  setShowValues(show: boolean): void;
  view?: StOnlineView & { marks: readonly InlineMark[] };
  /** The context menu and value prompt, when open. */
  overlay: ReactNode;
  /** The halted call's own variables show (read only). */
  callShown: boolean;
}

/** A METHOD or property accessor of the function block whose body the editor shows. */
export interface StMember {
  /** As declared: its result variable has this name. */
  name: string;
  /** Its declarations: its own variables, which hide the FB's. */
  declarations: string;
  /** The engine's POU of a method (`FB.M`) or accessor (`FB.P.GET`), where the scan halts and the call stack names it. */
  call: string;
  /** The body's file (methods/members.ts memberFile), naming the subscription. */
  file: string;
}

const NO_NAMES: ReadonlySet<string> = new Set();

export function useStOnline(pou: Pou, body: string, scope: Scope, member?: StMember): StOnline {
  const phase = useOnline((s) => s.phase);
  const monitor = useOnline((s) => s.monitor);
  const prepared = useOnline((s) => s.prepared);
  const [showValues, setShowValues] = useState(true);
  const [menu, setMenu] = useState<{ occurrence: Occurrence; x: number; y: number } | null>(null);
  const [prompt, setPrompt] = useState<{ occurrence: Occurrence; action: "write" | "force" | "prepare" } | null>(null);
  const live = phase !== "offline";
  const at = haltedAt(monitor);
  const here = (member?.call ?? pou.name).toUpperCase();
  const haltedHere = at?.instance && at.pou.toUpperCase() === here ? at.instance.toUpperCase() : null;
  const shown = useShownInstance(pou);
  const instance = haltedHere ?? shown;
  const key = `st:${member?.file ?? pou.name}`;
  const [ownName, ownDeclarations] = [member?.name, member?.declarations];
  const hidden = useMemo(
    () => (ownName === undefined ? NO_NAMES : ownNames(ownName, ownDeclarations ?? "")),
    [ownName, ownDeclarations],
  );

  const occurrences = useMemo(
    () => (live && instance ? variableOccurrences(body, scope, instance, hidden) : []),
    [live, instance, body, scope, hidden],
  );
  const paths = useMemo(() => [...new Set(occurrences.map((o) => o.path))], [occurrences]);
  const il = pou.language === "il";
  useEffect(() => {
    // IL: every probe of the instance - the accumulator after each line (`L<line>:<type>`)
    const elements = il && instance ? [{ pou_instance: instance, ids: null }] : [];
    onlineStore.getState().subscribe(key, live && (paths.length || elements.length) ? { paths, elements } : null);
  }, [key, live, paths, il, instance]);
  useEffect(() => () => onlineStore.getState().subscribe(key, null), [key]);

  // An element `a[i]` acts on the element `i` names when the command runs.
  const commands = useMemo(
    () =>
      operandCommands(
        (text) => {
          const o = occurrences.find((c) => c.text === text);
          return o ? concretePath(o, onlineStore.getState().monitor.values) : null;
        },
        (text) => occurrences.find((c) => c.text === text)?.type,
      ),
    [occurrences],
  );
  const marks = useMemo(() => {
    if (!showValues) return [];
    const values = inlineMarks(occurrences, monitor, prepared);
    if (!il || !instance) return values;
    const accumulators = accumulatorMarks(body, monitor, instance).map((m) => ({ ...m, accumulator: true }));
    return [...values, ...accumulators].sort((a, b) => a.pos - b.pos);
  }, [showValues, occurrences, monitor, prepared, il, instance, body]);
  const view = useMemo(
    () =>
      live && instance
        ? {
            occurrences,
            marks,
            describe: (o: Occurrence) => describe(o, monitor, prepared),
            onMenu: (occurrence: Occurrence, x: number, y: number) => setMenu({ occurrence, x, y }),
            onPrepare: (occurrence: Occurrence) => {
              if (!commands.prepare(occurrence.text)) setPrompt({ occurrence, action: "prepare" });
            },
          }
        : undefined,
    [live, instance, occurrences, marks, monitor, prepared, commands],
  );

  const overlay = (
    <>
      {menu && view ? (
        // The menu is placed at the click's viewport coordinates.
        <div style={{ position: "fixed", left: 0, top: 0, zIndex: 30 }}>
          <MenuList
            x={menu.x}
            y={menu.y}
            groups={[
              onlineOperandItems(
                menu.occurrence.text,
                commands,
                (action) => setPrompt({ occurrence: menu.occurrence, action }),
                menu.occurrence.type.toUpperCase() === "BOOL",
              ),
            ]}
            onClose={() => setMenu(null)}
          />
        </div>
      ) : null}
      {prompt && view ? (
        <OperandValuePrompt
          request={{ operand: prompt.occurrence.text, action: prompt.action }}
          commands={commands}
          onDone={() => setPrompt(null)}
        />
      ) : null}
    </>
  );
  const call = useCallValues(member ? member.call : pou.kind === "function" ? pou.name : null, body);
  const called = call && !showValues ? { ...call, marks: [] } : call;
  return { live, instance, showValues, setShowValues, view: withCall(view, called), overlay, callShown: !!call };
}
