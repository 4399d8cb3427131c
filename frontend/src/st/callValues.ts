// A FUNCTION's or METHOD's own variables online (issue 25 item 6; ON-03, ON-09): they live for one call, so no
// path names them and nothing subscribes to them; while the scan is halted in the call, the status message's call
// stack carries their values (`CallFrame`), and its editor shows them after each occurrence as every inline value
// is shown (CODESYS shows a method's variables only at a halt in it). Read only: a call's variable has no path to
// write or force. Elementary values only (an array or structure variable shows none, as in the LD/FBD views).
import { useMemo } from "react";
import type { CallFrame, StackVariable } from "../generated/monitor";
import { haltedCall } from "../online/monitor";
import { shownOf } from "../online/shown";
import { useOnline } from "../online/store";
import { tokenize } from "./language";
import type { InlineMark, Occurrence, StOnlineView } from "./inlineValues";

export type CallView = StOnlineView & { marks: readonly InlineMark[] };

const elementary = (value: unknown) => value === null || typeof value !== "object";

/** A call's variable kinds in words, for the hover text. */
const KIND_WORDS: Record<StackVariable["kind"], string> = {
  input: "input",
  output: "output",
  in_out: "in-out",
  var: "variable",
  temp: "temporary",
  result: "result",
};

/**
 * The occurrences in `text` of the call's own variables (names as declared, any case) and their values: a bare
 * name, not a member (`inst.x`), a called POU (`x(`) or a formal parameter (`x :=` in a call).
 */
export function callView(text: string, call: CallFrame): CallView {
  const variables = new Map((call.variables ?? []).map((v) => [v.name.toUpperCase(), v]));
  const tokens = tokenize(text).filter((t) => t.style !== null);
  const occurrences: Occurrence[] = [];
  const marks: InlineMark[] = [];
  const said = new Map<Occurrence, string>();
  let depth = 0;
  tokens.forEach((t, i) => {
    if (t.text === "(") depth += 1;
    else if (t.text === ")") depth = Math.max(0, depth - 1);
    const variable = t.style === "variableName" ? variables.get(t.text.toUpperCase()) : undefined;
    const [before, after] = [tokens[i - 1]?.text, tokens[i + 1]?.text];
    const formal = depth > 0 && (after === ":=" || after === "=>");
    if (!variable || before === "." || after === "(" || after === "." || formal) return;
    if (variable.reason == null && !elementary(variable.value)) return;
    const o: Occurrence = { from: t.from, to: t.to, text: t.text, path: variable.name, type: variable.type.name };
    occurrences.push(o);
    if (variable.reason != null) {
      said.set(o, `${t.text} : ${variable.type.name}: no value (${variable.reason})`);
      return;
    }
    const shown = { ...shownOf(variable.value ?? null, variable.type), forced: false, prepared: null };
    marks.push({ pos: t.to, shown });
    said.set(o, `${t.text} : ${variable.type.name} = ${shown.text} (this call's ${KIND_WORDS[variable.kind]})`);
  });
  return { occurrences, marks, describe: (o) => said.get(o) ?? o.text, onMenu: () => {}, onPrepare: () => {} };
}

/** The inline values of POU `pou`'s own variables (a method as `FB.M`) while the scan is halted in a call of it. */
export function useCallValues(pou: string | null, text: string): CallView | undefined {
  const call = useOnline((s) => (pou ? haltedCall(s.monitor, pou) : null));
  return useMemo(() => (call ? callView(text, call) : undefined), [call, text]);
}

/**
 * A method body's view online: the instance's variables (`view`, writable) and, while halted in the call, its own
 * (`call`, read only: no menu, no prepare); either alone when the other is missing.
 */
export function withCall(view: CallView | undefined, call: CallView | undefined): CallView | undefined {
  if (!view || !call) return view ?? call;
  const own = new Set(call.occurrences);
  return {
    occurrences: [...view.occurrences, ...call.occurrences],
    marks: [...view.marks, ...call.marks].sort((a, b) => a.pos - b.pos),
    describe: (o) => (own.has(o) ? call.describe(o) : view.describe(o)),
    onMenu: (o, x, y) => (own.has(o) ? undefined : view.onMenu(o, x, y)),
    onPrepare: (o) => (own.has(o) ? undefined : view.onPrepare(o)),
  };
}
