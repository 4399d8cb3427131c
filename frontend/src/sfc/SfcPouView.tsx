// An SFC POU in the workspace: the chart editor with the live check of the working copy (POST /api/check),
// online mode (active steps and actions, step times, every condition, forces on step flags through the
// watch list and the step's context), breakpoints on steps and transitions, "step to the next transition",
// and the POU's actions and named transitions opened in the ST, IL, LD or FBD editor (their lines and networks
// take breakpoints too, with the part they are in; an IL part shows its accumulator after each line online).
import { useCallback, useEffect, useMemo, useState, type ReactNode } from "react";
import type { Diagnostic, LibraryEntry, SymbolInfo } from "../generated/api";
import type { FbdBody, LdBody, Pou, SfcAction, SfcNamedTransition } from "../generated/api";
import { debugStore, useDebug } from "../debug/store";
import { FbdEditor } from "../fbd/editor/FbdEditor";
import { keysOf } from "../keys/keymap";
import { LdEditor } from "../ld/editor/LdEditor";
import { historyOf, record, type History } from "../store/history";
import { operandCommands } from "../online/operandCommands";
import { onlineStore, useOnline } from "../online/store";
import { useLdOnline } from "../ld/useLdOnline";
import { onlineReadOnly, useShownInstance } from "../online/editorOnline";
import { useFbdOnline } from "../fbd/useFbdOnline";
import { usePanels } from "../store/panels";
import { useWorkspace } from "../store/project";
import { StEditor, type StEditorProps } from "../st/StEditor";
import { accumulatorMarks } from "../st/ilOnline";
import { IL_OPERATOR_COMPLETIONS } from "../st/ilLanguage";
import { useStAssist } from "../st/useStAssist";
import { useOperandMembers } from "../st/useOperandMembers";
import type { MembersAfter } from "../ui/OperandEditor";
import { actionChartOf, type ActionChartBody, type SfcBody } from "./model";
import { bindSfc, sfcOnlineView } from "./online";
import { setPartBody } from "./ops";
import { SfcEditor, type SfcPart } from "./SfcEditor";

const partPath = (part: SfcPart) => `${part.kind === "action" ? "actions" : "transitions"}/${part.name}`;

