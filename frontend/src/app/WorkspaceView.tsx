// The open project: project tree (POUs by kind with their language, types, globals, tasks, test
// files), tabs of open POUs and test files with unsaved marks, the LD and FBD editors (online when a
// simulation runs, tinted by the tests' coverage), the ST editor of test files, the simulation
// toolbar, the bottom panels, Save (Ctrl+S) and the dialog for a save conflict (reload theirs or
// overwrite deliberately).
import {
  Fragment,
  lazy,
  Suspense,
  useCallback,
  useEffect,
  useMemo,
  useState,
  type CSSProperties,
  type FormEvent,
  type ReactNode,
} from "react";
import type { Diagnostic } from "../generated/api";
import type { LdBody, Pou, Project, TestFile } from "../generated/api";
import { LdEditor } from "../ld/editor/LdEditor";
import type { History } from "../store/history";
import { operandPath, setGlobalListNames } from "../online/monitor";
import { onlineStore, useOnline } from "../online/store";
import { SimulationBar } from "../online/SimulationBar";
import { HistoryBanner } from "../online/HistoryBar";
import { useLdOnline } from "../ld/useLdOnline";
import { instanceOf } from "../online/editorOnline";
import { BottomPanels } from "../panels/BottomPanels";
import { focusOf, panelOf, panelsStore, usePanels } from "../store/panels";
import { parseDeclarations } from "../iec/declarations";
import { isTestPath, pouOf, symbolsOf, testPath, useWorkspace, workspaceStore } from "../store/project";
import { coverageMarks, coverageOf } from "../tests/coverage";
import { testsStore, useTests } from "../tests/store";
import { runsOf } from "../store/tasks";
import { useDiagramPou } from "../ld/useDiagramPou";
import { TaskActions } from "../tree/TaskActions";
import { TypesInTree } from "../tree/TypeActions";
import { followBreakpoints } from "./followBreakpoints";
import { partAt, elementText as sfcElementText, type SfcBody } from "../sfc/model";
import { ExportMenu } from "../interchange/ExportMenu";
import { Keyboard, PanelBottomClose, PanelBottomOpen, PanelLeftClose, PanelLeftOpen, Save } from "lucide-react";
import { SidePanel } from "../ui/SidePanel";
import { ToolButton } from "../ui/ToolButton";
import { ImportPlcopen } from "../interchange/ImportPlcopen";
import { appStore } from "../store/workspace";
import { DebugBar } from "../debug/DebugBar";
import { describeHalt } from "../debug/breakpoints";
import { useLdDebugging } from "../debug/ldDebugging";
import { revealPlace } from "../debug/reveal";
import { debugStore } from "../debug/store";
import { isShellTab, PanelsTree, revealWidget, tabLabel } from "../hmi/shell";
import { ViewBoundary } from "../ui/ViewBoundary";
import { useAppKeys } from "./useAppKeys";
import { ShortcutHelp } from "../keys/ShortcutHelp";
import { keysOf } from "../keys/keymap";
import { VariablesView } from "./VariablesView";
import { InstancePicker, OnlineActions } from "./InstancePicker";
import { LOADING } from "./lazy";
import { useHidden, useStoredSize } from "../store/layout";
import { PouActions } from "../tree/PouActions";
import { KindPicker } from "../tree/kinds";
import { TestFileActions } from "../tests/TestFileActions";
import { isProjectPart, PART_LABELS, PROJECT_PARTS, type ProjectPart } from "../store/parts";
import { gvlNameOf, isGvlTab, sharedListVariables } from "../store/gvls";
import { GvlsTree } from "../tree/GvlsTree";
import { PouMembers } from "../tree/PouMembers";
import { typeRows } from "../store/types";
import { keepSession, restoreSession, type SessionStores } from "./session";
import { traceStore } from "../trace/store";
import { FormError } from "../ui/FormError";

