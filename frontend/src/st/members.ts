// What `x.` can be followed by: the inputs, outputs and in-outs of an FB instance's type (standard
// and user FBs, from /api/library) and the fields of a STRUCT type (read from the project's TYPE
// text). Access chains (`inst.Q`, `s.inner.x`) resolve to a type the same way for autocomplete,
// inline values and hover. `membersAfter` answers what may follow a qualifier in an operand - a variable's
// chain, `r^.`, or a name that is no variable (a program, an enumeration type: qualifiers.ts) - for ST
// completion and the LD/FBD operand editor alike.
import type { LibraryEntry, SymbolInfo } from "../generated/api";
import type { InterfaceTypes } from "./interfaces";
import { tokenize } from "./language";

export interface Member {
  name: string;
  type: string;
  /** VAR_INPUT, VAR_OUTPUT, VAR_IN_OUT for FB pins (or a program's, an instance's own VAR...); "field" for a struct
   * field; "value" for an enumeration's value (its type the enumeration). */
  kind: string;
  /** A PROPERTY with CODESYS's {attribute 'monitoring'}: it has a value online (monitoring.ts). */
  monitored?: boolean;
}

/** A name other than a variable that qualifies members (`Prog.x`, `Color.Red`, `THIS^.x`): what follows it. */
export interface Qualifier {
  /** As declared. */
  name: string;
  /** What the name is: "PROGRAM", "enumeration", "THIS^"... */
  kind: string;
  members: readonly Member[];
  /** The function block or program whose methods may be called on it; null: none (an enumeration). */
  methodsOf: string | null;
  /** The methods called on it, when not those of `methodsOf` in the library (THIS^: PRIVATE ones too). */
  methods?: readonly LibraryEntry[];
}

/** Upper-case name (`PROG`, `COLOR`, `THIS^`) -> what it qualifies (qualifiers.ts builds it). */
export type Qualifiers = ReadonlyMap<string, Qualifier>;

/** Upper-case STRUCT type name -> its fields in declaration order. */
export type StructTypes = ReadonlyMap<string, readonly Member[]>;

/** The tokens of declaration text that are code: no space, comment or pragma. */
export function codeTokens(text: string): ReturnType<typeof tokenize> {
  return tokenize(text).filter(
    (t) => t.style !== null && t.style !== "comment" && t.style !== "lineComment" && t.style !== "meta",
  );
}

/**
 * The STRUCT types of TYPE text (`Point : STRUCT x, y : INT; END_STRUCT;`), read from its tokens so
 * comments are skipped. A field's type is its text up to `;` or `:=`; nested STRUCTs are not read.
 */
export function structTypes(text: string): StructTypes {
  const tokens = codeTokens(text);
  const upper = (i: number) => tokens[i]?.text.toUpperCase();
  const types = new Map<string, Member[]>();
  for (let i = 2; i < tokens.length; i++) {
    if (upper(i) !== "STRUCT" || tokens[i - 1]!.text !== ":") continue;
    const fields: Member[] = [];
    let names: string[] = [];
    let j = i + 1;
    for (; j < tokens.length && upper(j) !== "END_STRUCT"; j++) {
      const t = tokens[j]!;
      if (t.style === "variableName" || (t.style === "typeName" && names.length === 0 && tokens[j + 1]?.text === ":"))
        names.push(t.text);
      else if (t.text === ":" && names.length) {
        const start = j + 1;
        while (
          j + 1 < tokens.length &&
          tokens[j + 1]!.text !== ";" &&
          tokens[j + 1]!.text !== ":=" &&
          upper(j + 1) !== "END_STRUCT"
        )
          j++;
        const type = text.slice(tokens[start]?.from ?? 0, tokens[j]!.to).trim();
        for (const name of names) fields.push({ name, type, kind: "field" });
        names = [];
        while (j + 1 < tokens.length && tokens[j + 1]!.text !== ";" && upper(j + 1) !== "END_STRUCT") j++; // skip an initial value
      } else if (t.text !== ",") names = [];
    }
    types.set(tokens[i - 2]!.text.toUpperCase(), fields);
    i = j;
  }
  return types;
}

