import { describe, expect, it } from "vitest";
import { instanceLabel, runsOf } from "./tasks";

describe("runsOf", () => {
  it("lists a project's own tasks with the programs they run", () => {
    expect(
      runsOf({ name: "p", tasks: [{ name: "Main", interval: "T#10ms", priority: 1, programs: ["Main", "Scaling"] }] }),
    ).toEqual({
      configuration: null,
      resources: [
        {
          name: null,
          on: null,
          tasks: [{ name: "Main", timing: "every T#10ms", priority: 1, instances: ["Main", "Scaling"] }],
          unscheduled: [],
        },
      ],
    });
  });

  it("lists a configuration's resources, SINGLE tasks and named instances", () => {
    const view = runsOf({
      name: "p",
      configuration: {
        name: "Plant",
        resources: [
          {
            name: "Cpu",
            on: "PLC",
            tasks: [
              { name: "event", interval: null, single: "go", programs: [{ name: "c", type: "Counter" }] },
              { name: "both", interval: "T#10ms", single: "hold", priority: 2, programs: [] },
            ],
            programs: [{ name: "loose", type: "Counter", retain: "RETAIN" }],
          },
        ],
      },
    });
    expect(view.configuration).toBe("Plant");
    expect(view.resources[0]!.tasks.map((t) => [t.name, t.timing, t.priority, t.instances])).toEqual([
      ["event", "on rising go", 0, ["c : Counter"]],
      ["both", "every T#10ms, on rising hold", 2, []],
    ]);
    expect(view.resources[0]!.unscheduled).toEqual(["loose : Counter (RETAIN)"]);
  });

  it("names an instance by its program when they share the name", () => {
    expect(instanceLabel({ name: "Main", type: "Main" })).toBe("Main");
  });
});