// Loaded on first use, each in its own chunk: the ST views (CodeMirror) and the FBD editor (@xyflow).
const StPouView = lazy(() => import("./StViews").then((m) => ({ default: m.StPouView })));
const ActionsView = lazy(() => import("./ActionsView").then((m) => ({ default: m.ActionsView })));
const TestFileView = lazy(() => import("./StViews").then((m) => ({ default: m.TestFileView })));
const FbdPouView = lazy(() => import("../fbd/FbdPouView").then((m) => ({ default: m.FbdPouView })));
const ShellTab = lazy(() => import("../hmi/ShellTab").then((m) => ({ default: m.ShellTab })));
const GlobalsView = lazy(() => import("./ProjectParts").then((m) => ({ default: m.GlobalsView })));
const GvlView = lazy(() => import("./ProjectParts").then((m) => ({ default: m.GvlView })));
const TypesView = lazy(() => import("./ProjectParts").then((m) => ({ default: m.TypesView })));
const TasksView = lazy(() => import("./ProjectParts").then((m) => ({ default: m.TasksView })));
const LibrariesView = lazy(() => import("../libraries/LibrariesView").then((m) => ({ default: m.LibrariesView })));
const MethodsView = lazy(() => import("../methods/MethodsView").then((m) => ({ default: m.MethodsView })));
const PouDeclarations = lazy(() => import("./PouDeclarations").then((m) => ({ default: m.PouDeclarations })));
const StView = lazy(() => import("../stview/StView").then((m) => ({ default: m.StView })));
const SfcPouView = lazy(() => import("../sfc/SfcPouView").then((m) => ({ default: m.SfcPouView })));

/** The stores a project's session (app/session.ts) is kept from. */
const SESSION_STORES: SessionStores = { workspace: workspaceStore, online: onlineStore, trace: traceStore };

const KINDS: { kind: Pou["kind"]; title: string }[] = [
  { kind: "program", title: "Programs" },
  { kind: "function_block", title: "Function blocks" },
  { kind: "function", title: "Functions" },
  { kind: "plant", title: "Plants" },
];
const LANGUAGE = { st: "ST", ld: "LD", fbd: "FBD", cfc: "CFC", il: "IL", sfc: "SFC" } as const;
/** Languages whose body is text, edited in the text editor (docs/il.md). */
const TEXT_LANGUAGES: readonly Pou["language"][] = ["st", "il"];

export const formatTime = (iso: string | null | undefined): string => {
  if (!iso) return "an unknown time";
  const date = new Date(iso);
  return Number.isNaN(date.getTime()) ? iso : date.toLocaleString();
};

/**
 * A "New ..." button that opens a small form: a name (and `fields`); `create` adds the item to the working
 * copy and returns the reason it refused the name, or null (the form closes).
 */
function NewItemForm({
  title,
  nameLabel,
  create,
  onOpen,
  children,
}: {
  title: string;
  nameLabel: string;
  create(name: string): string | null;
  /** Called as the form opens (to start its fields afresh). */
  onOpen?: () => void;
  children?: ReactNode;
}) {
  const [open, setOpen] = useState(false);
  const [name, setName] = useState("");
  const [error, setError] = useState<string | null>(null);
  if (!open) {
    return (
      <button
        type="button"
        className="new-pou-button"
        onClick={() => {
          onOpen?.();
          setOpen(true);
        }}
      >
        {title}
      </button>
    );
  }
  const submit = (e: FormEvent) => {
    e.preventDefault();
    const problem = create(name);
    setError(problem);
    if (!problem) {
      setOpen(false);
      setName("");
    }
  };
  return (
    <form className="new-pou" aria-label={title} onSubmit={submit}>
      <input
        aria-label={nameLabel}
        autoFocus
        value={name}
        onChange={(e) => setName(e.target.value)}
        placeholder="name"
        spellCheck={false}
      />
      {children}
      <button type="submit">Create</button>
      <button type="button" onClick={() => setOpen(false)}>
        Cancel
      </button>
      <FormError error={error} />
    </form>
  );
}

/** "New POU": name, kind (each time from "program", with what the kind is) and language; the POU joins
 * the working copy (saved with the project). */
function NewPou() {
  const addPou = useWorkspace((s) => s.addPou);
  const [kind, setKind] = useState<Pou["kind"]>("program");
  const [language, setLanguage] = useState<Pou["language"]>("ld");
  return (
    <NewItemForm
      title="New POU"
      nameLabel="POU name"
      create={(name) => addPou(name, kind, language)}
      onOpen={() => setKind("program")}
    >
      <KindPicker kind={kind} onChange={setKind} />
      <select
        aria-label="POU language"
        value={language}
        onChange={(e) => setLanguage(e.target.value as Pou["language"])}
      >
        {Object.entries(LANGUAGE).map(([value, label]) => (
          <option key={value} value={value}>
            {label}
          </option>
        ))}
      </select>
    </NewItemForm>
  );
}

