// Issue 19 item 2 / issue 22 item 3: the browser's IEC words are the backend's, never a hand copy.
import { readdirSync, readFileSync, statSync } from "node:fs";
import { join, relative } from "node:path";
import { describe, expect, it } from "vitest";
import { IEC } from "../generated/iec";
import { FAMILY_DEFAULT } from "../ld/editor/declare";
import { formatValue } from "../online/values";
import { tokenize as stTokens } from "../st/language";
import { highlightLines } from "../stview/highlight";
import { DECLARABLE_TYPES, ELEMENTARY, FAMILIES, KEYWORDS, SFC_WORDS, TYPE_WORDS, widens } from "./vocabulary";

const SRC = join(__dirname, "..");

/** The class the read-only ST views give a word. */
const viewClass = (word: string) => highlightLines(word)[0]![0]!.className;

/** Every source file of the app but the generated ones, this folder and the tests. */
function sources(dir = SRC): string[] {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) return ["generated", "iec", "test"].includes(name) ? [] : sources(path);
    return /\.tsx?$/.test(name) && !/\.test\.tsx?$/.test(name) ? [path] : [];
  });
}

describe("the IEC vocabulary the browser reads", () => {
  it("offers the types the checker accepts in declarations: no CHAR or WCHAR, which it rejects", () => {
    // IEC 61131-3 elementary types LadderLab implements (docs/st.md), STRING and WSTRING with a length.
    expect([...DECLARABLE_TYPES].sort()).toEqual(
      [
        ...["BOOL", "SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT"],
        ...["BYTE", "WORD", "DWORD", "LWORD", "REAL", "LREAL", "TIME", "DATE", "TIME_OF_DAY", "DATE_AND_TIME"],
        ...["LTIME", "LDATE", "LTIME_OF_DAY", "LDATE_AND_TIME"],
        ...["STRING", "WSTRING"],
      ].sort(),
    );
    expect(DECLARABLE_TYPES).not.toContain("CHAR");
    expect(DECLARABLE_TYPES).not.toContain("WCHAR");
  });

  it("widens as IEC 61131-3 table 11 allows, and no other way", () => {
    expect(widens("SINT", "INT") && widens("USINT", "UINT") && widens("UINT", "DINT")).toBe(true);
    expect(widens("BYTE", "WORD") && widens("REAL", "LREAL")).toBe(true);
    expect(widens("INT", "SINT") || widens("INT", "REAL") || widens("UINT", "INT") || widens("BOOL", "BYTE")).toBe(
      false,
    );
  });

  it("highlights the backend's keywords and types the same in the ST editor and the read-only view", () => {
    for (const word of [...KEYWORDS].filter((w) => !SFC_WORDS.has(w))) {
      const kind = viewClass(word);
      const style = stTokens(word)[0]!.style;
      expect([word, kind, style]).toEqual([word, "st-keyword", ["TRUE", "FALSE"].includes(word) ? "atom" : "keyword"]);
    }
    for (const word of TYPE_WORDS) {
      expect([word, viewClass(word), stTokens(word)[0]!.style]).toEqual([word, "st-type", "typeName"]);
    }
    // Words the grammar does not know are names (CHAR was hand-copied once); CONTINUE is the grammar's now.
    expect(KEYWORDS).toContain("CONTINUE");
    for (const word of ["CHAR", "WCHAR"]) {
      expect([word, viewClass(word), stTokens(word)[0]!.style]).toEqual([word, "st-name", "variableName"]);
    }
  });

  it("highlights SFC's words as keywords only in an SFC body, from its INITIAL_STEP to its POU's end", () => {
    // docs/st.md: SFC words stay usable as names (OSCAT's `step`); the grammar's SFC body starts with INITIAL_STEP
    expect([...SFC_WORDS].sort()).toEqual(["ACTION", "FROM", "PRIORITY", "STEP", "TRANSITION"]);
    for (const word of SFC_WORDS) expect(KEYWORDS).toContain(word);
    const sfc = "INITIAL_STEP s0: END_STEP\nSTEP s1: END_STEP\nTRANSITION FROM s0 TO s1 := TRUE; END_TRANSITION";
    const classes = (text: string, word: string) => [
      ...new Set(highlightLines(text).flatMap((line) => line.filter((t) => t.text === word).map((t) => t.className))),
    ];
    const styles = (text: string, word: string) => [
      ...new Set(stTokens(text).flatMap((t) => (t.text === word ? [t.style] : []))),
    ];
    for (const word of ["STEP", "TRANSITION", "FROM"]) {
      expect([word, classes(sfc, word), styles(sfc, word)]).toEqual([word, ["st-keyword"], ["keyword"]]);
    }
    const names = "step := step + 1;\nIF Transition THEN Action := From; END_IF;";
    for (const word of ["step", "Transition", "Action", "From"]) {
      expect([word, classes(names, word), styles(names, word)]).toEqual([word, ["st-name"], ["variableName"]]);
    }
    // A function block's action outside SFC (CODESYS) is headed by the keyword; `action : BOOL` declares a name.
    const fb =
      "FUNCTION_BLOCK F\nVAR action : BOOL; END_VAR\nACTION Reset:\naction := FALSE;\nEND_ACTION\nEND_FUNCTION_BLOCK";
    expect(
      stTokens(fb)
        .filter((t) => t.text.toUpperCase() === "ACTION")
        .map((t) => [t.text, t.style]),
    ).toEqual([
      ["action", "variableName"],
      ["ACTION", "keyword"],
      ["action", "variableName"],
    ]);
    // A textual SFC body ends with its POU: the next POU's `step` is a name again.
    const two = `PROGRAM A\n${sfc}\nEND_PROGRAM\nPROGRAM B\nstep := 1;\nEND_PROGRAM`;
    expect(
      stTokens(two)
        .filter((t) => t.text.toUpperCase() === "STEP")
        .map((t) => [t.text, t.style]),
    ).toEqual([
      ["STEP", "keyword"],
      ["step", "variableName"],
    ]);
  });

  it("declares a variable on a generic pin with a member of the pin's family, for every family", () => {
    expect(Object.keys(FAMILY_DEFAULT).sort()).toEqual(Object.keys(FAMILIES).sort());
    for (const [family, type] of Object.entries(FAMILY_DEFAULT)) expect(FAMILIES[family]).toContain(type);
  });

  it("writes every monitored value as the engine's TO_STRING does", () => {
    for (const sample of IEC.value_texts) {
      expect([sample.type, sample.value, formatValue(sample.value, sample.type)]).toEqual([
        sample.type,
        sample.value,
        sample.text,
      ]);
    }
  });

  it("is never copied by hand into a feature: no source outside src/iec lists the elementary types", () => {
    const copies = sources().filter((path) => {
      const literals = readFileSync(path, "utf8").match(/"[^"\n]*"|'[^'\n]*'|`[^`]*`/g) ?? [];
      const named = new Set(
        literals.flatMap((l) => l.match(/\b[A-Z_]+\b/g) ?? []).filter((w) => ELEMENTARY.includes(w)),
      );
      return named.size >= 8;
    });
    expect(copies.map((path) => relative(SRC, path))).toEqual([]);
  });
});
