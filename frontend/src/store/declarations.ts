// Adding a variable to a declaration text (the declare dialog of the LD, FBD and ST editors): one line
// `name : type := initial; (* comment *)` goes into the first block of the chosen class (VAR when none is
// chosen), or a new block of that class is appended; then the declarations are aligned in columns like the
// table prints them, when the table can read them (otherwise the text stays as the user typed it). The
// backend's checker reads the result like any other declaration.
import { alignDeclarations } from "../iec/declarations";
import type { NewVariable } from "./newVariable";

/** A variable to declare: what the editors offer and the declare dialog completes. */
export type VariableDeclaration = NewVariable;

const END_VAR_LINE = /^[ \t]*END_VAR\b/i;

/** A block's opening line of exactly `varClass` ("VAR_INPUT", "VAR CONSTANT"), a trailing comment allowed. */
const blockStart = (varClass: string) =>
  new RegExp(`^[ \\t]*${varClass.trim().split(/\s+/).join("[ \\t]+")}[ \\t]*(\\(\\*.*\\*\\))?[ \\t]*$`, "i");

/** The declaration line of `v` without indentation. */
export function declarationLine(v: NewVariable): string {
  const initial = v.initial?.trim() ? ` := ${v.initial.trim()}` : "";
  const comment = v.comment?.trim() ? ` (* ${v.comment.trim().replace(/\*\)/g, "* )")} *)` : "";
  return `${v.name} : ${v.type}${initial};${comment}`;
}

/** `declarations` with `variable` added to its first block of its class (or a new one). */
export function addDeclaration(declarations: string, variable: NewVariable): string {
  return alignDeclarations(inserted(declarations, variable));
}

function inserted(declarations: string, variable: NewVariable): string {
  const varClass = variable.varClass?.trim() || "VAR";
  const line = declarationLine(variable);
  const lines = declarations.split("\n");
  const opening = blockStart(varClass);
  const start = lines.findIndex((l) => opening.test(l));
  if (start >= 0) {
    const end = lines.findIndex((l, i) => i > start && END_VAR_LINE.test(l));
    if (end > start) {
      const previous = lines.slice(start + 1, end).find((l) => l.trim());
      const indent = previous ? /^[ \t]*/.exec(previous)![0] : "    ";
      return [...lines.slice(0, end), `${indent}${line}`, ...lines.slice(end)].join("\n");
    }
  }
  const block = `${varClass}\n    ${line}\nEND_VAR`;
  return declarations.trim() ? `${declarations.replace(/\s+$/, "")}\n${block}` : block;
}
