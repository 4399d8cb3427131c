// Debugging while online: add a breakpoint on a network or element of the active LD POU, the list
// of breakpoints (remove, clear all), and when the scan halts: where it halted (revealed in its
// editor) with Continue / Step (statement in ST) / Step network / Step cycle.
import { useEffect, useState, type FormEvent } from "react";
import type { LdBody, Pou } from "../generated/project";
import { useOnline } from "../online/store";
import { describeBreakpoint, describeHalt, type Breakpoint } from "./breakpoints";
import { useDebug } from "./store";

export interface DebugBarProps {
  /** The POU in the active tab (breakpoints are added to it). */
  pou: Pou | null;
  /** Network ids of a POU in order (for "network 2"), empty when it has no diagram. */
  networksOf(pou: string): string[];
  /** Shows a location in its editor (opens the POU, selects the network or element). */
  reveal(target: { pou: string; network?: string | null; element?: string | null }): void;
}

/** One wrapping row (the bar sits above the tabs and should take little height). */
const ROW = { display: "flex", flexWrap: "wrap", alignItems: "center", gap: "0.4rem", padding: "0.15rem 0.4rem" } as const;

const ldNetworks = (pou: Pou | null): string[] =>
  pou?.language === "ld" && pou.body && typeof pou.body === "object" ? ((pou.body as LdBody).networks ?? []).map((n) => n.id) : [];

export function DebugBar({ pou, networksOf, reveal }: DebugBarProps) {
  const phase = useOnline((s) => s.phase);
  const state = useOnline((s) => s.monitor.state);
  const at = useOnline((s) => s.monitor.at);
  const breakpoints = useDebug((s) => s.breakpoints);
  const debug = useDebug((s) => s);
  const [target, setTarget] = useState("");
  const [element, setElement] = useState("");
  const halted = state === "halted" && at ? at : null;

  // A new halt shows its location in the editor.
  useEffect(() => {
    if (halted) reveal({ pou: halted.pou, network: halted.network, element: halted.element });
  }, [halted, reveal]);

  if (phase === "offline" && breakpoints.length === 0) return null;
  const networks = ldNetworks(pou);
  const add = (e: FormEvent) => {
    e.preventDefault();
    if (!pou) return;
    const bp: Breakpoint | null = element.trim() ? { pou: pou.name, element: element.trim() } : target ? { pou: pou.name, network: target } : null;
    if (bp) debug.toggle(bp);
    setElement("");
  };
  return (
    <div className="debug-bar" role="region" aria-label="Debugging" style={ROW}>
      {halted ? (
        <div className="debug-halted" role="status" style={{ ...ROW, background: "#fff3b0", padding: "0 0.4rem" }}>
          <span>Halted at {describeHalt(halted, networksOf(halted.pou))}</span>
          <button type="button" onClick={debug.resume}>Continue</button>
          {halted.line != null ? (
            <button type="button" onClick={() => debug.step("statement")}>Step statement</button>
          ) : null}
          <button type="button" onClick={() => debug.step("network")}>Step network</button>
          <button type="button" onClick={() => debug.step("cycle")}>Step cycle</button>
        </div>
      ) : null}
      {networks.length ? (
        <form className="debug-add" aria-label="Toggle breakpoint" onSubmit={add}>
          <select aria-label="Breakpoint network" value={target} onChange={(e) => setTarget(e.target.value)}>
            <option value="">network…</option>
            {networks.map((id, i) => (
              <option key={id} value={id}>
                {pou!.name} network {i + 1}
              </option>
            ))}
          </select>
          <input aria-label="Breakpoint element" value={element} onChange={(e) => setElement(e.target.value)} placeholder="or element id" spellCheck={false} />
          <button type="submit">Toggle breakpoint</button>
        </form>
      ) : null}
      <ul className="debug-breakpoints" aria-label="Breakpoints" style={{ ...ROW, listStyle: "none", margin: 0, padding: 0 }}>
        {breakpoints.map((bp) => {
          const text = describeBreakpoint(bp, networksOf(bp.pou));
          return (
            <li key={JSON.stringify(bp)}>
              <button type="button" className="link" onClick={() => reveal({ pou: bp.pou, network: "network" in bp ? bp.network : null, element: "element" in bp ? bp.element : null })}>
                {text}
              </button>
              <button type="button" aria-label={`Remove breakpoint ${text}`} onClick={() => debug.remove(bp)}>
                ×
              </button>
            </li>
          );
        })}
      </ul>
      {breakpoints.length > 1 ? (
        <button type="button" onClick={debug.clearAll}>
          Remove all breakpoints
        </button>
      ) : null}
    </div>
  );
}