export function SfcPouView({
  pou,
  history,
  onlineActions,
}: {
  pou: Pou;
  history: History<SfcBody>;
  onlineActions: ReactNode;
}) {
  const name = pou.name;
  const setHistory = useWorkspace((s) => s.setSfcHistory);
  const table = useWorkspace((s) => s.symbols[name]);
  const body = history.present;
  const { diagnostics: checked, completions } = useStAssist(pou);
  const [part, setPart] = useState<SfcPart | null>(null);
  const diagnostics = useMemo(
    () => checked.filter((d) => (d.pou ?? "").toUpperCase() === name.toUpperCase()),
    [checked, name],
  );

  // The chart shown: the POU's, or the chart of an action written in SFC (edited as a body of its own whose
  // actions and named transitions are the POU's; its edits are written back into the action).
  const sfcAction =
    part?.kind === "action" ? body.actions?.find((a) => a.name === part.name && a.language === "sfc") : undefined;
  const [innerHistory, setInnerHistory] = useState<History<SfcBody> | null>(null);
  const chartHistory = useMemo(() => {
    if (!sfcAction) return history;
    if (innerHistory && innerHistory.present.chart === sfcAction.body) return innerHistory;
    const inner: ActionChartBody = { ...body, chart: sfcAction.body as SfcBody["chart"], enclosing: body.chart };
    return historyOf<SfcBody>(inner);
  }, [sfcAction, innerHistory, history, body]);
  const shown = chartHistory.present;
  const onChartChange = (h: History<SfcBody>) => {
    if (!sfcAction) return setHistory(name, h);
    setInnerHistory(h);
    setHistory(name, record(history, withActionChart(body, h.present, sfcAction.name)));
  };
  const chartFile = sfcAction ? `${name}/actions/${sfcAction.name}` : `${name}/chart`;
  const chartDiagnostics = useMemo(
    () =>
      diagnostics.filter((d) =>
        sfcAction
          ? d.file?.toUpperCase() === chartFile.toUpperCase()
          : !d.file || d.file.toUpperCase() === chartFile.toUpperCase(),
      ),
    [diagnostics, sfcAction, chartFile],
  );
  const variables = useMemo(
    () => (table?.symbols ?? []).filter((s) => s.type.toUpperCase() === "BOOL").map((s) => s.name),
    [table],
  );

  // online
  const phase = useOnline((s) => s.phase);
  const monitor = useOnline((s) => s.monitor);
  const instance = useShownInstance(pou);
  const live = phase !== "offline";
  const key = `sfc:${name}`;
  const binding = useMemo(() => (instance ? bindSfc(shown, instance) : null), [shown, instance]);
  useEffect(() => {
    onlineStore
      .getState()
      .subscribe(key, live && binding ? { paths: binding.paths, elements: binding.elements } : null);
  }, [key, live, binding]);
  useEffect(() => () => onlineStore.getState().subscribe(key, null), [key]);
  const online = useMemo(
    () => (live && binding ? sfcOnlineView(monitor, binding) : undefined),
    [live, binding, monitor],
  );
  const readOnly = onlineReadOnly(pou, live, instance);
  const flagCommands = useMemo(
    () =>
      live && instance
        ? operandCommands(
            (operand) => `${instance}.${operand}`,
            () => "BOOL",
          )
        : undefined,
    [live, instance],
  );

  // debugging
  const breakpoints = useDebug((s) => s.breakpoints);
  const at = useOnline((s) => (s.monitor.state === "halted" ? s.monitor.at : null));
  const upper = name.toUpperCase();
  const marks = useMemo(() => {
    const mine = breakpoints.filter((b) => b.pou.toUpperCase() === upper && !b.body);
    return {
      breakpoints: new Set(mine.flatMap((b) => ("element" in b ? [b.element] : []))),
      halted: at && at.pou.toUpperCase() === upper && !at.body ? (at.element ?? null) : null,
    };
  }, [breakpoints, at, upper]);
  // A place revealed in this POU (the Breakpoints panel's "Show in the editor", a diagnostic, a halt: the debug
  // bar reveals it) opens the action or named transition it is in, or the chart (an element of an action's chart
  // opens that action).
  const focus = usePanels((s) => (s.focus?.pou.toUpperCase() === upper ? s.focus : null));
  // (null at first: "Show in the editor" opens the POU and reveals the place at once, before this view is made)
  const [focusSeen, setFocusSeen] = useState<typeof focus>(null);
  if (focus !== focusSeen) {
    setFocusSeen(focus);
    if (focus) {
      const target = focus.body ?? (focus.element ? actionChartOf(history.present, focus.element) : null);
      const [kind, partName] = target ? target.split("/", 2) : [];
      setPart(target ? { kind: kind === "actions" ? "action" : "transition", name: partName! } : null);
    }
  }

  // The server steps to a transition from a stopped or halted scan (a running one is stopped first).
  const running = useOnline((s) => s.monitor.state === "running");
  const stepToTransition = live ? (
    <button
      type="button"
      disabled={running}
      title={
        running
          ? "Stop the simulation first: then scans run until an SFC transition fires"
          : `Run scans until an SFC transition fires, then halt there (${keysOf("app", "step-transition")})`
      }
      onClick={() => debugStore.getState().step("transition")}
    >
      Step to next transition
    </button>
  ) : null;

  if (part && !sfcAction) {
    const item =
      part.kind === "action"
        ? body.actions?.find((a) => a.name === part.name)
        : body.transitions?.find((t) => t.name === part.name);
    return (
      <PartFrame
        title={
          <>
            {part.kind === "action" ? "Action" : "Transition"} <strong>{part.name}</strong>
            {item ? ` (${(item.language ?? "st").toUpperCase()})` : ""}
          </>
        }
        extra={stepToTransition}
        onClose={() => setPart(null)}
      >
        {item ? (
          <PartEditor
            pou={pou}
            part={part}
            item={item}
            diagnostics={diagnostics}
            completions={completions}
            readOnly={readOnly}
            focusLine={focus?.body && focus.line != null ? { line: focus.line, seq: focus.seq } : null}
            onChange={(content) => setHistory(name, record(history, setPartBody(body, part.kind, part.name, content)))}
          />
        ) : (
          <p className="placeholder">
            {part.name} is no longer part of {name}.
          </p>
        )}
      </PartFrame>
    );
  }
  const editor = (
    <SfcEditor
      key={chartFile}
      history={chartHistory}
      onHistoryChange={onChartChange}
      variables={variables}
      diagnostics={chartDiagnostics}
      online={online}
      readOnly={readOnly}
      readOnlyActions={readOnly ? onlineActions : undefined}
      onOpen={setPart}
      focus={focus?.element && !focus.body ? { element: focus.element, seq: focus.seq } : null}
      debugging={{ marks, toggle: (element) => debugStore.getState().toggle({ pou: name, element }) }}
      toolbarExtra={stepToTransition}
      onlineActions={flagCommands}
    />
  );
  if (!sfcAction) return editor;
  return (
    <PartFrame
      title={
        <>
          Action <strong>{sfcAction.name}</strong> (SFC)
        </>
      }
      onClose={() => setPart(null)}
    >
      {editor}
    </PartFrame>
  );
}

