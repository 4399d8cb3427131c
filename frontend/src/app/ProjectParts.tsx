// Editors of the project's own parts: the global variables and each global variable list (the declarations
// table and text of the POUs; a row is renamed everywhere and deleted through the tree's dialogs, listing its
// uses), the types (text with a list of the types and a form that adds a STRUCT, enumeration, array,
// subrange or alias) and the tasks (cyclic interval or SINGLE event, priority, watchdog, the programs each
// runs in order, each run's instance name and parameter bindings).
// Each shows the live check of the working copy where it applies, like the POU editors.
import { PencilLine, SlidersHorizontal } from "lucide-react";
import { Suspense, useMemo, useState, type FormEvent } from "react";
import type { Diagnostic } from "../generated/api";
import type { Task } from "../generated/api";
import { DeclarationsEditor } from "../declarations/DeclarationsEditor";
import { useDeclarableTypes } from "../store/declarableTypes";
import { DeleteDialog, RenameDialog } from "../tree/lazyDialogs";
import { globalOperations } from "../tree/operations";
import { TypeActions } from "../tree/TypeActions";
import { usePanels } from "../store/panels";
import { LazyStEditor, LOADING } from "./lazy";
import { useLiveCheck } from "../store/useLiveCheck";
import { useOnline } from "../online/store";
import { taskIndexOf } from "../store/parts";
import { globalsText } from "../store/globals";
import { gvlOf, gvlTab, withGvlChange } from "../store/gvls";
import { structMembers, TYPE_KINDS, typeRows, withNewType, withStructMembers, type TypeKind } from "../store/types";
import type { DeclRow } from "../iec/declarations";
import { useWorkspace, workspaceStore } from "../store/project";
import { FormError } from "../ui/FormError";
import { asInstance, runField } from "../store/bindings";
import { RunBindings } from "./RunBindings";
import { identifierProblem } from "../iec/identifier";

const NO_COMPLETIONS = { options: [], members: () => null };
const NO_TASKS: Task[] = [];

/** The live check of the working copy, for the diagnostics of one part. */
function usePartDiagnostics(): Diagnostic[] {
  const project = useWorkspace((s) => s.project);
  return useLiveCheck(project);
}

/** The line a clicked diagnostic of this part (or global variable list tab) asks to reveal. */
function usePartFocus(part: string) {
  const focus = usePanels((s) => s.focus);
  // derived outside the selector: a selector returning a new object every time renders without end
  return useMemo(
    () => (focus?.pou === part && focus.line != null ? { line: focus.line, seq: focus.seq } : null),
    [focus, part],
  );
}

const readOnlyWhenOnline = (phase: string) => (phase === "offline" ? null : "Online: go offline to edit.");

export function GlobalsView() {
  return <GlobalDeclarations list={null} />;
}

/** A global variable list (CODESYS's GVL): its qualified_only option and its variables, as the Global variables
 * editor shows those of no list. */
export function GvlView({ name }: { name: string }) {
  const gvl = useWorkspace((s) => gvlOf(s.project, name));
  const setProjectPart = useWorkspace((s) => s.setProjectPart);
  const phase = useOnline((s) => s.phase);
  if (!gvl) return <p className="tree-empty">There is no global variable list called {name}.</p>;
  const readOnly = readOnlyWhenOnline(phase);
  return (
    <div className="pou-view part-view gvl-view" role="region" aria-label={`Global variable list ${gvl.name}`}>
      <label className="gvl-option" title={readOnly ?? undefined}>
        <input
          type="checkbox"
          checked={gvl.qualified_only ?? false}
          disabled={readOnly !== null}
          onChange={(e) =>
            setProjectPart(gvlTab(gvl.name), (p) => withGvlChange(p, gvl.name, { qualified_only: e.target.checked }))
          }
        />{" "}
        qualified_only: its variables are used only as {gvl.name}.name
      </label>
      <GlobalDeclarations list={gvl.name} />
    </div>
  );
}

/** The declarations table and text of the globals of no list (`list` null) or of one global variable list; a row
 * is renamed everywhere and deleted through the tree's dialogs. */
