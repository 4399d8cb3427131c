// What `x.` can be followed by: the inputs, outputs and in-outs of an FB instance's type (standard
// and user FBs, from /api/library) and the fields of a STRUCT type (read from the project's TYPE
// text). Access chains (`inst.Q`, `s.inner.x`) resolve to a type the same way for autocomplete,
// inline values and hover.
import type { LibraryEntry, SymbolInfo } from "../generated/api";
import { tokenize } from "./language";

export interface Member {
  name: string;
  type: string;
  /** VAR_INPUT, VAR_OUTPUT, VAR_IN_OUT for FB pins; "field" for a struct field. */
  kind: string;
}

/** Upper-case STRUCT type name -> its fields in declaration order. */
export type StructTypes = ReadonlyMap<string, readonly Member[]>;

/**
 * The STRUCT types of TYPE text (`Point : STRUCT x, y : INT; END_STRUCT;`), read from its tokens so
 * comments are skipped. A field's type is its text up to `;` or `:=`; nested STRUCTs are not read.
 */
export function structTypes(text: string): StructTypes {
  const tokens = tokenize(text).filter(
    (t) => t.style !== null && t.style !== "comment" && t.style !== "lineComment" && t.style !== "meta",
  );
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

/** The type of `a.b.c` (names matched case-insensitively), or null when a part is unknown. */
export function typeOfChain(chain: readonly string[], scope: Scope): string | null {
  const [head, ...rest] = chain;
  if (!head) return null;
  let type = scope.symbols.find((s) => s.name.toUpperCase() === head.toUpperCase())?.type ?? null;
  for (const part of rest) {
    if (type === null) return null;
    type = membersOf(type, scope)?.find((m) => m.name.toUpperCase() === part.toUpperCase())?.type ?? null;
  }
  return type;
}
