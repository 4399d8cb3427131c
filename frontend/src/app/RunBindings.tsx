// A task's program run opened in the Tasks editor: the instance's name and its parameter bindings, one field
// per VAR_INPUT (`Start := Go`) and VAR_OUTPUT (`Running => Out`) of the program, the run in the configuration's
// ST words, and each problem the live check finds next to the field it is about.
import type { Diagnostic, Pou } from "../generated/api";
import {
  asInstance,
  parametersOf,
  runField,
  runText,
  withBinding,
  withInstanceName,
  type BindingKind,
  type Run,
} from "../store/bindings";

export interface RunBindingsProps {
  run: Run;
  task: string;
  /** Where the run is in the tasks (its diagnostics' JSON paths say so). */
  taskIndex: number;
  runIndex: number;
  program: Pou | undefined;
  diagnostics: readonly Diagnostic[];
  disabled: boolean;
  onChange(run: Run): void;
}

const ARROW: Record<BindingKind, string> = { inputs: ":=", outputs: "=>" };

export function RunBindings({
  run,
  task,
  taskIndex,
  runIndex,
  program,
  diagnostics,
  disabled,
  onChange,
}: RunBindingsProps) {
  const instance = asInstance(run);
  const parameters = parametersOf(program);
  const problems = diagnostics.flatMap((d) => {
    const field = runField(d, taskIndex, runIndex);
    return field === undefined ? [] : [{ field, message: d.message }];
  });
  const problemsAt = (field: string | null) => problems.filter((p) => p.field === field);
  // The program's parameters, and bindings of names it does not have (so they can be seen and cleared).
  const names = (kind: BindingKind) => {
    const declared = parameters?.[kind] ?? [];
    const extra = Object.keys(instance[kind] ?? {}).filter(
      (p) => !declared.some((d) => d.toUpperCase() === p.toUpperCase()),
    );
    return [...declared, ...extra];
  };
  const bound = (kind: BindingKind, param: string) =>
    Object.entries(instance[kind] ?? {}).find(([p]) => p.toUpperCase() === param.toUpperCase());
  const field = (kind: BindingKind, param: string) => {
    const entry = bound(kind, param);
    const here = problemsAt(`${kind}.${param.toUpperCase()}`);
    return (
      <li key={`${kind}:${param}`}>
        <label>
          <code>
            {param} {ARROW[kind]}
          </code>{" "}
          <input
            aria-label={`${param} ${ARROW[kind]}`}
            aria-invalid={here.length > 0}
            value={entry?.[1] ?? ""}
            placeholder={kind === "inputs" ? "unbound (expression)" : "unbound (variable)"}
            spellCheck={false}
            disabled={disabled}
            onChange={(e) => onChange(withBinding(run, kind, entry?.[0] ?? param, e.target.value))}
          />
        </label>
        {here.map((p, i) => (
          <p key={i} className="new-pou-error" role="alert">
            {p.message}
          </p>
        ))}
      </li>
    );
  };
  const general = [...problemsAt(null), ...problemsAt("type"), ...problemsAt("name")];
  return (
    <div className="run-bindings" role="group" aria-label={`Parameters of ${instance.name}`}>
      <label>
        Instance name{" "}
        <input
          aria-label="Instance name"
          value={instance.name}
          spellCheck={false}
          disabled={disabled}
          onChange={(e) => onChange(withInstanceName(run, e.target.value))}
        />
      </label>
      {parameters === null ? (
        <p className="tree-empty">
          The declarations of {instance.type} cannot be read as a table: its parameters are not listed here.
        </p>
      ) : null}
      <ul className="run-binding-list">
        {names("inputs").map((p) => field("inputs", p))}
        {names("outputs").map((p) => field("outputs", p))}
      </ul>
      {parameters && names("inputs").length + names("outputs").length === 0 ? (
        <p className="tree-empty">{instance.type} has no VAR_INPUT or VAR_OUTPUT to bind.</p>
      ) : null}
      <code className="run-text" aria-label="As ST">
        {runText(run, task)}
      </code>
      {general.map((p, i) => (
        <p key={i} className="new-pou-error" role="alert">
          {p.message}
        </p>
      ))}
    </div>
  );
}
