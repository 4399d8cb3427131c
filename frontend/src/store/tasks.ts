// What a project runs, as the project tree lists it: its own tasks, or its configuration's resources with
// their tasks and the program instances each runs (issue 16; the model is backend/ladderlab/model/project.py).
import type { ProgramInstance, Project, Task } from "../generated/api";
import { copyName, identifierProblem } from "../iec/identifier";
import { asInstance } from "./bindings";

export interface TaskLine {
  name: string;
  /** "every T#10ms", "on rising x", "every T#10ms, on rising x" */
  timing: string;
  priority: number;
  /** "Main" for an instance named after its program, else "inst : Type" */
  instances: string[];
}

export interface ResourceGroup {
  /** null: the project's own tasks, or a configuration's tasks without a RESOURCE block */
  name: string | null;
  on: string | null;
  tasks: TaskLine[];
  /** program instances of no task: they run in the default 10 ms task */
  unscheduled: string[];
}

export interface RunsView {
  configuration: string | null;
  resources: ResourceGroup[];
}

export function instanceLabel(program: string | ProgramInstance): string {
  if (typeof program === "string") return program;
  const retain = program.retain === "RETAIN" ? " (RETAIN)" : "";
  return program.name === program.type ? `${program.name}${retain}` : `${program.name} : ${program.type}${retain}`;
}

function taskLine(task: Task): TaskLine {
  const timing = [task.interval ? `every ${task.interval}` : "", task.single ? `on rising ${task.single}` : ""]
    .filter(Boolean)
    .join(", ");
  return {
    name: task.name,
    timing,
    priority: task.priority ?? 0,
    instances: (task.programs ?? []).map(instanceLabel),
  };
}

export function runsOf(project: Project): RunsView {
  const config = project.configuration;
  if (!config) {
    const tasks = (project.tasks ?? []).map(taskLine);
    return { configuration: null, resources: tasks.length ? [{ name: null, on: null, tasks, unscheduled: [] }] : [] };
  }
  return {
    configuration: config.name,
    resources: (config.resources ?? []).map((r) => ({
      name: r.name ?? null,
      on: r.on ?? null,
      tasks: (r.tasks ?? []).map(taskLine),
      unscheduled: (r.programs ?? []).map(instanceLabel),
    })),
  };
}

/** The project with task `oldName` called `newName` (wherever it is: the project's tasks or a resource's), or why
 * not. Nothing else names a task (a program instance runs in the task that lists it), so nothing else changes. */
export function renameTask(project: Project, oldName: string, newName: string): Project | string {
  const name = newName.trim();
  const notIdentifier = identifierProblem(name);
  if (notIdentifier) return notIdentifier;
  const resources = project.configuration?.resources ?? [];
  const all = [...(project.tasks ?? []), ...resources.flatMap((r) => r.tasks ?? [])];
  if (all.some((t) => t.name !== oldName && t.name.toUpperCase() === name.toUpperCase()))
    return `There is already a task called ${name}.`;
  return withTaskLists(project, (tasks) => tasks.map((t) => (t.name === oldName ? { ...t, name } : t)));
}

/** The project with `update` applied to each of its task lists: its own, and each resource's. */
function withTaskLists(project: Project, update: (tasks: Task[]) => Task[]): Project {
  return {
    ...project,
    ...(project.tasks ? { tasks: update(project.tasks) } : {}),
    ...(project.configuration
      ? {
          configuration: {
            ...project.configuration,
            resources: (project.configuration.resources ?? []).map((r) => ({ ...r, tasks: update(r.tasks ?? []) })),
          },
        }
      : {}),
  };
}

/** The project without task `name`; its programs no longer run (nothing else names a task). */
export const withoutTask = (project: Project, name: string): Project =>
  withTaskLists(project, (tasks) => tasks.filter((t) => t.name !== name));

/** Every task of the project: its own, and its configuration's resources'. */
const allTasks = (project: Project): Task[] => [
  ...(project.tasks ?? []),
  ...(project.configuration?.resources ?? []).flatMap((r) => r.tasks ?? []),
];

/** Every program instance's name (a plain run is an instance named after its program), unscheduled ones too. */
function instanceNames(project: Project): string[] {
  const runs = [
    ...allTasks(project).flatMap((t) => t.programs ?? []),
    ...(project.configuration?.resources ?? []).flatMap((r) => r.programs ?? []),
  ];
  return runs.map((run) => asInstance(run).name);
}

/** The name a copy of task `name` gets unless the user types another: `name`_copy (the next free one). */
export const taskCopyName = (project: Project, name: string): string =>
  copyName(
    allTasks(project).map((t) => t.name),
    name,
  );

/** The project with a copy of task `name` called `copy` right after it (in the project's tasks or its
 * resource's), running an instance of each of its programs under a new name (watch paths start with an
 * instance's name: two of one name would be one state) with the same parameter bindings; or why not. */
export function duplicateTask(project: Project, name: string, copy: string): Project | string {
  const original = allTasks(project).find((t) => t.name === name);
  if (!original) return `There is no task ${name}.`;
  const task = copy.trim();
  const problem =
    identifierProblem(task) ??
    (allTasks(project).some((t) => t.name.toUpperCase() === task.toUpperCase())
      ? `There is already a task called ${task}.`
      : null);
  if (problem) return problem;
  const taken = [...instanceNames(project), ...(project.pous ?? []).map((p) => p.name)];
  const programs = (original.programs ?? []).map((run): ProgramInstance => {
    const instance = asInstance(run);
    const renamed = { ...instance, name: copyName(taken, instance.name) };
    taken.push(renamed.name);
    return renamed;
  });
  const duplicate: Task = { ...original, name: task, programs };
  return withTaskLists(project, (tasks) => tasks.flatMap((t) => (t === original ? [t, duplicate] : [t])));
}
