import { describe, expect, it } from "vitest";
import { instanceLabel, renameTask, runsOf } from "./tasks";

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

describe("renameTask (issue 22: rename a task from the tree)", () => {
  const fast = { name: "Fast", interval: "T#10ms", priority: 0, programs: ["Main"] };
  const slow = { name: "Slow", interval: "T#100ms", priority: 1, programs: [] };

  it("renames the project's task and keeps everything else", () => {
    expect(renameTask({ name: "p", tasks: [fast, slow] }, "Fast", " Quick ")).toEqual({
      name: "p",
      tasks: [{ ...fast, name: "Quick" }, slow],
    });
  });

  it("renames a task of a configuration's resource", () => {
    const project = { name: "p", configuration: { name: "C", resources: [{ name: "R", tasks: [slow] }] } };
    expect(renameTask(project, "Slow", "Background")).toEqual({
      name: "p",
      configuration: { name: "C", resources: [{ name: "R", tasks: [{ ...slow, name: "Background" }] }] },
    });
  });

  it("refuses a name that is no identifier or another task's (case-insensitive), but allows a change of case", () => {
    const project = { name: "p", tasks: [fast, slow] };
    expect(renameTask(project, "Fast", "2fast")).toBe(
      "2fast is not an IEC identifier (letters, digits and _, not starting with a digit).",
    );
    expect(renameTask(project, "Fast", "SLOW")).toBe("There is already a task called SLOW.");
    expect(renameTask(project, "Fast", "FAST")).toEqual({ name: "p", tasks: [{ ...fast, name: "FAST" }, slow] });
  });
});
