// The names a METHOD's or property accessor's body reaches online (issue 25 item 6; ON-03, ON-09): the
// FB instance's variables, those it inherits through EXTENDS included (one instance holds them all), as
// paths of the instance shown; the member's own variables (and its result, named as the member) hide
// the FB's of the same name, as in the language, and show from the call stack instead (callValues.ts). The FB's
// variables with those it inherits are scope.ts `withInherited`.
import { declaredSymbols } from "./scope";

/** The upper-case names a member's own declarations (and its result, `name`) hide in its body. */
export function ownNames(name: string, declarations: string): ReadonlySet<string> {
  const own = declaredSymbols(declarations) ?? [];
  return new Set([name.toUpperCase(), ...own.map((s) => s.name.toUpperCase())]);
}
