// What the LD/FBD operand editor offers after a qualifier (`T1.`, `Prog.`, `Color.`, `Color#`): the members ST
// completion offers (members.ts `membersAfter`), over the POU's symbols and the working copy's function blocks,
// STRUCTs, INTERFACEs, enumerations and programs, as whole operands. Loaded when an operand is first edited
// (useOperandMembers.ts): it reads declarations with the ST tokenizer, which the app's opening scripts leave out.
import type { GlobalVariableList, LibraryEntry, Pou, SymbolInfo } from "../generated/api";
import type { MembersAfter } from "../ui/OperandEditor";
import { QUALIFIER_PART, membersAfter, type Scope } from "./members";
import { projectScope } from "./qualifiers";
import { workingLibrary } from "./scope";

/** A qualified operand being typed: the qualifier (`a.b`, `a[1]`, `r^`, `Color`), its separator and what follows. */
const QUALIFIED = new RegExp(String.raw`^\s*((?:${QUALIFIER_PART}\.)*${QUALIFIER_PART})([.#])([A-Za-z0-9_]*)$`);

/** After a qualifier in `text`, its members whose name starts with what follows it (in their order), each as the
 * whole operand (`Color.Red`); null: `text` is no qualified operand. */
export function qualifiedSuggestions(text: string, scope: Scope): { name: string; type: string }[] | null {
  const qualified = QUALIFIED.exec(text);
  if (!qualified) return null;
  const qualifier = qualified[1]!;
  const separator = qualified[2] === "#" ? "#" : ".";
  const needle = qualified[3]!.toUpperCase();
  return (membersAfter(qualifier.split("."), scope, separator) ?? [])
    .filter((m) => m.name.toUpperCase().startsWith(needle) && m.name.toUpperCase() !== needle)
    .map((m) => ({ name: `${qualifier}${separator}${m.name}`, type: m.type }));
}

export function operandMembers(
  symbols: readonly SymbolInfo[],
  library: readonly LibraryEntry[],
  pous: readonly Pou[],
  types: string,
  gvls: readonly GlobalVariableList[] = [],
): MembersAfter {
  const scope: Scope = { symbols, library: workingLibrary(library, pous), ...projectScope(pous, types, gvls) };
  return (text) => qualifiedSuggestions(text, scope);
}
