import { describe, expect, it } from "vitest";
import { describeTrigger, noTrigger, triggerOf } from "./trigger";

describe("triggerOf", () => {
  it("is no trigger without a path", () => {
    expect(triggerOf(noTrigger)).toEqual({ ok: true, trigger: null });
    expect(triggerOf({ path: "  ", condition: "cross_up", level: "x" })).toEqual({ ok: true, trigger: null });
  });

  it("sends edges without a level and crossings with the level as a number", () => {
    expect(triggerOf({ path: " Main.Go ", condition: "falling", level: "3" })).toEqual({
      ok: true,
      trigger: { path: "Main.Go", condition: "falling" },
    });
    expect(triggerOf({ path: "Main.T", condition: "cross_down", level: " -2.5 " })).toEqual({
      ok: true,
      trigger: { path: "Main.T", condition: "cross_down", level: -2.5 },
    });
  });

  it("names a missing or malformed level", () => {
    expect(triggerOf({ path: "Main.T", condition: "cross_up", level: "" })).toEqual({
      ok: false,
      error: "a level crossing needs a level",
    });
    expect(triggerOf({ path: "Main.T", condition: "cross_up", level: "T#5s" })).toEqual({
      ok: false,
      error: "the trigger level must be a number, not 'T#5s'",
    });
  });

  it("describes what the trace waits for", () => {
    expect(describeTrigger({ path: "MAIN.GO" })).toBe("MAIN.GO rising");
    expect(describeTrigger({ path: "MAIN.GO", condition: "falling" })).toBe("MAIN.GO falling");
    expect(describeTrigger({ path: "MAIN.T", condition: "cross_up", level: 50 })).toBe("MAIN.T crosses 50 upwards");
    expect(describeTrigger({ path: "MAIN.T", condition: "cross_down", level: 0 })).toBe("MAIN.T crosses 0 downwards");
  });
});
