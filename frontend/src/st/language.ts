// IEC 61131-3 Structured Text for CodeMirror 6 as a StreamLanguage (no Lezer grammar): comments
// ((* *), /* */ and //, block comments span lines), pragmas ({...}), strings, typed and time
// literals (16#FF, T#5s, INT#3), numbers, keywords, elementary/standard FB types, operators. SFC's words (STEP,
// ACTION, ...) are keywords only in a textual SFC body, which starts with INITIAL_STEP, and ACTION heading a function
// block's action (`ACTION Reset:`): elsewhere they are names.
// The token names are CodeMirror's standard tags, so the editor's highlight style (highlightStyle.ts) colours them.
// Keywords and type names are the backend's (iec/vocabulary.ts).
import { StreamLanguage, StringStream, type StreamParser } from "@codemirror/language";
import { KEYWORDS, SFC_WORDS, TEST_FILE_KEYWORDS, TYPE_WORDS } from "../iec/vocabulary";

const ATOMS = new Set(["TRUE", "FALSE"]);

/** Inside a block comment or a pragma that continues on the next line; inside a textual SFC body. */
export interface StState {
  open: null | "paren" | "slash" | "pragma";
  /** An SFC body began (INITIAL_STEP) and its POU has not ended: SFC words are keywords (SFC_WORDS). */
  sfc: boolean;
}

/** What follows ACTION in a function block's action outside SFC (`ACTION Reset:`), where it is the keyword too. */
const ACTION_HEAD = /^\s+[A-Za-z_][A-Za-z0-9_]*\s*:(?!=)/;

/** The ends of the POUs a textual SFC body may be in: SFC words are names again after them. */
const POU_ENDS = new Set(["END_PROGRAM", "END_FUNCTION_BLOCK"]);

const CLOSER = { paren: "*)", slash: "*/", pragma: "}" } as const;

/** Consumes up to and including `closer`; true when it was found on this line. */
function skipTo(stream: StringStream, closer: string): boolean {
  const rest = stream.string.slice(stream.pos);
  const at = rest.indexOf(closer);
  if (at < 0) {
    stream.skipToEnd();
    return false;
  }
  stream.pos += at + closer.length;
  return true;
}

/** The ST tokenizer with `keywords` as its keywords (test files add their verbs: docs/testing.md). */
function makeStParser(name: string, keywords: ReadonlySet<string>): StreamParser<StState> {
  return {
    name,
    startState: () => ({ open: null, sfc: false }),
    copyState: (s) => ({ open: s.open, sfc: s.sfc }),
    token(stream, state) {
      if (state.open) {
        const kind = state.open;
        if (skipTo(stream, CLOSER[kind])) state.open = null;
        return kind === "pragma" ? "meta" : "comment";
      }
      if (stream.eatSpace()) return null;
      if (stream.match("//")) {
        stream.skipToEnd();
        return "lineComment";
      }
      for (const [opener, kind] of [
        ["(*", "paren"],
        ["/*", "slash"],
        ["{", "pragma"],
      ] as const) {
        if (stream.match(opener)) {
          if (!skipTo(stream, CLOSER[kind])) state.open = kind;
          return kind === "pragma" ? "meta" : "comment";
        }
      }
      if (stream.match(/^'(\$.|[^'$])*'?/) || stream.match(/^"(\$.|[^"$])*"?/)) return "string";
      if (stream.match(/^([A-Za-z_]+|\d+)#[A-Za-z0-9_.:+\-#]+/)) return "number";
      if (stream.match(/^\d[\d_]*(\.\d[\d_]*)?([eE][+-]?\d+)?/)) return "number";
      const word = stream.match(/^[A-Za-z_][A-Za-z0-9_]*/) as RegExpMatchArray | null;
      if (word) {
        const upper = word[0].toUpperCase();
        if (ATOMS.has(upper)) return "atom";
        if (upper === "INITIAL_STEP") state.sfc = true;
        else if (POU_ENDS.has(upper)) state.sfc = false;
        if (SFC_WORDS.has(upper) && !state.sfc && !(upper === "ACTION" && stream.match(ACTION_HEAD, false)))
          return "variableName";
        if (keywords.has(upper)) return "keyword";
        if (TYPE_WORDS.has(upper)) return "typeName";
        return "variableName";
      }
      if (stream.match(/^(:=|=>|<=|>=|<>|\*\*|[-+*/=<>&^])/)) return "operator";
      if (stream.match(/^[()[\]]/)) return "bracket";
      stream.next();
      return "punctuation";
    },
    languageData: { commentTokens: { line: "//", block: { open: "(*", close: "*)" } } },
  };
}

export const stParser = makeStParser("iec-st", KEYWORDS);
export const stLanguage = StreamLanguage.define(stParser);
/** Test files: ST with TEST, SETUP, MOCK, ... and the verbs (ASSERT_EQ, RUN_SCANS, ...) as keywords. */
export const stTestLanguage = StreamLanguage.define(makeStParser("iec-st-test", TEST_FILE_KEYWORDS));

/** One token of a text: document offsets, its style (null for spaces) and whether a block comment or pragma continues after it. */
export interface Token {
  from: number;
  to: number;
  style: string | null;
  text: string;
  continues: boolean;
}

/**
 * Every token of `text`, line by line with the parser state carried over, as the editor's
 * highlighter sees them; END_* matching, folding and inline values read the same tokens, so a
 * keyword in a comment or a string is never taken for code.
 */
export function tokenize(text: string): Token[] {
  const state = stParser.startState!(2);
  const out: Token[] = [];
  let offset = 0;
  for (const line of text.split("\n")) {
    const stream = new StringStream(line, 4, 2);
    while (!stream.eol()) {
      stream.start = stream.pos;
      const style = stParser.token(stream, state);
      out.push({
        from: offset + stream.start,
        to: offset + stream.pos,
        style,
        text: stream.current(),
        continues: state.open !== null,
      });
    }
    offset += line.length + 1;
  }
  return out;
}
