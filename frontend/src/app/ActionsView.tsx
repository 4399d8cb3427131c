// A function block's ACTIONs outside SFC (CODESYS; IL-08, docs/st.md "ACTION"): statements without variables of
// their own that run on the instance's variables, called `Inst.Reset();` in ST or `CAL Inst.Reset` in IL. Each is
// edited here in the ST editor, with the live check of the working copy (the checker names an action's text
// `<FB>.<action>/body`) and the FB's variables to complete.
import { useState, type FormEvent } from "react";
import type { Pou, PouAction } from "../generated/api";
import { useOnline } from "../online/store";
import { StEditor } from "../st/StEditor";
import { useStAssist } from "../st/useStAssist";
import { useWorkspace } from "../store/project";

const IDENTIFIER = /^[A-Za-z_][A-Za-z0-9_]*$/;

/** Why `name` cannot be a new action of `pou` (null: it can). */
export function actionNameProblem(pou: Pou, name: string): string | null {
  if (!IDENTIFIER.test(name)) return `${name || "An empty name"} is not an IEC identifier.`;
  const upper = name.toUpperCase();
  const taken = [...(pou.actions ?? []), ...(pou.methods ?? []), ...(pou.properties ?? [])].some(
    (m) => m.name.toUpperCase() === upper,
  );
  return taken ? `${pou.name} already has a method, property or action called ${name}.` : null;
}

export function ActionsView({ pou }: { pou: Pou }) {
  const setActions = useWorkspace((s) => s.setActions);
  const { diagnostics, completions } = useStAssist(pou);
  const phase = useOnline((s) => s.phase);
  const readOnly = phase === "offline" ? null : "Online: go offline to edit.";
  const [name, setName] = useState("");
  const [problem, setProblem] = useState<string | null>(null);
  const actions = pou.actions ?? [];
  const replace = (next: PouAction[]) => setActions(pou.name, next);

  const add = (event: FormEvent) => {
    event.preventDefault();
    const wanted = name.trim();
    const refused = actionNameProblem(pou, wanted);
    setProblem(refused);
    if (refused) return;
    replace([...actions, { name: wanted, body: "" }]);
    setName("");
  };

  return (
    <div className="pou-actions-view">
      <p className="hint">
        Actions run on the variables of the instance they are called on: <code>Inst.Action();</code> in ST,{" "}
        <code>CAL Inst.Action</code> in IL, <code>Action();</code> inside {pou.name}.
      </p>
      {actions.map((action, index) => (
        <section key={action.name} className="pou-action" aria-label={`Action ${action.name}`}>
          <h3>
            ACTION {action.name}
            <button
              type="button"
              disabled={readOnly !== null}
              onClick={() => replace(actions.filter((_, i) => i !== index))}
            >
              Delete action {action.name}
            </button>
          </h3>
          <div style={{ height: "10rem", overflow: "hidden", border: "1px solid #ccc" }}>
            <StEditor
              text={action.body ?? ""}
              onChange={(text) =>
                text !== action.body && replace(actions.map((a, i) => (i === index ? { ...a, body: text } : a)))
              }
              file={`${pou.name}.${action.name}/body`}
              diagnostics={diagnostics}
              completions={completions}
              readOnly={readOnly}
              label={`${pou.name}.${action.name} body`}
            />
          </div>
        </section>
      ))}
      {actions.length === 0 ? <p className="tree-empty">{pou.name} has no actions.</p> : null}
      <form onSubmit={add} className="pou-action-add">
        <label>
          New action
          <input
            value={name}
            disabled={readOnly !== null}
            onChange={(e) => setName(e.target.value)}
            placeholder="name"
          />
        </label>
        <button type="submit" disabled={readOnly !== null}>
          Add action
        </button>
        {problem ? <span role="alert">{problem}</span> : null}
      </form>
    </div>
  );
}
