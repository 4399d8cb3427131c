// A task's program run and its parameter bindings, as the Tasks editor edits them: `PROGRAM inst WITH task :
// Prog(in := %IX0.0, out => g)` (IEC 61131-3 2.7.1, CFG-06; backend/ladderlab/model/project.py ProgramInstance).
// A run is a program's name while it adds nothing to it, an instance once it is renamed or binds a parameter.
// The backend checks the bindings (st/configuration.py) and locates each problem by its JSON path.
import { parseDeclarations } from "../iec/declarations";
import type { Diagnostic, Pou, ProgramInstance, Task } from "../generated/api";

export type Run = NonNullable<Task["programs"]>[number];
export type BindingKind = "inputs" | "outputs";

export const asInstance = (run: Run): ProgramInstance =>
  typeof run === "string" ? { name: run, type: run, inputs: {}, outputs: {} } : run;

/** The run as the model keeps it: the plain program name when the instance adds nothing to it. */
function simplified(instance: ProgramInstance): Run {
  const bound = Object.keys(instance.inputs ?? {}).length + Object.keys(instance.outputs ?? {}).length;
  return instance.name === instance.type && !instance.retain && bound === 0 ? instance.type : instance;
}

/** `run` with parameter `param` of `kind` bound to `text` (trimmed; empty: unbound). */
export function withBinding(run: Run, kind: BindingKind, param: string, text: string): Run {
  const instance = asInstance(run);
  const bindings = { ...(instance[kind] ?? {}) };
  if (text.trim()) bindings[param] = text.trim();
  else delete bindings[param];
  return simplified({ ...instance, [kind]: bindings });
}

/** `run` as an instance called `name` (the program's own name gives the plain run back). */
export const withInstanceName = (run: Run, name: string): Run => simplified({ ...asInstance(run), name: name.trim() });

/** A program's parameters, in declaration order; null when its declarations cannot be read as a table. */
export function parametersOf(pou: Pou | undefined): Record<BindingKind, string[]> | null {
  if (!pou) return null;
  const parsed = parseDeclarations(pou.declarations ?? "");
  if (!parsed.ok) return null;
  const of = (block: string) =>
    parsed.rows.filter((r) => r.varClass.toUpperCase().split(" ")[0] === block).map((r) => r.name);
  return { inputs: of("VAR_INPUT"), outputs: of("VAR_OUTPUT") };
}

/** The run in the configuration's ST words: `PROGRAM P1 WITH Fast : Pump(Start := Go, Running => Out);`. */
export function runText(run: Run, task: string): string {
  const instance = asInstance(run);
  const args = [
    ...Object.entries(instance.inputs ?? {}).map(([p, v]) => `${p} := ${v}`),
    ...Object.entries(instance.outputs ?? {}).map(([p, v]) => `${p} => ${v}`),
  ];
  const retain = instance.retain ? ` ${instance.retain}` : "";
  return `PROGRAM${retain} ${instance.name} WITH ${task} : ${instance.type}${args.length ? `(${args.join(", ")})` : ""};`;
}

/** Where in a run a problem is: a binding ("inputs.Start"), the program ("type") or the run as a whole (null). */
export function runField(d: Diagnostic, task: number, run: number): string | null | undefined {
  const prefix = `$.tasks[${task}].programs[${run}]`;
  const path = d.json_path ?? "";
  if (path !== prefix && !path.startsWith(`${prefix}.`)) return undefined;
  const rest = path.slice(prefix.length + 1);
  return rest
    ? rest.replace(/^(inputs|outputs)\.(.*)$/, (_, kind: string, p: string) => `${kind}.${p.toUpperCase()}`)
    : null;
}