export interface Scope {
  /** The POU's symbols and the globals. */
  symbols: readonly SymbolInfo[];
  library: readonly LibraryEntry[];
  structs: StructTypes;
  /** The names besides the variables that `name.` may follow (qualifiers.ts); none: only variables have members. */
  qualifiers?: Qualifiers;
  /** The INTERFACEs of the TYPE text (interfaces.ts): what follows a variable of one. */
  interfaces?: InterfaceTypes;
  /** Upper-case function block name -> what another POU may use of its instances besides its pins: its PUBLIC
   * PROPERTYs, an SFC's steps and actions (qualifiers.ts). */
  extras?: ReadonlyMap<string, readonly Member[]>;
}

/**
 * The members of a type (FB pins or struct fields); null for a type without members. An instance declared with its
 * FB_init arguments, `F(n := 3)` or `F(3)`, has the members of `F` (docs/st.md, "FB_init and FB_exit").
 */
export function membersOf(type: string, scope: Scope): readonly Member[] | null {
  const name = type.replace(/\(.*$/s, "").trim().toUpperCase();
  const fb = scope.library.find((e) => e.kind === "function_block" && e.name.toUpperCase() === name);
  if (fb) {
    return [
      ...fb.inputs.map((p) => ({ name: p.name, type: p.type, kind: "VAR_INPUT" })),
      ...fb.in_outs.map((p) => ({ name: p.name, type: p.type, kind: "VAR_IN_OUT" })),
      ...fb.outputs.map((p) => ({ name: p.name, type: p.type, kind: "VAR_OUTPUT" })),
    ];
  }
  return scope.structs.get(name) ?? null;
}

/** The type of `a.b.c` (names matched case-insensitively; a member may be an instance's monitored PROPERTY, which has
 * a value online, and so may a bare name in the code of its own function block), or null when a part is unknown. `GVL_IO.x` is the
 * variable `x` of the global variable list GVL_IO (a global whose `gvl` it is, called `GVL_IO.x` when several lists
 * declare `x`) unless something else has the list's name. */
export function typeOfChain(chain: readonly string[], scope: Scope): string | null {
  const [head, ...tail] = chain;
  if (!head) return null;
  let rest = tail;
  const own = (m: Member) => m.monitored && m.name.toUpperCase() === head.toUpperCase(); // a bare property, THIS^'s
  let type =
    scope.symbols.find((s) => s.name.toUpperCase() === head.toUpperCase())?.type ??
    scope.qualifiers?.get("THIS^")?.members.find(own)?.type ??
    null;
  const member = rest[0]?.toUpperCase();
  if (type === null && member !== undefined) {
    const list = head.toUpperCase();
    const names = [member, `${list}.${member}`];
    const listed = scope.symbols.find((s) => s.gvl?.toUpperCase() === list && names.includes(s.name.toUpperCase()));
    if (listed) [type, rest] = [listed.type, rest.slice(1)];
  }
  for (const part of rest) {
    if (type === null) return null;
    const named = (m: Member) => m.name.toUpperCase() === part.toUpperCase();
    const monitored = scope.extras
      ?.get(type.replace(/\(.*$/s, "").trim().toUpperCase())
      ?.find((m) => m.monitored && named(m));
    type = membersOf(type, scope)?.find(named)?.type ?? monitored?.type ?? null;
  }
  return type;
}

/** One part of a qualifier: a name, indexed (`a[i]`, the index without a dot) or dereferenced (`r^`, `THIS^`). */
export const QUALIFIER_PART = String.raw`[A-Za-z_][A-Za-z0-9_]*(?:\[[^\].[]*\])*\^?`;

/** `ARRAY [bounds] OF element`: the bounds' text and the element type. */
export const ARRAY_TYPE = /^\s*ARRAY\s*\[([^\]]*)\]\s*OF\s+(.+?)\s*$/i;

/** `REF_TO T`, `REFERENCE TO T`, `POINTER TO T` -> T; null: not a reference type. */
export function referencedType(type: string): string | null {
  return /^\s*(?:REF_TO|REFERENCE\s+TO|POINTER\s+TO)\s+(.+?)\s*$/i.exec(type)?.[1] ?? null;
}

/** What an operand may reach after `chain.`: the members and the methods it may call (those of `methodsOf` in the
 * library, unless `methods` lists them). */
export interface Reached {
  members: readonly Member[];
  /** The type or name the members belong to, for the completion's description. */
  owner: string;
  methodsOf: string | null;
  methods?: readonly LibraryEntry[];
}

/** Members an operand may name: not an in-out, which stands for the caller's variable during a call only (the
 * checker's ST-NOT-ACCESSIBLE, `THIS^.io` too). */
const fromOutside = (members: readonly Member[]) => members.filter((m) => m.kind !== "VAR_IN_OUT");

/** A type's members as an operand reaches them (an FB's pins and `extras`, an interface's properties and methods);
 * a REFERENCE TO's target's (CODESYS dereferences it implicitly). */
function reachType(type: string, scope: Scope): Reached | null {
  const target = /^\s*REFERENCE\s+TO\b/i.test(type) ? referencedType(type)! : type;
  const upper = target.trim().toUpperCase();
  const itf = scope.interfaces?.get(upper);
  if (itf) return { members: itf.properties, owner: itf.name, methodsOf: itf.name };
  const members = membersOf(target, scope);
  if (members === null) return null;
  const fb = scope.library.some((e) => e.kind === "function_block" && e.name.toUpperCase() === upper);
  const extras = scope.extras?.get(upper) ?? [];
  return {
    members: [...fromOutside(members), ...extras],
    owner: target.trim(),
    methodsOf: fb ? target.trim() : null,
  };
}

/**
 * What `a.b.` reaches (`a^.b.`, `a[i].b.` and `THIS^.` too): a variable's chain as its types say, else the members
 * of the qualifier it starts with (a program's inputs and outputs, an enumeration's values); with "#", an
 * enumeration's `Color#`. Null: nothing.
 */
export function reach(chain: readonly string[], scope: Scope, separator: "." | "#" = "."): Reached | null {
  const [head, ...rest] = chain;
  if (!head) return null;
  const qualifier = scope.qualifiers?.get(head.toUpperCase());
  const named = qualifier ? { ...qualifier, members: fromOutside(qualifier.members), owner: qualifier.name } : null;
  if (separator === "#") return rest.length === 0 && qualifier?.kind === "enumeration" ? named : null;
  // one part: a name, each `[...]` an element of its array, `^` what its reference points to
  const step = (part: string, members: readonly Member[] | null): string | null => {
    const [, name, indices, deref] = /^([A-Za-z_]\w*)((?:\[[^\]]*\])*)(\^?)$/.exec(part) ?? [];
    let type = members?.find((m) => m.kind !== "value" && m.name.toUpperCase() === name?.toUpperCase())?.type ?? null;
    for (let n = indices?.split("[").length ?? 1; type !== null && n > 1; n--)
      type = ARRAY_TYPE.exec(type)?.[2] ?? null;
    return type !== null && deref ? referencedType(type) : type;
  };
  const variable = step(
    head,
    scope.symbols.map((s) => ({ name: s.name, type: s.type, kind: s.var_class })),
  );
  let reached = variable !== null ? reachType(variable, scope) : named;
  for (const part of rest) {
    const type = reached ? step(part, reached.members) : null;
    reached = type === null ? null : reachType(type, scope);
  }
  return reached;
}

/** What may follow `chain.` (or, with "#", an enumeration's `Color#`) in an operand: one answer for ST completion
 * and the LD/FBD operand editor; null: nothing. */
export function membersAfter(
  chain: readonly string[],
  scope: Scope,
  separator: "." | "#" = ".",
): readonly Member[] | null {
  return reach(chain, scope, separator)?.members ?? null;
}
