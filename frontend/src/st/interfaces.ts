// The INTERFACEs of the project's TYPE text (docs/st.md: method prototypes and PROPERTY prototypes, EXTENDS other
// interfaces), as what follows a variable of an interface's type: `itf.` offers its properties (read through GET,
// written through SET) and its methods (and those of the interfaces it extends), as the checker accepts them.
import type { LibraryEntry } from "../generated/api";
import { codeTokens, type Member } from "./members";
import { callable, declaredSymbols } from "./scope";

export interface InterfaceType {
  /** As declared. */
  name: string;
  /** Its PROPERTY prototypes (kind "PROPERTY"), those of the interfaces it extends too. */
  properties: readonly Member[];
  /** Its METHOD prototypes as a box calls them (named without the interface), those it extends too. */
  methods: readonly LibraryEntry[];
}

/** Upper-case interface name -> what a variable of it offers. */
export type InterfaceTypes = ReadonlyMap<string, InterfaceType>;

type Token = ReturnType<typeof codeTokens>[number];

/** A METHOD prototype from its tokens `METHOD name [: type] VAR... END_METHOD` (`from`: at METHOD). */
function prototype(text: string, tokens: readonly Token[], from: number, to: number): LibraryEntry {
  let i = from + 1;
  if (/^(PUBLIC|PRIVATE|PROTECTED|INTERNAL)$/i.test(tokens[i]?.text ?? "")) i += 1;
  const name = tokens[i]?.text ?? "";
  const vars = tokens.findIndex((t, k) => k > i && k < to && /^VAR/i.test(t.text));
  const end = vars < 0 ? to : vars;
  const returns =
    tokens[i + 1]?.text === ":" && end > i + 2 ? text.slice(tokens[i + 2]!.from, tokens[end - 1]!.to) : null;
  const symbols = vars < 0 ? [] : (declaredSymbols(text.slice(tokens[vars]!.from, tokens[to]!.from)) ?? []);
  return callable(name, "function", symbols, returns?.trim().replace(/;$/, "").trim() || null);
}

/** The INTERFACEs of TYPE text, read from its tokens (comments and pragmas skipped). */
export function interfaceTypes(text: string): InterfaceTypes {
  const tokens = codeTokens(text);
  const upper = (i: number) => tokens[i]?.text.toUpperCase() ?? "";
  const own = new Map<string, { name: string; bases: string[]; properties: Member[]; methods: LibraryEntry[] }>();
  for (let i = 0; i < tokens.length; i++) {
    if (upper(i) !== "INTERFACE" || !tokens[i + 1]) continue;
    const found = {
      name: tokens[i + 1]!.text,
      bases: [] as string[],
      properties: [] as Member[],
      methods: [] as LibraryEntry[],
    };
    let j = i + 2;
    if (upper(j) === "EXTENDS")
      for (j += 1; j < tokens.length && /^[A-Za-z_]/.test(tokens[j]!.text); j += 2) {
        found.bases.push(tokens[j]!.text.toUpperCase());
        if (tokens[j + 1]?.text !== ",") {
          j += 1;
          break;
        }
      }
    for (; j < tokens.length && upper(j) !== "END_INTERFACE"; j++) {
      if (upper(j) === "METHOD") {
        let end = j + 1;
        while (end < tokens.length && upper(end) !== "END_METHOD" && upper(end) !== "END_INTERFACE") end++;
        found.methods.push(prototype(text, tokens, j, Math.min(end, tokens.length - 1)));
        j = end;
      } else if (upper(j) === "PROPERTY" && tokens[j + 2]?.text === ":") {
        let end = j + 3;
        while (end < tokens.length && !/^(GET|SET|END_PROPERTY|END_INTERFACE)$/.test(upper(end))) end++;
        const type = end > j + 3 ? text.slice(tokens[j + 3]!.from, tokens[end - 1]!.to).trim() : "";
        found.properties.push({ name: tokens[j + 1]!.text, type, kind: "PROPERTY" });
        while (end < tokens.length && upper(end) !== "END_PROPERTY" && upper(end) !== "END_INTERFACE") end++;
        j = end;
      }
    }
    own.set(found.name.toUpperCase(), found);
    i = j;
  }
  // each with what it extends (nearest first; each name once: an override is the interface's own)
  const has = (list: readonly { name: string }[], name: string) =>
    list.some((m) => m.name.toUpperCase() === name.toUpperCase());
  const all = new Map<string, InterfaceType>();
  for (const [key, first] of own) {
    const properties: Member[] = [];
    const methods: LibraryEntry[] = [];
    const seen = new Set<string>();
    const queue = [key];
    while (queue.length) {
      const next = own.get(queue.shift()!);
      if (!next || seen.has(next.name.toUpperCase())) continue;
      seen.add(next.name.toUpperCase());
      properties.push(...next.properties.filter((p) => !has(properties, p.name)));
      methods.push(...next.methods.filter((m) => !has(methods, m.name)));
      queue.push(...next.bases);
    }
    all.set(key, { name: first.name, properties, methods });
  }
  return all;
}
