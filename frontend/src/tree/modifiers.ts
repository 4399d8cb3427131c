// A method's or property's specifiers as the project tree and the Methods tab show them (issue 25). Here, below
// methods/, because the tree lists members under their FB and the Methods tab opens the tree's dialogs.
import type { Method } from "../generated/api";

export type Access = NonNullable<Method["access"]>;

/** A method's specifiers as the ST text writes them after METHOD: `PRIVATE FINAL` (PUBLIC left out). */
export function modifiersText(member: { access?: Access; final?: boolean; abstract?: boolean }): string {
  const words = [
    member.access && member.access !== "PUBLIC" ? member.access : "",
    member.final ? "FINAL" : "",
    member.abstract ? "ABSTRACT" : "",
  ];
  return words.filter(Boolean).join(" ");
}
