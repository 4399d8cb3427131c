import { describe, expect, it } from "vitest";
import { instanceOf } from "./editorOnline";

describe("which instance an online view shows", () => {
  const choices = { MAIN: ["MAIN"], BLINKER: ["MAIN.BLINK"], PULSE: ["MAIN.P1", "MAIN.P2"] };

  it("shows a program (and a plant) itself and a function nothing", () => {
    expect(instanceOf({ kind: "program", name: "Main" }, {}, choices)).toBe("MAIN");
    expect(instanceOf({ kind: "plant", name: "Tank" }, {}, choices)).toBe("TANK");
    expect(instanceOf({ kind: "function", name: "Scale" }, {}, choices)).toBeNull();
  });

  it("shows a function block's only instance until the user picks one", () => {
    expect(instanceOf({ kind: "function_block", name: "Blinker" }, {}, choices)).toBe("MAIN.BLINK");
    expect(instanceOf({ kind: "function_block", name: "Blinker" }, { Blinker: "GVL.B2" }, choices)).toBe("GVL.B2");
  });

  it("asks which one when there are several, or when the simulation has none", () => {
    expect(instanceOf({ kind: "function_block", name: "Pulse" }, {}, choices)).toBeNull();
    expect(instanceOf({ kind: "function_block", name: "Pulse" }, { Pulse: "MAIN.P2" }, choices)).toBe("MAIN.P2");
    expect(instanceOf({ kind: "function_block", name: "Unused" }, {}, choices)).toBeNull();
  });
});
