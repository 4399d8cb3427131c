import { describe, expect, it } from "vitest";
import { bodyOf, c, library, motorMain, net } from "../fixtures";
import { layoutBody } from "../layout";
import type { LdBody } from "../model";
import type { Selection } from "../view/types";
import { extend, navigate, type Direction } from "./navigation";

const layout = layoutBody(motorMain, { library });
const el = (id: string): Selection => ({ kind: "elements", ids: [id] });
function walkKeys(body: LdBody, from: Selection | null, keys: Direction[]): (Selection | null)[] {
  const l = body === motorMain ? layout : layoutBody(body, { library });
  const out: (Selection | null)[] = [];
  let s = from;
  for (const key of keys) {
    s = navigate(body, l, s, key);
    out.push(s);
  }
  return out;
}
const idsOf = (list: (Selection | null)[]) =>
  list.map((s) => (s?.kind === "elements" ? s.ids[0] : s?.kind === "network" ? `#${s.id}` : null));

describe("arrow keys", () => {
  it("starts at the first element of the first rung", () => {
    expect(navigate(motorMain, layout, null, "right")).toEqual(el("start_or_motor"));
  });

  it("moves right through a parallel's first branch and out after it", () => {
    expect(idsOf(walkKeys(motorMain, el("start_or_motor"), ["right", "right", "right", "right"]))).toEqual([
      "start",
      "stop",
      "motor",
      "motor",
    ]);
  });

  it("moves left to the end of a parallel's first branch, out to the parallel, then to the network", () => {
    expect(idsOf(walkKeys(motorMain, el("stop"), ["left", "left", "left", "left"]))).toEqual([
      "start",
      "start_or_motor",
      "#seal_in",
      "#seal_in",
    ]);
  });

  it("moves down to the lower branch and on to the nearest element of the next network", () => {
    expect(idsOf(walkKeys(motorMain, el("start"), ["down", "down", "up", "up"]))).toEqual([
      "seal",
      "motor_on",
      "seal",
      "start",
    ]);
  });

  it("goes from a box input series to the box and into the next network's rung", () => {
    expect(idsOf(walkKeys(motorMain, el("reset_count"), ["right", "down"]))).toEqual(["ctu", "reset_count"]);
    expect(idsOf(walkKeys(motorMain, el("ctu"), ["up"]))[0]).toBe("ton");
  });

  it("steps from a network header into its rung, and between headers", () => {
    expect(idsOf(walkKeys(motorMain, { kind: "network", id: "run_timer" }, ["down", "right"]))).toEqual([
      "#count_starts",
      "start_edge",
    ]);
    const empty = bodyOf(net("a", c("x")), net("b"));
    expect(idsOf(walkKeys(empty, el("x"), ["down", "right", "up"]))).toEqual(["#b", "#b", "#a"]);
  });

  it("moves from a selected wire to the element on either side", () => {
    const place: Selection = { kind: "place", place: { series: { kind: "network", network: "seal_in" }, index: 1 } };
    expect(navigate(motorMain, layout, place, "left")).toEqual(el("start_or_motor"));
    expect(navigate(motorMain, layout, place, "right")).toEqual(el("stop"));
  });

  it("extends a range only within one series", () => {
    expect(extend(motorMain, "stop", "stop", "left")).toBe("start_or_motor");
    expect(extend(motorMain, "start", "start", "right")).toBe("start");
  });
});
