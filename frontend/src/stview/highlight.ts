// A small ST tokenizer for read-only highlighting: comments, strings, typed literals (T#5s,
// 16#FF), numbers, keywords, identifiers and the rest. It never fails: text it does not know is
// "plain", and the tokens of a line always join back to the line. Keywords and type names are the
// backend's (iec/vocabulary.ts).

import { KEYWORDS, TYPE_WORDS as TYPES } from "../iec/vocabulary";

export type TokenKind = "comment" | "string" | "literal" | "number" | "keyword" | "type" | "name" | "plain";

export interface Token {
  kind: TokenKind;
  text: string;
}

const RULES: [TokenKind, RegExp][] = [
  ["comment", /\(\*[\s\S]*?(\*\)|$)|\/\/.*/y],
  ["string", /'(\$.|[^'$])*('|$)|"(\$.|[^"$])*("|$)/y],
  ["literal", /([A-Za-z_]+|\d+)#[A-Za-z0-9_.:+\-#]+/y],
  ["number", /\d[\d_]*(\.\d[\d_]*)?([eE][+-]?\d+)?/y],
  ["name", /[A-Za-z_][A-Za-z0-9_]*/y],
];

/** The tokens of one line (a comment left open continues only to the end of the line). */
export function tokenize(line: string): Token[] {
  const out: Token[] = [];
  let i = 0;
  let plain = "";
  const flush = () => {
    if (plain) out.push({ kind: "plain", text: plain });
    plain = "";
  };
  while (i < line.length) {
    let matched = false;
    for (const [kind, re] of RULES) {
      re.lastIndex = i;
      const m = re.exec(line);
      if (m && m[0].length) {
        flush();
        const upper = m[0].toUpperCase();
        out.push({
          kind: kind === "name" ? (KEYWORDS.has(upper) ? "keyword" : TYPES.has(upper) ? "type" : "name") : kind,
          text: m[0],
        });
        i += m[0].length;
        matched = true;
        break;
      }
    }
    if (!matched) plain += line[i++];
  }
  flush();
  return out;
}
