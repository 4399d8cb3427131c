import type { Pou } from "../generated/api";
import { modifiersText, type Access } from "./modifiers";

/** What a member row says: `Name : TYPE`, and its specifiers when it has any beyond PUBLIC (CODESYS's tree). */
function memberLabel(
  name: string,
  type: string | null | undefined,
  member: { access?: Access; final?: boolean; abstract?: boolean },
): string {
  const typed = type ? `${name} : ${type}` : name;
  const modifiers = modifiersText(member);
  return modifiers ? `${typed} (${modifiers})` : typed;
}

/**
 * A function block's (or program's) methods, properties and actions under it in the project tree (docs/st.md, object
 * orientation), with the FB it extends; choosing a method or property opens it in the POU's Methods tab, an action
 * the FB.
 */
export function PouMembers({ pou, open }: { pou: Pou; open(member: string | null): void }) {
  const methods = pou.methods ?? [];
  const properties = pou.properties ?? [];
  const actions = pou.actions ?? [];
  if (!methods.length && !properties.length && !actions.length && !pou.extends && !pou.implements?.length) return null;
  const heritage = [
    pou.extends ? `EXTENDS ${pou.extends}` : "",
    pou.implements?.length ? `IMPLEMENTS ${pou.implements.join(", ")}` : "",
  ].filter(Boolean);
  return (
    <li className="tree-members-row">
      <ul className="tree-members" aria-label={`${pou.name} members`}>
        {heritage.length ? <li className="tree-meta">{heritage.join(" ")}</li> : null}
        {methods.map((m) => (
          <li key={`m-${m.name}`}>
            <button type="button" className="tree-item tree-member" onClick={() => open(m.name)}>
              <span className="tree-kind">M</span>
              <span className="tree-name">{memberLabel(m.name, m.return_type, m)}</span>
            </button>
          </li>
        ))}
        {properties.map((p) => (
          <li key={`p-${p.name}`}>
            <button type="button" className="tree-item tree-member" onClick={() => open(p.name)}>
              <span className="tree-kind">P</span>
              <span className="tree-name">{memberLabel(p.name, p.type, p)}</span>
            </button>
          </li>
        ))}
        {actions.map((a) => (
          <li key={`a-${a.name}`}>
            <button type="button" className="tree-item tree-member" onClick={() => open(null)}>
              <span className="tree-kind">A</span>
              <span className="tree-name">{a.name}</span>
            </button>
          </li>
        ))}
      </ul>
    </li>
  );
}