function GlobalDeclarations({ list }: { list: string | null }) {
  const [renaming, setRenaming] = useState<string | null>(null);
  const [removing, setRemoving] = useState<string | null>(null);
  const removal = useMemo(() => (removing ? globalOperations(removing, list) : null), [removing, list]);
  const text = useWorkspace((s) => (s.project ? globalsText(s.project, list) : ""));
  const setProjectPart = useWorkspace((s) => s.setProjectPart);
  const setGlobals = useWorkspace((s) => s.setGlobals);
  const onChange = (next: string) =>
    list === null ? setGlobals(next) : setProjectPart(gvlTab(list), (p) => withGvlChange(p, list, { text: next }));
  const types = useDeclarableTypes();
  const file = list === null ? "globals" : `gvls/${list}`;
  const diagnostics = usePartDiagnostics().filter((d) => d.file === file);
  const focus = usePartFocus(list === null ? "part:globals" : gvlTab(list));
  const phase = useOnline((s) => s.phase);
  return (
    <div className="pou-view part-view" aria-label="Global variables editor" role="region">
      <DeclarationsEditor
        text={text}
        onChange={onChange}
        diagnostics={diagnostics}
        types={types}
        focus={focus}
        readOnly={readOnlyWhenOnline(phase)}
        newClass="VAR_GLOBAL"
        onRename={setRenaming}
        onRemove={setRemoving}
      />
      {renaming ? <RenameDialog current={renaming} isPou={false} onClose={() => setRenaming(null)} /> : null}
      {removing && removal ? (
        <DeleteDialog name={`global ${removing}`} item={removal} onClose={() => setRemoving(null)} />
      ) : null}
    </div>
  );
}

export function TypesView() {
  const text = useWorkspace((s) => s.project?.types ?? "");
  const setTypes = useWorkspace((s) => s.setTypes);
  const diagnostics = usePartDiagnostics();
  const focus = usePartFocus("part:types");
  const phase = useOnline((s) => s.phase);
  const [jump, setJump] = useState<{ line: number; seq: number } | null>(null);
  const [name, setName] = useState("");
  const [kind, setKind] = useState<TypeKind>("struct");
  const [error, setError] = useState<string | null>(null);
  const [renaming, setRenaming] = useState<string | null>(null);
  const [selected, setSelected] = useState<string | null>(null);
  const rows = useMemo(() => typeRows(text), [text]);
  const struct = rows.find((r) => r.kind === "struct" && r.name === selected)?.name ?? null;
  const add = (e: FormEvent) => {
    e.preventDefault();
    const wanted = name.trim();
    const notIdentifier = identifierProblem(wanted);
    if (notIdentifier) {
      setError(notIdentifier);
      return;
    }
    if (rows.some((r) => r.name.toUpperCase() === wanted.toUpperCase())) {
      setError(`There is already a type called ${wanted}.`);
      return;
    }
    setError(null);
    setName("");
    const next = withNewType(text, wanted, kind);
    setTypes(next);
    const line = typeRows(next).find((r) => r.name === wanted)?.line ?? 1;
    setJump({ line, seq: Date.now() });
  };
  const readOnly = readOnlyWhenOnline(phase);
  return (
    <div className="pou-view part-view types-view" role="region" aria-label="Types editor">
      <div className="types-side">
        <table className="types-table" aria-label="Types">
          <thead>
            <tr>
              <th>Type</th>
              <th>Kind</th>
              <th />
            </tr>
          </thead>
          <tbody>
            {rows.map((r) => (
              <tr key={`${r.name}:${r.line}`}>
                <td>
                  <button
                    type="button"
                    className="link"
                    aria-pressed={selected === r.name}
                    onClick={() => {
                      setSelected(r.name);
                      setJump({ line: r.line, seq: Date.now() });
                    }}
                  >
                    {r.name}
                  </button>
                </td>
                <td>{TYPE_KINDS.find((k) => k.kind === r.kind)!.label}</td>
                <td>
                  <button
                    type="button"
                    aria-label={`Rename ${r.name} everywhere`}
                    title="Rename everywhere (every use in the project)"
                    disabled={readOnly !== null}
                    onClick={() => setRenaming(r.name)}
                  >
                    <PencilLine size={14} aria-hidden="true" />
                  </button>
                  <TypeActions type={r.name} disabledBecause={readOnly ?? undefined} />
                </td>
              </tr>
            ))}
          </tbody>
        </table>
        {struct ? (
          <StructMembers key={struct} text={text} name={struct} onChange={setTypes} readOnly={readOnly !== null} />
        ) : null}
        {readOnly ? null : (
          <form className="new-type" aria-label="New type" onSubmit={add}>
            <input aria-label="Type name" value={name} onChange={(e) => setName(e.target.value)} placeholder="name" />
            <select aria-label="Type kind" value={kind} onChange={(e) => setKind(e.target.value as TypeKind)}>
              {TYPE_KINDS.map((k) => (
                <option key={k.kind} value={k.kind}>
                  {k.label}
                </option>
              ))}
            </select>
            <button type="submit">Add type</button>
            <FormError error={error} />
          </form>
        )}
      </div>
      {renaming ? <RenameDialog current={renaming} isPou={false} onClose={() => setRenaming(null)} /> : null}
      <div className="types-text">
        <Suspense fallback={LOADING}>
          <LazyStEditor
            text={text}
            onChange={setTypes}
            file="types"
            diagnostics={diagnostics}
            completions={NO_COMPLETIONS}
            readOnly={readOnly}
            label="Types text"
            focusLine={jump && (!focus || jump.seq > focus.seq) ? jump : focus}
          />
        </Suspense>
      </div>
    </div>
  );
}