/** An action or named transition opened: the bar back to the chart with what is open, then its editor. */
function PartFrame(props: { title: ReactNode; extra?: ReactNode; onClose(): void; children: ReactNode }) {
  return (
    <div className="sfc-pou">
      <div className="sfc-part-bar" role="navigation" aria-label="SFC parts">
        <button type="button" onClick={props.onClose}>
          Chart
        </button>
        <span>{props.title}</span>
        {props.extra}
      </div>
      <div className="sfc-part">{props.children}</div>
    </div>
  );
}

/** The POU's body `outer` after an edit of an action's chart: `edited` is the action's chart as a body of its own
 * (its actions and named transitions are the POU's, perhaps edited too). */
function withActionChart(outer: SfcBody, edited: SfcBody, action: string): SfcBody {
  const chart = edited.chart ?? { elements: [] };
  return {
    ...outer,
    actions: (edited.actions ?? []).map((a) => (a.name === action ? { ...a, body: chart } : a)),
    transitions: edited.transitions,
  };
}

function PartEditor(props: {
  pou: Pou;
  part: SfcPart;
  item: SfcAction | SfcNamedTransition;
  diagnostics: Diagnostic[];
  completions: ReturnType<typeof useStAssist>["completions"];
  readOnly: string | null;
  focusLine: { line: number; seq: number } | null;
  onChange(content: SfcAction["body"]): void;
}) {
  const { pou, part, item } = props;
  const body = partPath(part);
  const file = `${pou.name}/${body}`;
  const mine = useMemo(
    () => props.diagnostics.filter((d) => d.file?.toUpperCase() === file.toUpperCase()),
    [props.diagnostics, file],
  );
  const breakpoints = useDebug((s) => s.breakpoints);
  const at = useOnline((s) => (s.monitor.state === "halted" ? s.monitor.at : null));
  const upper = pou.name.toUpperCase();
  const inPart = (b: { pou: string; body?: string }) => b.pou.toUpperCase() === upper && b.body === body;
  const library = useWorkspace((s) => s.library);
  const table = useWorkspace((s) => s.symbols[pou.name]);
  const symbols = useMemo(() => (table ? [...table.symbols, ...table.globals] : []), [table]);
  const members = useOperandMembers(symbols);
  const [histories, setHistories] = useState<Record<string, History<LdBody | FbdBody>>>({});
  const il = item.language === "il";
  const text = typeof item.body === "string" ? item.body : "";
  const ilOnline = useIlPartOnline(pou, body, il ? text : null);
  const completions = useMemo(
    () =>
      il
        ? { ...props.completions, options: [...IL_OPERATOR_COMPLETIONS, ...props.completions.options] }
        : props.completions,
    [il, props.completions],
  );
  if (typeof item.body === "string" || item.body === undefined) {
    const lines = breakpoints.flatMap((b) => ("line" in b && inPart(b) ? [b.line] : []));
    return (
      <StEditor
        key={file}
        text={text}
        onChange={(text) => props.onChange(text)}
        file={file}
        diagnostics={mine}
        completions={completions}
        readOnly={props.readOnly}
        label={`${pou.name} ${part.kind} ${part.name}`}
        language={il ? "il" : "st"}
        online={ilOnline}
        focusLine={props.focusLine}
        debug={{
          breakpoints: lines,
          halted: at && inPart({ pou: at.pou, body: at.body ?? undefined }) && at.line != null ? at.line : null,
          onToggle: (line) => debugStore.getState().toggle({ pou: pou.name, body, line }),
        }}
      />
    );
  }
  const diagram = {
    pou,
    body,
    file,
    diagnostics: mine,
    library,
    symbols: table ? symbols : null,
    members,
    readOnly: props.readOnly,
    histories,
    setHistories,
    onChange: props.onChange,
  };
  if ("networks" in item.body && kindOfDiagram(item) === "ld") {
    const networks = breakpoints.flatMap((b) => ("network" in b && inPart(b) ? [[b.network, true] as const] : []));
    return (
      <LdPart
        {...diagram}
        content={item.body as LdBody}
        breakpoints={Object.fromEntries(networks)}
        halted={at && at.body === body && at.network ? at.network : null}
      />
    );
  }
  return (
    <FbdPart
      {...diagram}
      content={item.body as FbdBody}
      breakpoints={new Set(breakpoints.flatMap((b) => ("network" in b && inPart(b) ? [b.network] : [])))}
      halted={at && at.body === body ? { network: at.network ?? null, element: null } : null}
    />
  );
}