/** "New test file": a name; the file joins the working copy with a first test and opens. */
function NewTestFile() {
  const addTestFile = useWorkspace((s) => s.addTestFile);
  return <NewItemForm title="New test file" nameLabel="Test file name" create={addTestFile} />;
}

const NO_TESTS: readonly TestFile[] = [];

/** The test files (tests/<name>.st) of the working copy, each with its outcome of the last run. */
function TestFilesTree() {
  const tests = useWorkspace((s) => s.project?.tests ?? NO_TESTS);
  const changed = useWorkspace((s) => s.changed);
  const active = useWorkspace((s) => s.active);
  const openPou = useWorkspace((s) => s.openPou);
  const results = useTests((s) => s.results);
  return (
    <section>
      <h3>Tests</h3>
      {tests.length ? (
        <ul>
          {tests.map((t) => {
            const path = testPath(t.name);
            const mine = Object.values(results).filter((r) => r.file === path);
            const failed = mine.filter((r) => r.outcome === "failed").length;
            return (
              <li key={t.name} className="tree-row">
                <button
                  type="button"
                  className="tree-item"
                  aria-current={active === path ? "true" : undefined}
                  onClick={() => openPou(path)}
                >
                  <span className="tree-name">{path}</span>
                  {mine.length ? (
                    <span className={`test-badge${failed ? " test-badge-failed" : ""}`}>
                      {failed ? `${failed} failed` : "passed"}
                    </span>
                  ) : null}
                  {changed.includes(path) ? (
                    <span className="unsaved" aria-label="unsaved changes">
                      ●
                    </span>
                  ) : null}
                </button>
                <TestFileActions name={t.name} />
              </li>
            );
          })}
        </ul>
      ) : (
        <p className="tree-empty">none</p>
      )}
      <NewTestFile />
    </section>
  );
}

/** What the tree says of a project part: how many types, globals, tasks it has. */
function partSummary(project: Project, part: ProjectPart): string {
  if (part === "part:tasks") return project.tasks?.length ? `${project.tasks.length}` : "default";
  if (part === "part:libraries") {
    const count = project.libraries?.length ? `${project.libraries.length}` : "none";
    return project.typing === "codesys" ? `${count}, CODESYS typing` : count;
  }
  if (part === "part:types") return `${typeRows(project.types ?? "").length}`;
  const parsed = parseDeclarations(project.globals ?? "");
  return parsed.ok ? `${parsed.rows.length}` : "";
}

function ProjectTree() {
  const project = useWorkspace((s) => s.project);
  const changed = useWorkspace((s) => s.changed);
  const active = useWorkspace((s) => s.active);
  const openPou = useWorkspace((s) => s.openPou);
  if (!project) return null;
  const pous = project.pous ?? [];
  return (
    <nav className="tree" aria-label="Project tree">
      <NewPou />
      {KINDS.map(({ kind, title }) => {
        const group = pous.filter((p) => p.kind === kind);
        return (
          <section key={kind}>
            <h3>{title}</h3>
            {group.length ? (
              <ul>
                {group.map((p) => (
                  <Fragment key={p.name}>
                    <li className="tree-row">
                      <button
                        type="button"
                        className="tree-item"
                        aria-current={active === p.name ? "true" : undefined}
                        onClick={() => openPou(p.name)}
                      >
                        <span className="tree-name">{p.name}</span>
                        <span className={`lang lang-${p.language}`}>{LANGUAGE[p.language]}</span>
                        {changed.includes(p.name) ? (
                          <span className="unsaved" aria-label="unsaved changes">
                            ●
                          </span>
                        ) : null}
                      </button>
                      <PouActions pou={p} />
                    </li>
                    <PouMembers
                      pou={p}
                      open={(member) => {
                        openPou(p.name);
                        if (member) panelsStore.getState().reveal({ pou: p.name, member });
                      }}
                    />
                  </Fragment>
                ))}
              </ul>
            ) : (
              <p className="tree-empty">none</p>
            )}
          </section>
        );
      })}
      <PanelsTree />
      <section>
        <h3>Project</h3>
        <ul>
          {PROJECT_PARTS.map((part) => (
            <li key={part}>
              <button
                type="button"
                className="tree-item"
                aria-current={active === part ? "true" : undefined}
                onClick={() => openPou(part)}
              >
                <span className="tree-name">{PART_LABELS[part]}</span>
                <span className="tree-meta">{partSummary(project, part)}</span>
                {changed.includes(part) ? (
                  <span className="unsaved" aria-label="unsaved changes">
                    ●
                  </span>
                ) : null}
              </button>
              {part === "part:types" ? <TypesInTree text={project.types ?? ""} /> : null}
            </li>
          ))}
        </ul>
      </section>
      <GvlsTree />
      <TasksSection project={project} />
      <TestFilesTree />
    </nav>
  );
}