const MEMBER_COLUMNS = [
  ["name", "Name"],
  ["type", "Type"],
  ["initial", "Initial value"],
  ["comment", "Comment"],
] as const;

/**
 * The members of one STRUCT as an editable table (name, type, initial value, comment): each edit rewrites the
 * STRUCT in the types text. The table keeps its own rows while the user types (a half-typed member need not
 * parse); a STRUCT the table cannot hold (e.g. comments between members) is edited in the text.
 */
function StructMembers({
  text,
  name,
  onChange,
  readOnly,
}: {
  text: string;
  name: string;
  onChange(text: string): void;
  readOnly: boolean;
}) {
  const read = useMemo(() => structMembers(text, name), [text, name]);
  const [rows, setRows] = useState<DeclRow[]>(read ?? []);
  const [written, setWritten] = useState<string | null>(null);
  const [seen, setSeen] = useState(text);
  if (text !== seen) {
    setSeen(text);
    if (text !== written && read) setRows(read); // changed elsewhere (the text view): the text wins
  }
  if (!read && text !== written) {
    return <p className="tree-empty">The members of {name} are edited in the text (the table cannot hold them).</p>;
  }
  const update = (next: DeclRow[]) => {
    setRows(next);
    const printed = withStructMembers(text, name, next);
    setWritten(printed);
    onChange(printed);
  };
  const free = (base: string) => {
    const taken = new Set(rows.map((r) => r.name.toUpperCase()));
    let n = rows.length + 1;
    while (taken.has(`${base}${n}`.toUpperCase())) n += 1;
    return `${base}${n}`;
  };
  return (
    <div className="struct-members">
      <table className="types-table" aria-label={`Members of ${name}`}>
        <thead>
          <tr>
            {MEMBER_COLUMNS.map(([, heading]) => (
              <th key={heading}>{heading}</th>
            ))}
            <th />
          </tr>
        </thead>
        <tbody>
          {rows.map((row, i) => (
            <tr key={i}>
              {MEMBER_COLUMNS.map(([field, heading]) => (
                <td key={field}>
                  <input
                    aria-label={`${heading} of member ${i + 1}`}
                    value={row[field]}
                    disabled={readOnly}
                    spellCheck={false}
                    onChange={(e) => update(rows.map((r, k) => (k === i ? { ...r, [field]: e.target.value } : r)))}
                  />
                </td>
              ))}
              <td>
                <button
                  type="button"
                  aria-label={`Remove member ${row.name}`}
                  disabled={readOnly}
                  onClick={() => update(rows.filter((_, k) => k !== i))}
                >
                  ×
                </button>
              </td>
            </tr>
          ))}
        </tbody>
      </table>
      <button
        type="button"
        disabled={readOnly}
        onClick={() =>
          update([
            ...rows,
            { name: free("Member"), varClass: "VAR", type: "BOOL", initial: "", address: "", comment: "" },
          ])
        }
      >
        Add member
      </button>
    </div>
  );
}

