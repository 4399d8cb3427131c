import { describe, expect, it } from "vitest";
import { emptyMonitor, type MonitorState } from "../online/monitor";
import { elementText, type SfcBody } from "./model";
import { bindSfc, sfcOnlineView } from "./online";

/** Fill: N Pump (an action) and S Lamp (a BOOL variable); a transition on `full`; the jump back. */
const body: SfcBody = {
  chart: {
    elements: [
      { type: "step", id: "s1", name: "Init", actions: [] },
      { type: "transition", id: "t1", condition: "go" },
      {
        type: "step",
        id: "s2",
        name: "Fill",
        actions: [
          { id: "a1", qualifier: "N", action: "Pump" },
          { id: "a2", qualifier: "S", action: "Lamp" },
        ],
      },
      { type: "transition", id: "t2", condition: "full" },
      { type: "jump", id: "j1", target: "Init" },
    ],
  },
  actions: [{ name: "Pump", language: "st", body: "n := n + 1;" }],
  transitions: [],
};

describe("the SFC online binding (SFC-09)", () => {
  it("subscribes the steps' X and T, the actions' Q and A and the associated BOOL variables", () => {
    const binding = bindSfc(body, "MAIN");
    expect(binding.paths).toEqual([
      "MAIN.Init.X",
      "MAIN.Init.T",
      "MAIN.Fill.X",
      "MAIN.Fill.T",
      "MAIN.Pump.Q",
      "MAIN.Pump.A",
      "MAIN.Lamp",
    ]);
    expect(binding.elements[0]!.ids).toEqual(["s1", "s2", "t1", "t2", "t1.COND", "t2.COND"]);
  });

  it("shows active steps, their times, every condition, running actions and TRUE variables", () => {
    const monitor: MonitorState = {
      ...emptyMonitor,
      values: {
        "MAIN.INIT.X": false,
        "MAIN.FILL.X": true,
        "MAIN.FILL.T": 1200,
        "MAIN.PUMP.Q": false,
        "MAIN.PUMP.A": true, // its final run after Q fell
        "MAIN.LAMP": true,
      },
      forced: new Set(["MAIN.FILL.X"]),
      power: { "MAIN/t1.COND": true, "MAIN/t2.COND": false, "MAIN/t1": "on" },
    };
    const view = sfcOnlineView(monitor, bindSfc(body, "MAIN"));
    expect([...view.active]).toEqual(["s2"]);
    expect(view.times).toEqual({ s2: "T#1s200ms" });
    expect(view.conditions).toEqual({ t1: true, t2: false });
    expect([...view.fired]).toEqual(["t1"]);
    expect([...view.running].sort()).toEqual(["LAMP", "PUMP"]);
    expect([...view.flagged]).toEqual(["LAMP"]);
    expect([...view.forced]).toEqual(["s2"]);
  });
});

describe("elementText", () => {
  it("names steps and transitions in the user's words", () => {
    expect(elementText(body, "s2")).toBe("step Fill");
    expect(elementText(body, "t2")).toBe("transition full");
    expect(elementText(body, "j1")).toBeNull();
    expect(elementText(body, "nope")).toBeNull();
  });
});
