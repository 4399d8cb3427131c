// The declarations of a POU as table rows, read from and written back to the ST text of its
// VAR ... END_VAR blocks (the text is what the project stores; docs/st.md). Reading is a small
// scanner that respects comments and strings; anything the table cannot hold without losing it
// (a comment between declarations, a pragma, text outside a block) makes the text "not tabular",
// and the table then stays read-only so the text view is the place to edit it.

/** A block keyword with its qualifier, as the class column shows it: "VAR", "VAR_INPUT", "VAR CONSTANT", ... */
export type VarClass = string;

export const VAR_CLASSES: readonly VarClass[] = [
  "VAR",
  "VAR_INPUT",
  "VAR_OUTPUT",
  "VAR_IN_OUT",
  "VAR_TEMP",
  "VAR_EXTERNAL",
  "VAR CONSTANT",
  "VAR RETAIN",
  "VAR_GLOBAL",
  "VAR_GLOBAL CONSTANT",
  "VAR_GLOBAL RETAIN",
];

export interface DeclRow {
  name: string;
  varClass: VarClass;
  type: string;
  initial: string;
  address: string;
  comment: string;
  /** 1-based line of the declaration in the text it was read from (diagnostics point at lines). */
  line?: number;
}

export type ParseResult = { ok: true; rows: DeclRow[] } | { ok: false; error: string; line: number };

const BLOCK = /^(VAR(?:_INPUT|_OUTPUT|_IN_OUT|_TEMP|_EXTERNAL|_GLOBAL)?)\b/i;
const QUALIFIER = /^(CONSTANT|RETAIN|NON_RETAIN|PERSISTENT)\b/i;
const NAME = /^[A-Za-z_][A-Za-z0-9_]*/;

