// Adding a variable to a POU's declaration text (the "declare variable" offer of the LD and FBD editors).
// One line goes into the first plain VAR block, or a new VAR block is appended; then the declarations
// are aligned in columns like the table prints them, when the table can read them (otherwise the text
// stays as the user typed it). The backend's checker reads the result like any other declaration.
import { alignDeclarations } from "../iec/declarations";

/** A variable to declare: the editors' "declare variable" offer. */
export interface VariableDeclaration {
  name: string;
  type: string;
}

const VAR_LINE = /^[ \t]*VAR[ \t]*(\(\*.*\*\))?[ \t]*$/i;
const END_VAR_LINE = /^[ \t]*END_VAR\b/i;

/** `declarations` with `name : type;` added to its first plain VAR block (or a new one). */
export function addDeclaration(declarations: string, name: string, type: string): string {
  return alignDeclarations(inserted(declarations, name, type));
}

function inserted(declarations: string, name: string, type: string): string {
  const lines = declarations.split("\n");
  const start = lines.findIndex((line) => VAR_LINE.test(line));
  if (start >= 0) {
    const end = lines.findIndex((line, i) => i > start && END_VAR_LINE.test(line));
    if (end > start) {
      const previous = lines.slice(start + 1, end).find((line) => line.trim());
      const indent = previous ? /^[ \t]*/.exec(previous)![0] : "    ";
      return [...lines.slice(0, end), `${indent}${name} : ${type};`, ...lines.slice(end)].join("\n");
    }
  }
  const block = `VAR\n    ${name} : ${type};\nEND_VAR`;
  return declarations.trim() ? `${declarations.replace(/\s+$/, "")}\n${block}` : block;
}
