// What each kind of POU is, in the user's words: the New POU form and the kind dialog show it.
import type { Pou } from "../generated/api";

/** What each kind of POU is, for the New POU form and the kind dialog. */
export const KIND_HELP: Record<Pou["kind"], { label: string; help: string }> = {
  program: { label: "program", help: "Runs in a task every cycle; its variables keep their values (like MAIN)." },
  function_block: {
    label: "function block",
    help: "A block with memory (like TON): declare instances of it in programs and call them.",
  },
  function: { label: "function", help: "Computes a result from its inputs (like ADD); no memory between calls." },
  plant: {
    label: "plant",
    help: "A model of the machine (lab bench): runs before the control program in every scan, reads its outputs, writes its inputs.",
  },
};

/** The kind select with a sentence saying what the chosen kind is. */
export function KindPicker({ kind, onChange }: { kind: Pou["kind"]; onChange(kind: Pou["kind"]): void }) {
  return (
    <>
      <select aria-label="POU kind" value={kind} onChange={(e) => onChange(e.target.value as Pou["kind"])}>
        {Object.entries(KIND_HELP).map(([value, { label }]) => (
          <option key={value} value={value}>
            {label}
          </option>
        ))}
      </select>
      <p className="kind-help">{KIND_HELP[kind].help}</p>
    </>
  );
}
