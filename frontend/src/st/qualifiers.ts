// The names other than variables that an operand qualifies (members.ts `reach`/`membersAfter` read them): a
// PROGRAM's inputs and outputs (`Prog.x`: another POU writes its inputs and reads its outputs, as the checker
// allows; its in-outs and internal variables are ST-NOT-ACCESSIBLE), an enumeration type's values (CODESYS's
// `Color.Red`, IEC's `Color#Red`), and inside a function block or program `THIS^` (all its variables) and
// `SUPER^` (its base's). A named GVL's variables (`GVL_IO.x`) are one more entry of `qualifiers`.
import type { Pou } from "../generated/api";
import { tokenize } from "./language";
import { interfaceTypes, type InterfaceTypes } from "./interfaces";
import { structTypes, type Member, type Qualifier, type Qualifiers, type StructTypes } from "./members";
import { withInherited } from "./scope";
import { declaredSymbols } from "./scope";

/** Upper-case enumeration type name -> its values in declaration order (each of the enumeration's type). */
export function enumTypes(text: string): ReadonlyMap<string, readonly Member[]> {
  const tokens = tokenize(text).filter(
    (t) => t.style !== null && t.style !== "comment" && t.style !== "lineComment" && t.style !== "meta",
  );
  const types = new Map<string, Member[]>();
  let depth = 0; // inside STRUCT ... END_STRUCT: a field's own `(A, B)` names no type
  for (let i = 0; i < tokens.length; i++) {
    const word = tokens[i]!.text.toUpperCase();
    if (word === "STRUCT") depth += 1;
    else if (word === "END_STRUCT") depth = Math.max(0, depth - 1);
    if (depth || tokens[i]!.text !== "(" || tokens[i - 1]?.text !== ":" || !tokens[i - 2]) continue;
    const type = tokens[i - 2]!.text;
    const values: Member[] = [];
    let j = i + 1;
    for (; j < tokens.length && tokens[j]!.text !== ")"; j++) {
      const previous = tokens[j - 1]!.text;
      if ((previous === "(" || previous === ",") && /^[A-Za-z_]\w*$/.test(tokens[j]!.text))
        values.push({ name: tokens[j]!.text, type, kind: "value" });
    }
    types.set(type.toUpperCase(), values);
    i = j;
  }
  return types;
}

/** A program's members seen from another POU: its inputs and outputs. */
function programMembers(pou: Pou): Member[] {
  return (declaredSymbols(pou.declarations ?? "") ?? [])
    .filter((s) => s.var_class === "VAR_INPUT" || s.var_class === "VAR_OUTPUT")
    .map((s) => ({ name: s.name, type: s.type, kind: s.var_class }));
}

/** The project's qualifiers: its enumeration types, then its programs (a program hides a type of its name, as in
 * the checker). */
export function qualifiers(pous: readonly Pou[], types: string): Map<string, Qualifier> {
  const found = new Map<string, Qualifier>();
  for (const [name, values] of enumTypes(types))
    found.set(name, { name: values[0]?.type ?? name, kind: "enumeration", members: values, methodsOf: null });
  for (const pou of pous)
    if (pou.kind === "program")
      found.set(pou.name.toUpperCase(), {
        name: pou.name,
        kind: "PROGRAM",
        members: programMembers(pou),
        methodsOf: pou.name,
      });
  return found;
}

/** The variables of function block or program `pou` (those it inherits through EXTENDS too), as members. */
function instanceMembers(pou: Pou, pous: readonly Pou[]): Member[] {
  const own = { symbols: declaredSymbols(pou.declarations ?? "") ?? [], library: [], structs: new Map() };
  return withInherited(own, pou, pous).symbols.map((s) => ({ name: s.name, type: s.type, kind: s.var_class }));
}

/** `found` with `THIS^` (all the variables of `pou`, a function block or program, and its methods) and, when it
 * EXTENDS another, `SUPER^` (the base's); as they were: another POU. */
export function withSelf(found: Qualifiers, pou: Pou, pous: readonly Pou[]): Qualifiers {
  if (pou.kind !== "function_block" && pou.kind !== "program") return found;
  const self = new Map(found);
  self.set("THIS^", { name: "THIS^", kind: "THIS^", members: instanceMembers(pou, pous), methodsOf: pou.name });
  const name = pou.extends?.trim().toUpperCase();
  const base = name ? pous.find((p) => p.kind === "function_block" && p.name.toUpperCase() === name) : undefined;
  if (base)
    self.set("SUPER^", { name: "SUPER^", kind: "SUPER^", members: instanceMembers(base, pous), methodsOf: base.name });
  return self;
}

/** What the project's TYPE text and programs give a scope besides its variables and library: the STRUCTs, the
 * INTERFACEs and the qualifiers. */
export function projectScope(
  pous: readonly Pou[],
  types: string,
): { structs: StructTypes; interfaces: InterfaceTypes; qualifiers: Qualifiers } {
  return { structs: structTypes(types), interfaces: interfaceTypes(types), qualifiers: qualifiers(pous, types) };
}
