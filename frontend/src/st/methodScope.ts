// The names a METHOD's or property accessor's body reaches online (issue 25 item 6; ON-03, ON-09): the
// FB instance's variables, those it inherits through EXTENDS included (one instance holds them all), as
// paths of the instance shown; the member's own variables (and its result, named as the member) hide
// the FB's of the same name, as in the language, and show from the call stack instead (callValues.ts).
import type { Pou } from "../generated/api";
import type { Scope } from "./members";
import { declaredSymbols } from "./scope";

/** The upper-case names a member's own declarations (and its result, `name`) hide in its body. */
export function ownNames(name: string, declarations: string): ReadonlySet<string> {
  const own = declaredSymbols(declarations) ?? [];
  return new Set([name.toUpperCase(), ...own.map((s) => s.name.toUpperCase())]);
}

/**
 * The FB's scope with the variables of its base FBs (EXTENDS, nearest first) that it does not redeclare,
 * from the working copy; a cycle or an unknown base ends the walk (the check reports those).
 */
export function withInherited(scope: Scope, pou: Pou, pous: readonly Pou[]): Scope {
  const declared = (name: string) =>
    scope.symbols.some((t) => t.var_class !== "VAR_GLOBAL" && t.name.toUpperCase() === name.toUpperCase());
  const inherited: Scope["symbols"][number][] = [];
  const seen = new Set([pou.name.toUpperCase()]);
  let base = pou.extends?.trim().toUpperCase();
  while (base && !seen.has(base)) {
    seen.add(base);
    const fb = pous.find((p) => p.kind === "function_block" && p.name.toUpperCase() === base);
    if (!fb) break;
    for (const s of declaredSymbols(fb.declarations ?? "") ?? [])
      if (!declared(s.name) && !inherited.some((t) => t.name.toUpperCase() === s.name.toUpperCase())) inherited.push(s);
    base = fb.extends?.trim().toUpperCase();
  }
  // before the globals: an instance variable hides a global of the same name
  return inherited.length ? { ...scope, symbols: [...inherited, ...scope.symbols] } : scope;
}
