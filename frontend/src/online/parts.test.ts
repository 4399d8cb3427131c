import { describe, expect, it } from "vitest";
import { emptyMonitor } from "./monitor";
import { partElements, partMonitor } from "./parts";

describe("an SFC part's diagram online", () => {
  it("subscribes its ids under the part's path", () => {
    const elements = [{ pou_instance: "MAIN", ids: ["c1", "add.OUT"] }];
    expect(partElements(elements, "actions/Fill")).toEqual([
      { pou_instance: "MAIN", ids: ["actions/Fill/c1", "actions/Fill/add.OUT"] },
    ]);
    expect(partElements(elements)).toEqual(elements);
  });

  it("reads only the part's power, without the prefix", () => {
    const monitor = {
      ...emptyMonitor,
      power: { "MAIN/c1": false, "MAIN/actions/Fill/c1": true, "MAIN/actions/Drain/c1": null, "MAIN/s1": true },
    };
    expect(partMonitor(monitor, "MAIN", "actions/Fill").power).toEqual({ "MAIN/c1": true });
    expect(partMonitor(monitor, "MAIN")).toBe(monitor);
  });
});