/** A task's run as listed: a program's name, or an instance "name : type" (its bindings are kept as they are). */
const runName = (run: NonNullable<Task["programs"]>[number]) =>
  typeof run === "string" ? run : `${run.name} : ${run.type}`;

const newTask = (tasks: readonly Task[]): Task => {
  const taken = new Set(tasks.map((t) => t.name.toUpperCase()));
  let n = tasks.length + 1;
  while (taken.has(`TASK${n}`)) n += 1;
  return { name: `Task${n}`, interval: "T#10ms", priority: 0, programs: [] };
};

export function TasksView() {
  const tasks = useWorkspace((s) => s.project?.tasks ?? NO_TASKS);
  const pous = useWorkspace((s) => s.project?.pous);
  const programs = useMemo(() => (pous ?? []).filter((p) => p.kind === "program").map((p) => p.name), [pous]);
  const setTasks = useWorkspace((s) => s.setTasks);
  const diagnostics = usePartDiagnostics();
  /** The run whose parameters are shown: [task index, run index]. */
  const [opened, setOpened] = useState<[number, number] | null>(null);
  const phase = useOnline((s) => s.phase);
  const disabled = phase !== "offline";
  const update = (index: number, patch: Partial<Task>) =>
    setTasks(tasks.map((t, i) => (i === index ? { ...t, ...patch } : t)));
  const move = (index: number, program: number, by: number) => {
    setOpened(null);
    const list = [...(tasks[index]!.programs ?? [])];
    const [moved] = list.splice(program, 1);
    list.splice(program + by, 0, moved!);
    update(index, { programs: list });
  };
  return (
    <div className="pou-view part-view tasks-view" role="region" aria-label="Tasks editor">
      {tasks.length === 0 ? (
        <p className="tree-empty">No tasks: every program runs in the default task every 10 ms.</p>
      ) : null}
      <table className="tasks-table" aria-label="Tasks">
        <thead>
          <tr>
            <th>Name</th>
            <th>Interval</th>
            <th>SINGLE (event)</th>
            <th>Priority</th>
            <th>Watchdog (ms)</th>
            <th>Programs, in the order they run</th>
            <th />
          </tr>
        </thead>
        <tbody>
          {tasks.map((task, index) => {
            const openRun = opened?.[0] === index ? opened[1] : null;
            // A problem of the run whose parameters are shown is shown there, at its field.
            const problems = diagnostics.filter(
              (d) => taskIndexOf(d) === index && (openRun === null || runField(d, index, openRun) === undefined),
            );
            const runs = task.programs ?? [];
            return (
              <tr key={index} aria-label={`Task ${task.name}`} className={problems.length ? "task-invalid" : undefined}>
                <td data-label="Name">
                  <input
                    aria-label="Task name"
                    value={task.name}
                    disabled={disabled}
                    onChange={(e) => update(index, { name: e.target.value })}
                  />
                </td>
                <td data-label="Interval">
                  <input
                    aria-label="Interval"
                    value={task.interval ?? ""}
                    placeholder="none"
                    disabled={disabled}
                    onChange={(e) => update(index, { interval: e.target.value || null })}
                  />
                </td>
                <td data-label="SINGLE (event)">
                  <input
                    aria-label="SINGLE"
                    value={task.single ?? ""}
                    placeholder="BOOL variable"
                    disabled={disabled}
                    onChange={(e) => update(index, { single: e.target.value || null })}
                  />
                </td>
                <td data-label="Priority">
                  <input
                    aria-label="Priority"
                    type="number"
                    min={0}
                    value={task.priority ?? 0}
                    disabled={disabled}
                    onChange={(e) => update(index, { priority: Number(e.target.value) || 0 })}
                  />
                </td>
                <td data-label="Watchdog (ms)">
                  <input
                    aria-label="Watchdog"
                    type="number"
                    min={1}
                    placeholder="100"
                    value={task.watchdog_ms ?? ""}
                    disabled={disabled}
                    onChange={(e) => update(index, { watchdog_ms: e.target.value ? Number(e.target.value) : null })}
                  />
                </td>
                <td data-label="Programs, in the order they run" className="task-programs-cell">
                  <ol className="task-programs" aria-label={`Programs of ${task.name}`}>
                    {runs.map((program, p) => (
                      <li key={p /* not its name: renaming the instance keeps the field focused */}>
                        {runName(program)}
                        <button
                          type="button"
                          aria-label={`Parameters of ${runName(program)}`}
                          aria-expanded={openRun === p}
                          title="Instance name and parameter bindings"
                          onClick={() => setOpened(openRun === p ? null : [index, p])}
                        >
                          <SlidersHorizontal size={14} aria-hidden />
                        </button>
                        <button
                          type="button"
                          aria-label={`Run ${runName(program)} earlier`}
                          disabled={disabled || p === 0}
                          onClick={() => move(index, p, -1)}
                        >
                          ↑
                        </button>
                        <button
                          type="button"
                          aria-label={`Run ${runName(program)} later`}
                          disabled={disabled || p === runs.length - 1}
                          onClick={() => move(index, p, 1)}
                        >
                          ↓
                        </button>
                        <button
                          type="button"
                          aria-label={`Remove ${runName(program)} from ${task.name}`}
                          disabled={disabled}
                          onClick={() => {
                            setOpened(null);
                            update(index, { programs: runs.filter((_, i) => i !== p) });
                          }}
                        >
                          ×
                        </button>
                        {openRun === p ? (
                          <RunBindings
                            run={program}
                            task={task.name}
                            taskIndex={index}
                            runIndex={p}
                            program={pous?.find(
                              (pou) => pou.name.toUpperCase() === asInstance(program).type.toUpperCase(),
                            )}
                            diagnostics={diagnostics}
                            disabled={disabled}
                            onChange={(next) => update(index, { programs: runs.map((r, i) => (i === p ? next : r)) })}
                          />
                        ) : null}
                      </li>
                    ))}
                  </ol>
                  <select
                    aria-label={`Add a program to ${task.name}`}
                    value=""
                    disabled={disabled}
                    onChange={(e) => e.target.value && update(index, { programs: [...runs, e.target.value] })}
                  >
                    <option value="">add a program…</option>
                    {programs
                      .filter((p) => !runs.some((r) => typeof r === "string" && r.toUpperCase() === p.toUpperCase()))
                      .map((p) => (
                        <option key={p} value={p}>
                          {p}
                        </option>
                      ))}
                  </select>
                  {problems.map((d, i) => (
                    <p key={i} className="new-pou-error" role="alert">
                      {d.message}
                    </p>
                  ))}
                </td>
                <td>
                  <button
                    type="button"
                    aria-label={`Delete task ${task.name}`}
                    disabled={disabled}
                    onClick={() => {
                      // one undoable step, as from the tree's menu
                      const ws = workspaceStore.getState();
                      if (!ws.project) return;
                      const rest = tasks.filter((_, i) => i !== index);
                      ws.applyOperation(`delete task ${task.name}`, { ...ws.project, tasks: rest }, ["part:tasks"]);
                    }}
                  >
                    Delete
                  </button>
                </td>
              </tr>
            );
          })}
        </tbody>
      </table>
      <button type="button" disabled={disabled} onClick={() => setTasks([...tasks, newTask(tasks)])}>
        New task
      </button>
    </div>
  );
}