/** The tasks and the program instances they run: the project's own, or its configuration's resources. */
function TasksSection({ project }: { project: Project }) {
  const runs = runsOf(project);
  const empty = project.configuration
    ? "none (an empty configuration runs nothing)"
    : "none (the default task runs every program)";
  return (
    <section aria-label="Tasks">
      <h3>{runs.configuration ? `Configuration ${runs.configuration}` : "Tasks"}</h3>
      {runs.resources.length ? (
        runs.resources.map((resource, index) => (
          <div key={resource.name ?? index} className="tree-resource">
            {resource.name ? (
              <p className="tree-resource-name">
                Resource {resource.name}
                {resource.on ? <span className="tree-meta"> on {resource.on}</span> : null}
              </p>
            ) : null}
            <ul>
              {resource.tasks.map((t) => (
                <li key={t.name} className="tree-task tree-row">
                  <span>
                    {t.name}{" "}
                    <span className="tree-meta">
                      {t.timing} · priority {t.priority} · {t.instances.join(", ") || "no programs"}
                    </span>
                  </span>
                  <TaskActions task={t.name} />
                </li>
              ))}
              {resource.unscheduled.length ? (
                <li className="tree-task">
                  <span className="tree-meta">default task · {resource.unscheduled.join(", ")}</span>
                </li>
              ) : null}
            </ul>
          </div>
        ))
      ) : (
        <p className="tree-empty">{empty}</p>
      )}
    </section>
  );
}

function Tabs() {
  const tabs = useWorkspace((s) => s.tabs);
  const active = useWorkspace((s) => s.active);
  const changed = useWorkspace((s) => s.changed);
  const openPou = useWorkspace((s) => s.openPou);
  const closeTab = useWorkspace((s) => s.closeTab);
  return (
    <div className="tabs" role="tablist" aria-label="Open POUs">
      {tabs.map((pou) => (
        <div key={pou} className="tab" role="presentation">
          <button
            type="button"
            role="tab"
            aria-selected={pou === active}
            onClick={() => (isShellTab(pou) ? workspaceStore.getState().openTab(pou) : openPou(pou))}
          >
            {tabLabel(pou)}
            {changed.includes(pou) ? (
              <span className="unsaved" aria-label="unsaved changes">
                {" "}
                ●
              </span>
            ) : null}
          </button>
          <button
            type="button"
            className="tab-close"
            aria-label={`Close ${tabLabel(pou)}`}
            onClick={() => closeTab(pou)}
          >
            ×
          </button>
        </div>
      ))}
    </div>
  );
}

/** A POU by an IEC name in any case (the simulation reports halts with the compiled spelling). */
const pouNamed = (project: Project | null, name: string) =>
  project?.pous?.find((p) => p.name.toUpperCase() === name.toUpperCase());

