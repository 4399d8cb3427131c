// @vitest-environment jsdom
// The method and property operations of the Methods tab (issue 25): pure edits of a function block.
import { describe, expect, it } from "vitest";
import type { Method, Pou } from "../generated/api";
import { focusOf, methodPlace } from "../store/panels";
import {
  addMember,
  changeMember,
  deleteMember,
  memberFile,
  memberOf,
  renameMember,
  withModifier,
  type Edited,
} from "./members";
import { modifiersText } from "../tree/modifiers";

const fb: Pou = {
  name: "Counter",
  kind: "function_block",
  language: "st",
  declarations: "",
  body: "",
  methods: [
    { name: "Bump", access: "PUBLIC", final: false, abstract: false, return_type: null, declarations: "", body: "" },
  ],
  properties: [
    { name: "Level", type: "INT", access: "PUBLIC", get: { declarations: "", body: "Level := 1;" }, set: null },
  ],
};
const ok = (edited: Edited): Pou => {
  if (!edited.ok) throw new Error(edited.error);
  return edited.pou;
};

describe("methods and properties of a function block", () => {
  it("adds a method and a property with unique IEC names", () => {
    const added = ok(addMember(ok(addMember(fb, "method", " Scaled ")), "property", "Speed"));
    expect(added.methods!.map((m) => m.name)).toEqual(["Bump", "Scaled"]);
    expect(added.properties!.map((p) => [p.name, p.type, p.get?.body, p.set?.body])).toEqual([
      ["Level", "INT", "Level := 1;", undefined],
      ["Speed", "INT", "", ""],
    ]);
    expect(addMember(fb, "method", "level")).toEqual({
      ok: false,
      error: "Counter already has a property called Level.",
    });
    expect(addMember(fb, "property", "2x")).toMatchObject({
      ok: false,
      error: expect.stringMatching(/^2x is not an IEC/),
    });
    expect(addMember({ ...fb, kind: "function", return_type: "INT" }, "method", "M")).toEqual({
      ok: false,
      error: "Only a function block or a program has methods and properties.",
    });
    // a PROGRAM has them too (CODESYS): Main.M, called M() in it and Main.M() elsewhere
    const program = ok(addMember({ ...fb, name: "Main", kind: "program", methods: [], properties: [] }, "method", "M"));
    expect([program.kind, program.methods!.map((m) => [m.name, m.access, m.final, m.abstract])]).toEqual([
      "program",
      [["M", "PUBLIC", false, false]],
    ]);
  });

  it("renames (also in another case), changes and deletes one member", () => {
    expect(ok(renameMember(fb, "Bump", "BUMP")).methods![0]!.name).toBe("BUMP");
    expect(renameMember(fb, "Bump", "Level")).toEqual({
      ok: false,
      error: "Counter already has a property called Level.",
    });
    const changed = ok(changeMember(fb, "bump", (m) => ({ ...m, body: "n := n + 1;" })));
    expect(memberOf(changed, "BUMP")).toMatchObject({ kind: "method", member: { body: "n := n + 1;" } });
    expect(deleteMember(fb, "LEVEL").properties).toEqual([]);
    expect(changeMember(fb, "Nope", (m) => m)).toEqual({
      ok: false,
      error: "Counter has no method or property called Nope.",
    });
  });

  it("names a member's texts as the checker's diagnostics do", () => {
    expect(memberFile("Counter", "Bump", "body")).toBe("Counter.Bump/body");
    expect(memberFile("Counter", "Level", "declarations", "get")).toBe("Counter.Level.GET/declarations");
  });
});

describe("places in a member's texts", () => {
  it("a diagnostic in a method or accessor text reveals the member in its FB's Methods tab", () => {
    const inMethod = { code: "ST-TYPE", message: "", file: "Counter.Scaled/body", pou: "Counter.Scaled", line: 2 };
    expect(focusOf(inMethod)).toEqual({ pou: "Counter", member: "Scaled", accessor: null, line: 2, part: "body" });
    const inGet = { code: "X", message: "", file: "Counter.Level.GET/declarations", pou: "Counter.Level.GET", line: 1 };
    expect(focusOf(inGet)).toEqual({ pou: "Counter", member: "Level", accessor: "GET", line: 1, part: "declarations" });
    const inSet = { code: "X", message: "", file: "Counter.Level.SET/body", pou: "Counter.Level.SET", line: 3 };
    expect(focusOf(inSet)).toMatchObject({ member: "Level", accessor: "SET", part: "body" });
    expect(focusOf({ code: "X", message: "", file: "Main/body", pou: "Main", line: 3 })).toMatchObject({
      pou: "Main",
      part: "body",
    });
  });

  it("a halt in a method or accessor, named as the engine names it, is its FB, the member and the accessor", () => {
    expect(methodPlace("COUNTER.SCALED")).toEqual({ pou: "COUNTER", member: "SCALED", accessor: null });
    expect(methodPlace("TANK.LEVEL.SET")).toEqual({ pou: "TANK", member: "LEVEL", accessor: "SET" });
    expect(methodPlace("MAIN")).toBeNull();
  });
});

describe("method specifiers", () => {
  const bump: Method = { name: "Bump", access: "PUBLIC", final: false, abstract: false, declarations: "", body: "" };
  it("FINAL and ABSTRACT exclude each other: setting one clears the other, clearing leaves the other", () => {
    const final = withModifier(bump, "final", true);
    expect([final.final, final.abstract]).toEqual([true, false]);
    const abstract = withModifier(final, "abstract", true);
    expect([abstract.final, abstract.abstract]).toEqual([false, true]);
    expect(withModifier(abstract, "final", false).abstract).toBe(true);
  });
  it("exclude each other on a function block too", () => {
    const final = withModifier(fb, "final", true);
    expect([final.final, final.abstract, withModifier(final, "abstract", true).final]).toEqual([true, false, false]);
  });
  it("are written as ST writes them after METHOD, PUBLIC left out", () => {
    expect(modifiersText(bump)).toBe("");
    expect(modifiersText({ ...bump, access: "PRIVATE", final: true })).toBe("PRIVATE FINAL");
    expect(modifiersText({ ...bump, access: "PROTECTED", abstract: true })).toBe("PROTECTED ABSTRACT");
    expect(modifiersText({ access: "INTERNAL" })).toBe("INTERNAL");
  });
});