/** The declaration text as rows, or where the table cannot follow it. */
export function parseDeclarations(text: string): ParseResult {
  const rows: DeclRow[] = [];
  let i = 0;
  const lineAt = (pos: number) => text.slice(0, pos).split("\n").length;
  const fail = (error: string, pos = i): ParseResult => ({ ok: false, error, line: lineAt(pos) });
  const skipSpace = () => {
    while (i < text.length && /\s/.test(text[i]!)) i += 1;
  };
  /** A comment at i: its inner text and where it ends, else null. */
  const comment = (): { body: string; end: number } | null => {
    if (text.startsWith("(*", i)) {
      const end = text.indexOf("*)", i + 2);
      return end < 0 ? null : { body: text.slice(i + 2, end).trim(), end: end + 2 };
    }
    if (text.startsWith("//", i)) {
      const end = text.indexOf("\n", i);
      const stop = end < 0 ? text.length : end;
      return { body: text.slice(i + 2, stop).trim(), end: stop };
    }
    return null;
  };
  /** Raw text up to one of `stops` at nesting depth 0, outside strings and comments. */
  const until = (stops: string[]): string | null => {
    const start = i;
    let depth = 0;
    while (i < text.length) {
      const c = text[i]!;
      if (depth === 0 && stops.some((s) => text.startsWith(s, i))) return text.slice(start, i).trim();
      if (c === "'" || c === '"') {
        const close = text.indexOf(c, i + 1);
        if (close < 0) return null;
        i = close + 1;
        continue;
      }
      if (text.startsWith("(*", i)) return null; // a comment inside a declaration: not tabular
      if (c === "(" || c === "[") depth += 1;
      if (c === ")" || c === "]") depth -= 1;
      i += 1;
    }
    return null;
  };

  for (;;) {
    skipSpace();
    if (i >= text.length) return { ok: true, rows };
    const block = BLOCK.exec(text.slice(i));
    if (!block) return fail(comment() ? "a comment outside a declaration" : "text outside a VAR ... END_VAR block");
    i += block[0].length;
    let varClass = block[1]!.toUpperCase();
    const rest = text.slice(i).replace(/^[ \t]+/, "");
    const qualifier = QUALIFIER.exec(rest);
    if (qualifier) {
      i += text.slice(i).length - rest.length + qualifier[0].length;
      varClass += ` ${qualifier[1]!.toUpperCase()}`;
    }
    for (;;) {
      skipSpace();
      if (i >= text.length) return fail(`${varClass} has no END_VAR`);
      if (/^END_VAR\b/i.test(text.slice(i))) {
        i += "END_VAR".length;
        break;
      }
      if (comment()) return fail("a comment between declarations");
      const start = i;
      const names: string[] = [];
      for (;;) {
        const name = NAME.exec(text.slice(i));
        if (!name) return fail("a variable name was expected");
        names.push(name[0]);
        i += name[0].length;
        skipSpace();
        if (text[i] !== ",") break;
        i += 1;
        skipSpace();
      }
      let address = "";
      if (/^AT\b/i.test(text.slice(i))) {
        i += 2;
        skipSpace();
        const at = /^%[A-Za-z0-9_.*]+/.exec(text.slice(i));
        if (!at) return fail("an address (%IX0.0) was expected after AT");
        address = at[0];
        i += at[0].length;
        skipSpace();
      }
      if (text[i] !== ":" || text[i + 1] === "=") return fail(`':' and a type were expected after ${names.join(", ")}`);
      i += 1;
      const type = until([":=", ";"]);
      if (type === null || !type) return fail(`the type of ${names.join(", ")} is missing or not tabular`);
      let initial = "";
      if (text.startsWith(":=", i)) {
        i += 2;
        const value = until([";"]);
        if (value === null || !value) return fail(`the initial value of ${names.join(", ")} is missing or not tabular`);
        initial = value;
      }
      i += 1; // ';'
      // A comment on the same line belongs to the declaration.
      const lineEnd = text.indexOf("\n", i);
      const tail = text.slice(i, lineEnd < 0 ? text.length : lineEnd);
      let note = "";
      const spaces = /^[ \t]*/.exec(tail)![0].length;
      i += spaces;
      const c = comment();
      if (c && !text.slice(i, c.end).includes("\n")) {
        note = c.body;
        i = c.end;
      } else i -= spaces;
      for (const name of names)
        rows.push({ name, varClass, type, initial, address, comment: note, line: lineAt(start) });
    }
  }
}

/**
 * The rows as declaration text: consecutive rows of one class share a block; in each block the names, colons and
 * trailing comments are aligned in columns (the backend's st/columns.py aligns exported declarations the same way;
 * both are tested against tests/fixtures/declaration_columns.json).
 */
export function printDeclarations(rows: readonly DeclRow[]): string {
  const blocks: DeclRow[][] = [];
  rows.forEach((r, index) => {
    if (index === 0 || rows[index - 1]!.varClass !== r.varClass) blocks.push([]);
    blocks[blocks.length - 1]!.push(r);
  });
  const head = (r: DeclRow) => `${r.name}${r.address ? ` AT ${r.address}` : ""}`;
  return blocks
    .map((block) => {
      const width = Math.max(0, ...block.map((r) => head(r).length));
      const lineOf = (r: DeclRow) =>
        `${head(r).padEnd(width)} : ${r.type.trim()}${r.initial.trim() ? ` := ${r.initial.trim()}` : ""};`;
      const codeWidth = Math.max(0, ...block.map((r) => lineOf(r).length));
      const lines = block.map((r) => {
        const code = lineOf(r);
        const note = r.comment.trim().replace(/\*\)/g, "* )");
        return `    ${note ? `${code.padEnd(codeWidth)}    (* ${note} *)` : code}`;
      });
      return [block[0]!.varClass, ...lines, "END_VAR"].join("\n");
    })
    .join("\n");
}

