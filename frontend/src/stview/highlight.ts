// A small ST tokenizer for read-only highlighting: comments, strings, typed literals (T#5s,
// 16#FF), numbers, keywords, identifiers and the rest. It never fails: text it does not know is
// "plain", and the tokens of a line always join back to the line.

export type TokenKind = "comment" | "string" | "literal" | "number" | "keyword" | "type" | "name" | "plain";

export interface Token {
  kind: TokenKind;
  text: string;
}

const KEYWORDS = new Set(
  (
    "PROGRAM END_PROGRAM FUNCTION END_FUNCTION FUNCTION_BLOCK END_FUNCTION_BLOCK VAR VAR_INPUT VAR_OUTPUT VAR_IN_OUT " +
    "VAR_TEMP VAR_GLOBAL VAR_EXTERNAL END_VAR CONSTANT RETAIN AT IF THEN ELSIF ELSE END_IF CASE OF END_CASE FOR TO BY DO " +
    "END_FOR WHILE END_WHILE REPEAT UNTIL END_REPEAT EXIT RETURN AND OR XOR NOT MOD TRUE FALSE TYPE END_TYPE STRUCT END_STRUCT ARRAY"
  ).split(" "),
);
const TYPES = new Set(
  (
    "BOOL SINT INT DINT LINT USINT UINT UDINT ULINT BYTE WORD DWORD LWORD REAL LREAL TIME DATE TIME_OF_DAY TOD DATE_AND_TIME DT " +
    "STRING WSTRING CHAR WCHAR TON TOF TP CTU CTD CTUD R_TRIG F_TRIG SR RS"
  ).split(" "),
);

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
