// The names other than variables that an operand qualifies (members.ts `reach`/`membersAfter` read them), with
// what follows each as the checker allows it: a PROGRAM's inputs and outputs (`Prog.x`: another POU writes its
// inputs and reads its outputs; its in-outs and internal variables are ST-NOT-ACCESSIBLE), PUBLIC properties, SFC
// steps and actions; an enumeration type's values (CODESYS's `Color.Red`, IEC's `Color#Red`); inside a function
// block or program `THIS^` (all its variables) and `SUPER^` (its base's). A named GVL (`GVL_IO.x`) is one more
// entry that `qualifiers` makes, with its variables as members.
import type { GlobalVariableList, LibraryEntry, Pou } from "../generated/api";
import { interfaceTypes } from "./interfaces";
import { codeTokens, structTypes, type Member, type Qualifier, type Qualifiers, type Scope } from "./members";
import { monitoringMode } from "./monitoring";
import { callable, chartSymbols, declaredSymbols, lineage, withInherited } from "./scope";

/** Upper-case enumeration type name -> its values in declaration order (each of the enumeration's type): CODESYS's
 * `E : (A, B) INT;` and IEC's `E : INT (A := 0, B);` too (not a subrange, `INT (0..9)`). */
export function enumTypes(text: string): ReadonlyMap<string, readonly Member[]> {
  const tokens = codeTokens(text);
  const types = new Map<string, Member[]>();
  let depth = 0; // inside STRUCT ... END_STRUCT: a field's own `(A, B)` names no type
  for (let i = 0; i < tokens.length; i++) {
    const word = tokens[i]!.text.toUpperCase();
    if (word === "STRUCT") depth += 1;
    else if (word === "END_STRUCT") depth = Math.max(0, depth - 1);
    if (depth || tokens[i]!.text !== "(") continue;
    const based = tokens[i - 2]?.text === ":" && /^[A-Za-z_]/.test(tokens[i + 1]?.text ?? "");
    const name = tokens[i - 1]?.text === ":" ? tokens[i - 2] : based ? tokens[i - 3] : undefined;
    if (!name) continue;
    const values: Member[] = [];
    let j = i + 1;
    for (; j < tokens.length && tokens[j]!.text !== ")"; j++) {
      const previous = tokens[j - 1]!.text;
      if ((previous === "(" || previous === ",") && /^[A-Za-z_]\w*$/.test(tokens[j]!.text))
        values.push({ name: tokens[j]!.text, type: name.text, kind: "value" });
    }
    types.set(name.text.toUpperCase(), values);
    i = j;
  }
  return types;
}

/** Where code uses an instance's PROPERTYs: in another POU, in the FB's own code (`THIS^`), in the code of an FB
 * derived from it (`SUPER^`). */
type UsedFrom = "outside" | "own" | "derived";

/** The members of kind `which` (PROPERTYs, METHODs) of `pou` and those it inherits, each once (the nearest: an
 * override), that code `from` where may use (the checker's check_access: PRIVATE in the FB's own code only,
 * PROTECTED in derived FBs' too). */
function usable<T extends { name: string; access?: string }>(
  pou: Pou,
  pous: readonly Pou[],
  from: UsedFrom,
  which: (owner: Pou) => readonly T[] | undefined,
): T[] {
  const found: T[] = [];
  lineage(pou, pous).forEach((owner, depth) => {
    for (const member of which(owner) ?? []) {
      const access = member.access ?? "PUBLIC";
      const allowed =
        access === "PUBLIC" ||
        access === "INTERNAL" ||
        (from !== "outside" && (access === "PROTECTED" || (depth === 0 && from === "own")));
      if (allowed && !found.some((f) => f.name.toUpperCase() === member.name.toUpperCase())) found.push(member);
    }
  });
  return found;
}

/** The PROPERTYs code `from` where may use, as members; those with {attribute 'monitoring'} are `monitored`. */
const propertiesOf = (pou: Pou, pous: readonly Pou[], from: UsedFrom): Member[] =>
  usable(pou, pous, from, (owner) => owner.properties).map((p) => ({
    name: p.name,
    type: p.type,
    kind: "PROPERTY",
    ...(monitoringMode(p) ? { monitored: true } : {}),
  }));

/** The METHODs code `from` where calls on an instance of `pou` (from the working copy, as ST completion offers
 * them). */
const methodsOf = (pou: Pou, pous: readonly Pou[], from: UsedFrom): LibraryEntry[] =>
  usable(pou, pous, from, (owner) => owner.methods).map((m) =>
    callable(m.name, "function", declaredSymbols(m.declarations ?? "") ?? [], m.return_type ?? null),
  );