const BLOCK_HEAD = /^[ \t]*VAR(?:_INPUT|_OUTPUT|_IN_OUT|_TEMP|_EXTERNAL|_GLOBAL)?\b.*$/i;
const BLOCK_END = /^[ \t]*END_VAR\b/i;
/** One declaration alone on its line: names (and address), type and initial value, `;`, a trailing comment. */
const DECLARATION_LINE =
  /^[ \t]*([A-Za-z_]\w*(?:[ \t]*,[ \t]*[A-Za-z_]\w*)*(?:[ \t]+AT[ \t]+%[\w.*]+)?)[ \t]*:(?!=)[ \t]*((?:[^;'"(/]|\((?!\*)|\/(?!\/)|'[^']*'|"[^"]*")+?)[ \t]*;[ \t]*(\(\*(?:(?!\*\)).)*\*\)|\/\/.*)?[ \t]*$/;

/**
 * `text` with the declarations that stand alone on their lines aligned in columns, block by block, keeping every
 * token as typed and every other line as it is: the layout `printDeclarations` gives and the backend's
 * st/columns.py gives the ST export (tests/fixtures/declaration_columns.json).
 */
export function alignDeclarations(text: string): string {
  const lines = text.split("\n");
  let block: { line: number; head: string; rest: string; comment: string }[] | null = null;
  const flush = () => {
    if (!block?.length) return;
    const width = Math.max(...block.map((r) => r.head.length));
    const codes = block.map((r) => `${r.head.padEnd(width)} : ${r.rest};`);
    const codeWidth = Math.max(...codes.map((c) => c.length));
    block.forEach((r, i) => {
      lines[r.line] = `    ${r.comment ? `${codes[i]!.padEnd(codeWidth)}    ${r.comment}` : codes[i]!}`;
    });
  };
  lines.forEach((line, index) => {
    if (block === null) {
      if (BLOCK_HEAD.test(line) && !BLOCK_END.test(line) && !/\bEND_VAR\b/i.test(line)) block = [];
      return;
    }
    if (BLOCK_END.test(line)) {
      flush();
      block = null;
      return;
    }
    if (BLOCK_HEAD.test(line)) {
      block = []; // the block before had no END_VAR: its lines stay as they are
      return;
    }
    const match = DECLARATION_LINE.exec(line);
    if (match)
      block.push({
        line: index,
        head: match[1]!.replace(/\s+/g, " ").replace(/\s*,\s*/g, ", "),
        rest: match[2]!.trim(),
        comment: (match[3] ?? "").trim(),
      });
  });
  return lines.join("\n");
}

/** A name no row uses yet: `base`, else `base1`, `base2`, ... (case-insensitive like IEC). */
export function freeName(rows: readonly DeclRow[], base = "NewVar"): string {
  const used = new Set(rows.map((r) => r.name.toUpperCase()));
  if (!used.has(base.toUpperCase())) return base;
  let n = 1;
  while (used.has(`${base}${n}`.toUpperCase())) n += 1;
  return `${base}${n}`;
}

/** Names of the user types declared in the project's TYPE text (for the type autocomplete). */
export function userTypeNames(types: string): string[] {
  const names: string[] = [];
  const re = /(?:^|[;\s])([A-Za-z_][A-Za-z0-9_]*)\s*:\s*(?:STRUCT\b|\(|ARRAY\b|[A-Za-z_])/g;
  const body = types.replace(/\(\*[\s\S]*?\*\)|\/\/.*$/gm, " ");
  const inside = /\bTYPE\b([\s\S]*?)\bEND_TYPE\b/gi;
  for (let m = inside.exec(body); m; m = inside.exec(body)) {
    // Only names at the top level of the TYPE block: skip STRUCT members.
    const top = m[1]!.replace(/\bSTRUCT\b[\s\S]*?\bEND_STRUCT\b/gi, " STRUCT ");
    for (let t = re.exec(top); t; t = re.exec(top)) names.push(t[1]!);
  }
  return names;
}