function LdPouView({ pou, history }: { pou: Pou; history: History<LdBody> }) {
  const name = pou.name;
  const setLdHistory = useWorkspace((s) => s.setLdHistory);
  const { library, symbols, symbolsLoaded, diagnostics, members, focus, declare } = useDiagramPou(name);
  const live = useLdOnline(pou, history.present, symbolsLoaded ? symbols : null, library);
  const stepping = useLdDebugging(name, history.present);
  const covered = useTests((s) => coverageOf(s.coverage, name));
  const debugging = useMemo(
    () => (covered ? { ...stepping, marks: { ...stepping.marks, coverage: coverageMarks(covered) } } : stepping),
    [stepping, covered],
  );
  return (
    <LdEditor
      key={name}
      history={history}
      onHistoryChange={(h) => setLdHistory(name, h)}
      library={library}
      symbols={symbols}
      members={members}
      diagnostics={diagnostics}
      onDeclareVariable={declare}
      online={live.online}
      readOnly={live.readOnly}
      readOnlyActions={live.readOnly ? <OnlineActions pou={pou} /> : undefined}
      onlineActions={live.actions}
      onVisibleChange={live.onVisibleChange}
      focus={focus}
      debugging={debugging}
    />
  );
}

/** The project tree may be dragged between these widths (px). */
const TREE_MIN_PX = 160;
const TREE_MAX_PX = 480;

type PouMode = "body" | "declarations" | "variables" | "st" | "methods" | "actions";

function ProjectPartView({ part }: { part: ProjectPart }) {
  return (
    <ViewBoundary name={`The ${PART_LABELS[part]} editor`}>
      <Suspense fallback={LOADING}>
        {part === "part:globals" ? (
          <GlobalsView />
        ) : part === "part:types" ? (
          <TypesView />
        ) : part === "part:libraries" ? (
          <LibrariesView />
        ) : (
          <TasksView />
        )}
      </Suspense>
    </ViewBoundary>
  );
}

function GvlPartView({ name }: { name: string }) {
  return (
    <ViewBoundary name={`The global variable list ${name}`}>
      <Suspense fallback={LOADING}>
        <GvlView name={name} />
      </Suspense>
    </ViewBoundary>
  );
}

function PouView({ name }: { name: string }) {
  const pou = useWorkspace((s) => pouOf(s.project, name));
  const history = useWorkspace((s) => s.histories[name]);
  const fbdHistory = useWorkspace((s) => s.fbdHistories[name]);
  const sfcHistory = useWorkspace((s) => s.sfcHistories[name]);
  const project = useWorkspace((s) => s.name);
  const unsaved = useWorkspace((s) => s.changed.includes(name));
  const focus = usePanels((s) => (s.focus?.pou.toUpperCase() === name.toUpperCase() ? s.focus : null));
  // A diagnostic clicked for this POU, or a halt or call in it, shows the part it is in (as the request arrives,
  // while rendering; also when it opens the POU: a method's call from the call stack opens its FB's Methods tab).
  const modeOf = (f: typeof focus): PouMode =>
    f?.member ? "methods" : f?.part === "declarations" ? "declarations" : "body";
  const [mode, setMode] = useState<PouMode>(() => modeOf(focus));
  const phase = useOnline((s) => s.phase);
  const [focusSeen, setFocusSeen] = useState(focus);
  if (focus !== focusSeen) {
    setFocusSeen(focus);
    if (focus) setMode(modeOf(focus));
  }
  if (!pou || !project) return <p className="placeholder">{name} is no longer in this project.</p>;
  const modes: { id: PouMode; label: string }[] = [
    {
      id: "body",
      label: TEXT_LANGUAGES.includes(pou.language) ? "Body" : pou.language === "sfc" ? "Chart" : "Diagram",
    },
    { id: "declarations", label: "Declarations" },
    { id: "variables", label: "Variables" },
    ...(pou.kind === "function_block" || pou.kind === "program" ? [{ id: "methods" as const, label: "Methods" }] : []),
    ...(pou.language !== "st" ? [{ id: "st" as const, label: "View as ST" }] : []),
    ...(pou.kind === "function_block"
      ? [{ id: "actions" as const, label: `Actions (${pou.actions?.length ?? 0})` }]
      : []),
  ];
  let content;
  if (mode === "declarations") {
    const readOnly = phase === "offline" ? null : "Online: go offline to edit.";
    content = (
      <PouDeclarations
        pou={pou}
        readOnly={readOnly}
        focus={focus?.part === "declarations" && focus.line != null ? { line: focus.line, seq: focus.seq } : null}
      />
    );
  } else if (mode === "actions") {
    content = <ActionsView pou={pou} />;
  } else if (mode === "variables") {
    content = <VariablesView pou={pou} instancePicker={<InstancePicker pou={pou.name} />} />;
  } else if (mode === "methods") {
    content = (
      <MethodsView pou={pou} focus={focus?.member ? focus : null} instancePicker={<InstancePicker pou={pou.name} />} />
    );
  } else if (mode === "st") {
    content = (
      <StView
        project={project}
        pou={name}
        unsaved={unsaved}
        onRevealNetwork={(network) => panelsStore.getState().reveal({ pou: name, network })}
      />
    );
  } else if (TEXT_LANGUAGES.includes(pou.language)) {
    content = <StPouView pou={pou} />;
  } else if (pou.language === "ld" && history) {
    content = <LdPouView pou={pou} history={history} />;
  } else if ((pou.language === "fbd" || pou.language === "cfc") && fbdHistory) {
    content = <FbdPouView pou={pou} history={fbdHistory} onlineActions={<OnlineActions pou={pou} />} />;
  } else if (pou.language === "sfc" && sfcHistory) {
    content = <SfcPouView pou={pou} history={sfcHistory} onlineActions={<OnlineActions pou={pou} />} />;
  } else {
    content = (
      <p className="placeholder">
        The {LANGUAGE[pou.language]} editor is not built yet; {name} opens here once it is.
      </p>
    );
  }
  const area =
    mode === "declarations"
      ? `The declarations of ${name}`
      : mode === "variables"
        ? `The variables of ${name}`
        : mode === "methods"
          ? `The methods and properties of ${name}`
          : mode === "st"
            ? `The ST view of ${name}`
            : mode === "actions"
              ? `The actions of ${name}`
              : `The ${LANGUAGE[pou.language]} editor of ${name}`;
  return (
    <div className="pou-view">
      <div className="pou-modes" role="tablist" aria-label={`${name} views`}>
        {modes.map((m) => (
          <button key={m.id} type="button" role="tab" aria-selected={mode === m.id} onClick={() => setMode(m.id)}>
            {m.label}
          </button>
        ))}
      </div>
      <ViewBoundary key={mode} name={area} onReload={() => workspaceStore.getState().refreshPou(name)}>
        <Suspense fallback={LOADING}>{content}</Suspense>
      </ViewBoundary>
    </div>
  );
}

