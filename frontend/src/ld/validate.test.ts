import { describe, expect, it } from "vitest";
import { bodyOf, c, motorMain, net, par, q } from "./fixtures";
import type { LdNetwork } from "./model";
import { ldProblems } from "./validate";

describe("ldProblems", () => {
  it("accepts the motor example", () => {
    expect(ldProblems(motorMain)).toEqual([]);
  });

  it("reports duplicate ids, bad and duplicate labels (GR-03)", () => {
    const labelled = (id: string, label: string): LdNetwork => ({ ...net(id, c(`${id}c`)), label });
    const body = bodyOf(
      net("n1", c("a"), c("a")),
      labelled("n2", "Go"),
      labelled("n3", "GO"),
      labelled("n4", "1x"),
      net("n1"),
    );
    expect(ldProblems(body)).toEqual([
      { network: "n1", element: "a", message: "duplicate element id a" },
      { network: "n3", message: "label GO is used twice" },
      { network: "n4", message: 'label "1x" is not an identifier or number' },
      { network: "n1", message: "duplicate network id n1" },
    ]);
  });

  it("reports broken parallels, contacts after coils and misplaced jumps (issue 5 rules)", () => {
    const body = bodyOf(
      net("n1", par("p", [c("a")])),
      net("n2", par("p2", [c("b")], [])),
      net("n3", q("m"), c("d")),
      net("n4", { type: "jump", id: "j", target: "L" }, q("m2")),
    );
    expect(ldProblems(body)).toEqual([
      { network: "n1", element: "p", message: "a parallel needs at least two branches" },
      { network: "n2", element: "p2", message: "a parallel branch is empty" },
      { network: "n3", element: "d", message: "contact after a coil: coils come last" },
      { network: "n4", element: "j", message: "jump must be the last element of its branch" },
    ]);
  });

  it("accepts parallel coils and coils in series, refuses coils feeding a box pin", () => {
    expect(ldProblems(bodyOf(net("n1", c("a"), par("p", [q("m")], [c("b"), q("k")]), q("z"))))).toEqual([]);
    const box = { type: "box" as const, id: "b", call: "CTU", inputs: { R: [q("m")], PV: [] } };
    expect(ldProblems(bodyOf(net("n1", box)))).toEqual([
      { network: "n1", element: "b", message: "input PV is fed by an empty series" },
      { network: "n1", element: "m", message: "a box input cannot hold a coil" },
    ]);
  });
});