/** The steps and actions of an SFC POU's chart (`Wash.Idle.X`, `counter.Start.X`, `Fill.Q`), as members. */
function chartMembers(pou: Pou): Member[] {
  return chartSymbols(pou).map((s) => ({
    name: s.name,
    type: s.type,
    kind: s.type === "SFC_STEP" ? "STEP" : "ACTION",
  }));
}

/** What another POU uses of an instance of `pou` besides its pins: its PUBLIC properties, its chart's steps and
 * actions. */
function outsideExtras(pou: Pou, pous: readonly Pou[]): Member[] {
  return [...propertiesOf(pou, pous, "outside"), ...chartMembers(pou)];
}

/** A program's members seen from another POU: its inputs and outputs, PUBLIC properties, steps and actions; a
 * plant's properties are its own (ST-PLANT). */
function programMembers(pou: Pou): Member[] {
  const variables = (declaredSymbols(pou.declarations ?? "") ?? [])
    .filter((s) => s.var_class === "VAR_INPUT" || s.var_class === "VAR_OUTPUT")
    .map((s) => ({ name: s.name, type: s.type, kind: s.var_class }));
  return [...variables, ...(pou.kind === "plant" ? chartMembers(pou) : outsideExtras(pou, []))];
}

/** The project's qualifiers: its named global variable lists (`GVL_IO.x`; the checker refuses a list named like a
 * POU or type, ST-DUPLICATE), its enumeration types, then its programs and plants (a program hides a type of its
 * name, as in the checker; a plant's methods are its own, ST-PLANT). */
export function qualifiers(
  pous: readonly Pou[],
  types: string,
  gvls: readonly GlobalVariableList[] = [],
): Map<string, Qualifier> {
  const found = new Map<string, Qualifier>();
  for (const list of gvls)
    found.set(list.name.toUpperCase(), {
      name: list.name,
      kind: "GVL",
      members: (declaredSymbols(list.text ?? "") ?? []).map((s) => ({ name: s.name, type: s.type, kind: s.var_class })),
      methodsOf: null,
    });
  for (const [name, values] of enumTypes(types))
    found.set(name, { name: values[0]?.type ?? name, kind: "enumeration", members: values, methodsOf: null });
  for (const pou of pous)
    if (pou.kind === "program" || pou.kind === "plant")
      found.set(pou.name.toUpperCase(), {
        name: pou.name,
        kind: pou.kind === "program" ? "PROGRAM" : "PLANT",
        members: programMembers(pou),
        methodsOf: pou.kind === "program" ? pou.name : null,
      });
  return found;
}

/** The variables of function block or program `pou` (those it inherits through EXTENDS too) and the properties
 * code `from` where may use, as members. */
function instanceMembers(pou: Pou, pous: readonly Pou[], from: UsedFrom): Member[] {
  const own = { symbols: declaredSymbols(pou.declarations ?? "") ?? [], library: [], structs: new Map() };
  const variables = withInherited(own, pou, pous).symbols.map((s) => ({
    name: s.name,
    type: s.type,
    kind: s.var_class,
  }));
  return [...variables, ...propertiesOf(pou, pous, from)];
}

/** `found` with `THIS^` (all the variables of `pou`, a function block or program, and its methods) and, when it
 * EXTENDS another, `SUPER^` (the base's); as they were: another POU. */
export function withSelf(found: Qualifiers, pou: Pou, pous: readonly Pou[]): Qualifiers {
  if (pou.kind !== "function_block" && pou.kind !== "program") return found;
  const self = new Map(found);
  self.set("THIS^", {
    name: "THIS^",
    kind: "THIS^",
    members: instanceMembers(pou, pous, "own"),
    methodsOf: null,
    methods: methodsOf(pou, pous, "own"),
  });
  const base = lineage(pou, pous)[1];
  if (base)
    self.set("SUPER^", {
      name: "SUPER^",
      kind: "SUPER^",
      members: instanceMembers(base, pous, "derived"),
      methodsOf: null,
      methods: methodsOf(base, pous, "derived"),
    });
  return self;
}

/** What the project's TYPE text, POUs and global variable lists give a scope besides its variables and library:
 * the STRUCTs, the INTERFACEs, the qualifiers and what the function blocks' instances have besides their pins. */
export function projectScope(
  pous: readonly Pou[],
  types: string,
  gvls: readonly GlobalVariableList[] = [],
): Required<Pick<Scope, "structs" | "interfaces" | "qualifiers" | "extras">> {
  const extras = new Map(
    pous
      .filter((p) => p.kind === "function_block")
      .map((fb) => [fb.name.toUpperCase(), outsideExtras(fb, pous)] as const),
  );
  return {
    structs: structTypes(types),
    interfaces: interfaceTypes(types),
    qualifiers: qualifiers(pous, types, gvls),
    extras,
  };
}