function ConflictDialog() {
  const conflict = useWorkspace((s) => s.conflict);
  const modified = useWorkspace((s) => s.modified);
  const save = useWorkspace((s) => s.save);
  const reload = useWorkspace((s) => s.reload);
  const dismiss = useWorkspace((s) => s.dismissConflict);
  if (!conflict) return null;
  return (
    <div className="ld-dialog-backdrop">
      <div className="ld-dialog conflict" role="alertdialog" aria-label="Save conflict">
        <h2>The project was changed elsewhere</h2>
        <p>
          Your changes are based on the version saved at <strong>{formatTime(modified)}</strong>. Since then another
          version was saved at <strong>{formatTime(conflict.current_modified)}</strong>.
        </p>
        <p className="conflict-detail">{conflict.message}</p>
        <div className="dialog-buttons">
          <button type="button" onClick={() => void reload()}>
            Reload the saved version (discard my changes)
          </button>
          <button type="button" onClick={() => void save(true)}>
            Overwrite with my version
          </button>
          <button type="button" onClick={dismiss}>
            Cancel
          </button>
        </div>
      </div>
    </div>
  );
}

export function WorkspaceView() {
  const status = useWorkspace((s) => s.status);
  const error = useWorkspace((s) => s.error);
  const name = useWorkspace((s) => s.name);
  const active = useWorkspace((s) => s.active);
  const changed = useWorkspace((s) => s.changed);
  const saving = useWorkspace((s) => s.saving);
  const saveError = useWorkspace((s) => s.saveError);
  const restoredAt = useWorkspace((s) => s.restoredAt);
  const save = useWorkspace((s) => s.save);
  const reload = useWorkspace((s) => s.reload);
  const project = useWorkspace((s) => s.project);
  const revision = useWorkspace((s) => s.revision);
  const panelsHeight = usePanels((s) => s.height);
  const undo = useWorkspace((s) => s.undo);
  const [treeHidden, toggleTree] = useHidden("tree");
  const [treeWidth, resizeTree] = useStoredSize("tree", TREE_MIN_PX, TREE_MAX_PX);
  const [panelsHidden, togglePanels] = useHidden("panels");
  const [help, setHelp] = useState(false);

  // Online paths name a list's variable by its own name (GVL_IO.bStart is BSTART) unless several lists declare it
  // (GVL_A.X): pathKey needs the lists and those names.
  const gvls = project?.gvls;
  useEffect(() => {
    setGlobalListNames(
      (gvls ?? []).map((g) => g.name),
      sharedListVariables(gvls ?? []),
    );
  }, [gvls]);

  // A save changes the project's POU count, revision and time: the project list shows them.
  useEffect(() => {
    if (revision) void appStore.getState().loadProjects();
  }, [revision]);

  const reveal = useCallback((d: Diagnostic) => {
    const target = focusOf(d);
    const panel = panelOf(d);
    if (!target) return void (panel && revealWidget(panel, d.element ?? null));
    workspaceStore.getState().openPou(pouOf(workspaceStore.getState().project, target.pou)?.name ?? target.pou);
    panelsStore.getState().reveal(target);
  }, []);

  /** A variable dragged from the active diagram, as a path of its POU's instance. */
  const pathOfOperand = useCallback(
    (operand: string) => {
      const ws = workspaceStore.getState();
      const pou = ws.active ? pouOf(project, ws.active) : undefined;
      const online = onlineStore.getState();
      const instance = pou ? instanceOf(pou, online.instances, online.instanceChoices) : null;
      return instance ? operandPath(operand, instance, symbolsOf(ws.symbols[pou!.name])) : null;
    },
    [project],
  );

  const networksOf = useCallback(
    (pouName: string, part?: string | null) => {
      const pou = pouNamed(project, pouName);
      const body = part && pou?.language === "sfc" ? partAt(pou.body as SfcBody, part)?.body : pou?.body;
      return body && typeof body === "object" && "networks" in body
        ? ((body as { networks?: { id: string }[] }).networks ?? []).map((n) => n.id)
        : [];
    },
    [project],
  );

  const elementText = useCallback(
    (pouName: string, id: string) => {
      const pou = pouNamed(project, pouName);
      return pou?.language === "sfc" ? sfcElementText(pou.body as SfcBody, id) : null;
    },
    [project],
  );

  // Breakpoints stay on what they are on, or are dropped with a message when it is gone.
  useEffect(() => {
    const stop = followBreakpoints();
    return stop;
  }, []);

  // A different project: the old one's simulation and check results do not apply; its own breakpoints do.
  useEffect(() => {
    void onlineStore.getState().goOffline();
    panelsStore.getState().clear();
    testsStore.getState().clear();
    debugStore.getState().open(name);
  }, [name]);

  // Once it has loaded, the project's session comes back (watch list, trace setup, tabs, its running
  // simulation) and is kept from then on.
  const ready = status === "ready";
  useEffect(() => {
    if (!ready || !name) return;
    let kept: (() => void) | null = null;
    let current = true;
    void restoreSession(name, SESSION_STORES, localStorage).finally(() => {
      if (current) kept = keepSession(name, SESSION_STORES, localStorage);
    });
    return () => {
      current = false;
      kept?.();
    };
  }, [name, ready]);

  useAppKeys();

  if (status === "loading" || status === "idle") return <p className="placeholder">Opening {name}…</p>;
  if (status === "error") {
    return (
      <div className="empty" role="alert">
        <p>Could not open {name}.</p>
        <p className="empty-detail">{error}</p>
      </div>
    );
  }
  return (
    <div
      className={`workspace${treeHidden ? " tree-hidden" : ""}${panelsHidden ? " panels-hidden" : ""}`}
      style={
        {
          ...(panelsHeight ? { "--panels-height": `${panelsHeight}px` } : {}),
          ...(treeWidth ? { "--tree-width": `${treeWidth}px` } : {}),
        } as CSSProperties
      }
    >
      <div className="workspace-bar">
        <ToolButton
          icon={treeHidden ? PanelLeftOpen : PanelLeftClose}
          label={treeHidden ? "Show project tree" : "Hide project tree"}
          className="panel-toggle"
          aria-pressed={!treeHidden}
          onClick={toggleTree}
        />
        <h2>{name}</h2>
        <span className={`save-state${changed.length ? " dirty" : ""}`} role="status">
          {saving
            ? "Saving…"
            : changed.length
              ? `Unsaved changes in ${changed.map(tabLabel).join(", ")}`
              : "All changes saved"}
        </span>
        <ToolButton
          icon={Save}
          label="Save"
          keys={keysOf("app", "save")}
          onClick={() => void save()}
          disabled={saving || changed.length === 0}
        />
        {undo ? (
          <button type="button" onClick={() => workspaceStore.getState().undoOperation()}>
            Undo {undo.label}
          </button>
        ) : null}
        {restoredAt ? (
          <span className="restored">
            Restored unsaved changes from {formatTime(restoredAt)}.{" "}
            <button type="button" className="link" onClick={() => void reload()}>
              Discard them
            </button>
          </span>
        ) : null}
        {saveError ? (
          <span className="save-error" role="alert">
            Save failed: {saveError}
          </span>
        ) : null}
        {name ? (
          <ExportMenu
            project={name}
            pou={
              active && !isTestPath(active) && !isShellTab(active) && !isProjectPart(active) && !isGvlTab(active)
                ? active
                : null
            }
            unsaved={changed.length > 0}
          />
        ) : null}
        <ToolButton
          icon={Keyboard}
          label="Keyboard shortcuts"
          aria-expanded={help}
          onClick={() => setHelp((h) => !h)}
        />
        <ToolButton
          icon={panelsHidden ? PanelBottomOpen : PanelBottomClose}
          label={panelsHidden ? "Show panels" : "Hide panels"}
          className="panel-toggle"
          aria-pressed={!panelsHidden}
          onClick={togglePanels}
        />

        {help ? <ShortcutHelp scopes={["app", "ld", "fbd", "st"]} onClose={() => setHelp(false)} /> : null}
        <ImportPlcopen
          onStored={() => appStore.getState().loadProjects()}
          onOpen={(imported) => appStore.getState().selectProject(imported)}
        />
      </div>
      <ViewBoundary name="The simulation toolbar" gridArea="sim">
        <SimulationBar />
      </ViewBoundary>
      {treeHidden ? null : (
        <SidePanel
          name="The project tree"
          gridArea="tree"
          resizeLabel="Resize the project tree"
          splitterClass="tree-splitter"
          width={treeWidth}
          onResize={resizeTree}
        >
          <ProjectTree />
        </SidePanel>
      )}
      <div className="editor-area">
        <HistoryBanner
          describe={(at) =>
            describeHalt(
              at,
              networksOf(at.pou, at.body),
              at.element && !at.body ? elementText(at.pou, at.element) : null,
            )
          }
          reveal={revealPlace}
        />
        <ViewBoundary name="The debugging bar">
          <DebugBar networksOf={networksOf} elementText={elementText} reveal={revealPlace} />
        </ViewBoundary>
        <ViewBoundary name="The tabs">
          <Tabs />
        </ViewBoundary>
        {active ? (
          isShellTab(active) ? (
            <Suspense fallback={LOADING}>
              <ShellTab tab={active} />
            </Suspense>
          ) : isProjectPart(active) ? (
            <ProjectPartView key={active} part={active} />
          ) : isGvlTab(active) ? (
            <GvlPartView key={active} name={gvlNameOf(active)} />
          ) : isTestPath(active) ? (
            <Suspense fallback={LOADING}>
              <TestFileView key={active} path={active} />
            </Suspense>
          ) : (
            <PouView key={active} name={active} />
          )
        ) : (
          <p className="placeholder">Open a POU from the project tree.</p>
        )}
      </div>
      {panelsHidden ? null : (
        <ViewBoundary name="The panels" gridArea="panels">
          <BottomPanels onReveal={reveal} pathOfOperand={pathOfOperand} />
        </ViewBoundary>
      )}
      <ViewBoundary name="The save conflict dialog">
        <ConflictDialog />
      </ViewBoundary>
    </div>
  );
}