/** Online, an IL action or transition (`text`; null: not IL) shows the accumulator after each line, from the
 * probes of its part (`body`, "actions/Count") in the POU's instance, as an IL POU does (ilOnline.ts). */
function useIlPartOnline(pou: Pou, body: string, text: string | null): StEditorProps["online"] {
  const live = useOnline((s) => s.phase !== "offline");
  const monitor = useOnline((s) => s.monitor);
  const instance = useShownInstance(pou);
  const key = `il:${pou.name}/${body}`;
  const on = live && instance !== null && text !== null;
  useEffect(() => {
    onlineStore
      .getState()
      .subscribe(key, on ? { paths: [], elements: [{ pou_instance: instance!, ids: null }] } : null);
  }, [key, on, instance]);
  useEffect(() => () => onlineStore.getState().subscribe(key, null), [key]);
  return useMemo(() => {
    if (!on) return undefined;
    const marks = accumulatorMarks(text!, monitor, instance!, body).map((m) => ({ ...m, accumulator: true }));
    return { occurrences: [], marks, describe: () => "", onMenu: () => undefined, onPrepare: () => undefined };
  }, [on, text, monitor, instance, body]);
}

/** What the LD and FBD editors of a part share: where it is, its checks and its undo history. */
interface DiagramPart {
  pou: Pou;
  /** "actions/Fill": breakpoints, halts and probes name the part so. */
  body: string;
  file: string;
  diagnostics: Diagnostic[];
  library: LibraryEntry[];
  symbols: SymbolInfo[] | null;
  members: MembersAfter;
  readOnly: string | null;
  histories: Record<string, History<LdBody | FbdBody>>;
  setHistories(
    update: (all: Record<string, History<LdBody | FbdBody>>) => Record<string, History<LdBody | FbdBody>>,
  ): void;
  onChange(content: SfcAction["body"]): void;
}

/** An LD action or transition, online with the power of its own probes. */
function LdPart(props: DiagramPart & { content: LdBody; breakpoints: Record<string, boolean>; halted: string | null }) {
  const { pou, body, file, content } = props;
  const history = (props.histories[file] as History<LdBody> | undefined) ?? historyOf(content);
  const present = history.present === content ? history : historyOf(content);
  const live = useLdOnline(pou, content, props.symbols, props.library, body);
  return (
    <LdEditor
      key={file}
      history={present}
      onHistoryChange={(h) => {
        props.setHistories((all) => ({ ...all, [file]: h }));
        props.onChange(h.present);
      }}
      library={props.library}
      symbols={props.symbols ?? []}
      members={props.members}
      diagnostics={props.diagnostics}
      readOnly={props.readOnly}
      online={live.online}
      onlineActions={live.actions}
      onVisibleChange={live.onVisibleChange}
      debugging={{
        marks: {
          networks: props.breakpoints,
          halted: props.halted ? { network: props.halted, element: null } : null,
        },
        toggle: (target) => {
          if ("network" in target) debugStore.getState().toggle({ pou: pou.name, body, network: target.network });
        },
      }}
    />
  );
}

/** An FBD action or transition, online with the values of its own probes. */
function FbdPart(
  props: DiagramPart & {
    content: FbdBody;
    breakpoints: ReadonlySet<string>;
    halted: { network: string | null; element: null } | null;
  },
) {
  const { pou, body, file, content, library } = props;
  const history = (props.histories[file] as History<FbdBody> | undefined) ?? historyOf(content);
  const present = history.present === content ? history : historyOf(content);
  const byName = useMemo(() => new Map(library.map((e) => [e.name.toUpperCase(), e])), [library]);
  const lookup = useCallback((call: string) => byName.get(call.toUpperCase()), [byName]);
  const live = useFbdOnline(pou, content, lookup, props.symbols, body);
  return (
    <FbdEditor
      key={file}
      history={present}
      onHistoryChange={(h) => {
        props.setHistories((all) => ({ ...all, [file]: h }));
        props.onChange(h.present);
      }}
      library={library}
      symbols={props.symbols ?? []}
      members={props.members}
      diagnostics={props.diagnostics}
      readOnly={props.readOnly}
      online={live.online}
      onlineActions={live.actions}
      onVisibleChange={live.onVisibleChange}
      onFeedbackChange={live.onFeedbackChange}
      debug={{
        networks: props.breakpoints,
        elements: new Set(),
        halted: props.halted,
        toggle: (bp) => {
          if ("network" in bp) debugStore.getState().toggle({ pou: pou.name, body, network: bp.network });
        },
      }}
    />
  );
}

const kindOfDiagram = (item: SfcAction | SfcNamedTransition) => item.language ?? "st";
