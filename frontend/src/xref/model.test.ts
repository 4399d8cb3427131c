import { describe, expect, it } from "vitest";
import type { XrefEntry } from "../generated/api";
import { entryOf, filterEntries, placeOf, placeToReveal, rootOf } from "./model";

const entry = (name: string, pou: string | null, extra: Partial<XrefEntry> = {}): XrefEntry => ({
  name,
  pou,
  var_class: pou ? "VAR" : "VAR_GLOBAL",
  type: "BOOL",
  accesses: [],
  ...extra,
});

describe("cross references", () => {
  it("finds the variable an operand starts from", () => {
    expect(rootOf("RunTimer.Q")).toBe("RunTimer");
    expect(rootOf(" arr[i] ")).toBe("arr");
    expect(rootOf("NOT Stop")).toBe("Stop");
    expect(rootOf("%IX0.3")).toBe("%IX0.3");
    expect(rootOf("T#5s")).toBe("T");
    expect(rootOf("5")).toBeNull();
  });

  it("resolves an operand to the POU's own variable first, then the global (or its address)", () => {
    const entries = [entry("Motor", null, { address: "%QX0.0" }), entry("motor", "Other"), entry("Lamp", "Main")];
    expect(entryOf(entries, "MOTOR", "Main")).toBe(entries[0]);
    expect(entryOf(entries, "Motor", "other")).toBe(entries[1]);
    expect(entryOf(entries, "%qx0.0", "Main")).toBe(entries[0]);
    expect(entryOf(entries, "Lamp", "Other")).toBeNull();
  });

  it("filters by name, address, type, scope or comment", () => {
    const entries = [
      entry("Start", null, { address: "%IX0.0", comment: "push key" }),
      entry("RunTimer", "Main", { type: "TON" }),
    ];
    expect(filterEntries(entries, "ix0").map((e) => e.name)).toEqual(["Start"]);
    expect(filterEntries(entries, "ton").map((e) => e.name)).toEqual(["RunTimer"]);
    expect(filterEntries(entries, "global").map((e) => e.name)).toEqual(["Start"]);
    expect(filterEntries(entries, "KEY").map((e) => e.name)).toEqual(["Start"]);
    expect(filterEntries(entries, " ")).toHaveLength(2);
  });

  it("says where an access is and what to reveal", () => {
    const diagram = {
      kind: "write" as const,
      pou: "Main",
      network: "n3",
      network_number: 3,
      element: "ctu",
      operand: "StartCounter",
      path: "StartCount",
    };
    expect(placeOf(diagram)).toBe("Main, network 3 (StartCounter)");
    expect(placeToReveal(diagram)).toMatchObject({
      pou: "Main",
      network: "n3",
      element: "ctu",
      line: null,
      file: null,
    });
    const text = { kind: "read" as const, pou: "Blinker", line: 8, path: "Out" };
    expect(placeOf(text)).toBe("Blinker, line 8");
    expect(placeToReveal(text)).toMatchObject({
      pou: "Blinker",
      network: null,
      element: null,
      line: 8,
      file: "Blinker/body",
    });
    const declared = { kind: "declared" as const, pou: null, line: 2, path: "Start" };
    expect(placeOf(declared)).toBe("globals, declarations line 2");
    expect(placeOf({ ...declared, gvl: "GVL_IO" })).toBe("GVL_IO, declarations line 2"); // a global variable list's
    expect(placeToReveal(declared)).toBeNull();
    expect(placeToReveal({ ...declared, pou: "Main" })).toMatchObject({ line: 2, file: "Main/declarations" });
  });
});
