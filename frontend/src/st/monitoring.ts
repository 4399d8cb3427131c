// CODESYS's {attribute 'monitoring' := 'variable' | 'call'} on a PROPERTY (docs/st.md, "Properties online"): the
// property then has a value online (the last GET's or SET's, or what its GET returns between scans). The model keeps
// the attribute heading its GET's declarations, else its SET's (backend st/monitoring.py); this reads it there so
// the ST editor shows the property's value inline where code names it (`t.Level`).
import type { Property } from "../generated/api";

/** Comments, blanks and pragmas at the head of a declarations text, one at a time. */
const HEAD = /^(?:\s+|\(\*[\s\S]*?\*\)|\/\*[\s\S]*?\*\/|\/\/[^\n]*|(\{[^}]*\}))/;
const ATTRIBUTE = /^\{\s*attribute\s+'monitoring'\s*:=\s*'([^']*)'\s*\}$/i;

/** The monitoring mode heading a declarations text, or null. */
function headMode(text: string): string | null {
  for (let rest = text; ;) {
    const match = HEAD.exec(rest);
    if (!match) return null;
    const mode = match[1] ? ATTRIBUTE.exec(match[1])?.[1] : undefined;
    if (mode !== undefined) return mode.toLowerCase();
    rest = rest.slice(match[0].length);
  }
}

/** The property's monitoring mode ("variable" or "call"), or null when it has none the engine knows. */
export function monitoringMode(prop: Pick<Property, "get" | "set">): "variable" | "call" | null {
  const accessor = prop.get ?? prop.set;
  const mode = accessor ? headMode(accessor.declarations ?? "") : null;
  return mode === "variable" || mode === "call" ? mode : null;
}
