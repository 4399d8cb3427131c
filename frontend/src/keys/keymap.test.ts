// @vitest-environment jsdom
import { describe, expect, it } from "vitest";
import { COMMANDS } from "../ld/editor/commands";
import { LD_EDITOR_KEYS } from "../ld/editor/LdEditor";
import { codeMirrorKeys, commandsFor, KEYMAP, keysOf, matches, RESERVED_KEYS, type KeyScope } from "./keymap";

const press = (key: string, mods: { ctrl?: boolean; alt?: boolean; shift?: boolean; meta?: boolean } = {}) => ({
  key,
  ctrlKey: mods.ctrl ?? false,
  altKey: mods.alt ?? false,
  shiftKey: mods.shift ?? false,
  metaKey: mods.meta ?? false,
});

describe("the keymap (issue 17: one table for every editor and the help)", () => {
  it("binds CODESYS's keys for online mode and debugging, and build/check to a key of its own", () => {
    const app = (key: string, mods = {}) => commandsFor("app", press(key, mods));
    expect(app("F7")).toEqual(["force-prepared"]);
    expect(app("F7", { ctrl: true })).toEqual(["write-prepared"]);
    expect(app("F7", { alt: true })).toEqual(["release-forces"]);
    expect(app("F5")).toEqual(["run"]);
    expect(app("F5", { shift: true })).toEqual(["stop"]);
    expect(app("F5", { ctrl: true })).toEqual(["single-cycle"]);
    expect(app("F10")).toEqual(["step-over"]);
    expect(app("F11")).toEqual(["step-into"]);
    expect(app("F11", { shift: true })).toEqual(["step-out"]);
    expect(app("F8", { alt: true })).toEqual(["go-online"]);
    expect(app("F8", { ctrl: true })).toEqual(["go-offline"]);
    expect(app("B", { ctrl: true, shift: true })).toEqual(["check"]);
    expect(app("s", { meta: true })).toEqual(["save"]); // Cmd counts as Ctrl
    expect(KEYMAP.filter((b) => b.command === "check").map((b) => b.keys)).not.toContain("F7");
    for (const scope of ["ld", "fbd", "st"] as const) expect(keysOf(scope, "toggle-breakpoint")).toBe("F9");
  });

  it("does nothing for a modifier combination it does not list", () => {
    for (const [key, mods] of [
      ["F5", { alt: true }],
      ["F5", { ctrl: true, shift: true }],
      ["F7", { shift: true }],
      ["F7", { ctrl: true, alt: true }],
      ["F8", {}],
      ["F8", { ctrl: true, alt: true }],
      ["F10", { ctrl: true }],
      ["F11", { alt: true }],
      ["s", { ctrl: true, alt: true }],
    ] as const)
      expect(commandsFor("app", press(key, mods)), `${key} ${JSON.stringify(mods)}`).toEqual([]);
    expect(matches("Ctrl+Y / Ctrl+Shift+Z", press("z", { ctrl: true }))).toBe(false);
    expect(matches("Ctrl+Y / Ctrl+Shift+Z", press("Z", { ctrl: true, shift: true }))).toBe(true);
    expect(matches("Space", press(" "))).toBe(true);
  });

  it("has one binding per command and scope, and no key twice in a scope except the LD mode digits", () => {
    const seen = new Set<string>();
    const keys = new Map<string, string[]>();
    for (const b of KEYMAP) {
      const id = `${b.scope}:${b.command}`;
      expect(seen.has(id), id).toBe(false);
      seen.add(id);
      for (const alternative of b.keys.split(" / ")) {
        const key = `${b.scope}:${alternative.toLowerCase()}`;
        keys.set(key, [...(keys.get(key) ?? []), b.command]);
      }
    }
    const shared = [...keys].filter(([, commands]) => commands.length > 1).map(([key]) => key);
    expect(shared.sort()).toEqual(["ld:1", "ld:2", "ld:3", "ld:4"]); // a contact's or a coil's mode
  });

  it("names only LD commands the editor has: its editing commands or its own keys", () => {
    const known = new Set<string>([...COMMANDS.map((c) => c.id), ...LD_EDITOR_KEYS]);
    const ld = KEYMAP.filter((b) => b.scope === "ld").map((b) => b.command);
    expect(ld.filter((c) => !known.has(c))).toEqual([]);
    // every LD command that had a key before the keymap still has one
    for (const id of ["contact", "coil", "box", "delete", "undo", "redo", "network-add", "coil-mode-n"])
      expect(keysOf("ld", id), id).not.toBe("");
  });

  it("zooms the diagrams by the keymap: Ctrl+=, Ctrl++ (with or without Shift), Ctrl+-, Ctrl+0, and fit on Ctrl+Shift+H", () => {
    const ld = (key: string, mods = {}) => commandsFor("ld", press(key, { ctrl: true, ...mods }));
    expect(ld("=")).toEqual(["zoom-in"]);
    expect(ld("+", { shift: true })).toEqual(["zoom-in"]);
    expect(ld("+")).toEqual(["zoom-in"]); // the numeric keypad's plus
    expect(ld("-")).toEqual(["zoom-out"]);
    expect(ld("0")).toEqual(["zoom-reset"]);
    for (const scope of ["ld", "fbd", "sfc"] as const)
      expect(commandsFor(scope, press("H", { ctrl: true, shift: true })), scope).toEqual(["zoom-fit"]);
    expect(ld("h")).toEqual([]);
  });

  it("keeps the browser from acting on the function keys it binds (F5 never reloads the page)", () => {
    expect([...RESERVED_KEYS].sort()).toEqual(["F10", "F11", "F12", "F2", "F5", "F7", "F8", "F9"]);
  });

  it("spells keys for CodeMirror", () => {
    expect(codeMirrorKeys("Ctrl+Shift+[")).toEqual(["Mod-Shift-["]);
    expect(codeMirrorKeys("Ctrl+Y / Ctrl+Shift+Z")).toEqual(["Mod-y", "Mod-Shift-z"]);
    expect(codeMirrorKeys("Tab / Shift+Tab")).toEqual(["Tab", "Shift-Tab"]);
    expect(codeMirrorKeys("Ctrl+Space")).toEqual(["Mod-Space"]);
  });

  it("lists every scope in the help", () => {
    const scopes: KeyScope[] = ["app", "ld", "fbd", "st"];
    for (const scope of scopes) expect(KEYMAP.some((b) => b.scope === scope)).toBe(true);
  });
});
