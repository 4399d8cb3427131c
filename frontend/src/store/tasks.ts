// What a project runs, as the project tree lists it: its own tasks, or its configuration's resources with
// their tasks and the program instances each runs (issue 16; the model is backend/ladderlab/model/project.py).
import type { ProgramInstance, Project, Task } from "../generated/api";
import { identifierProblem } from "../iec/identifier";

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
  const renamed = (tasks: Task[] | undefined) => tasks?.map((t) => (t.name === oldName ? { ...t, name } : t));
  return {
    ...project,
    ...(project.tasks ? { tasks: renamed(project.tasks) } : {}),
    ...(project.configuration
      ? {
          configuration: {
            ...project.configuration,
            resources: resources.map((r) => ({ ...r, tasks: renamed(r.tasks) })),
          },
        }
      : {}),
  };
}
