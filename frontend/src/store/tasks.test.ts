import { describe, expect, it } from "vitest";
import { asInstance } from "./bindings";
import { duplicateTask, withoutTask, instanceLabel, renameTask, runsOf, taskCopyName } from "./tasks";
import type { Project } from "../generated/api";

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

describe("duplicating a task (issue 22 item 1)", () => {
  it("copies it right after itself under a free name, each program as an instance of its own", () => {
    const project = {
      name: "p",
      pous: [{ name: "Main_copy", kind: "function" as const, language: "st" as const, body: "" }],
      tasks: [
        {
          name: "Fast",
          interval: "T#5ms",
          priority: 2,
          watchdog_ms: 20,
          programs: ["Main", { name: "Pump1", type: "Pump", inputs: { Start: "Go" }, outputs: {} }],
        },
        { name: "Fast_copy", interval: "T#50ms", programs: [] },
        { name: "Slow", interval: "T#100ms", programs: [{ name: "Pump1_copy", type: "Pump" }] },
      ],
    };
    expect(taskCopyName(project, "Fast")).toBe("Fast_copy2");
    const result = duplicateTask(project, "Fast", "Fast_copy2") as Project;
    expect(result.tasks!.map((t) => t.name)).toEqual(["Fast", "Fast_copy2", "Fast_copy", "Slow"]);
    expect(result.tasks![1]).toEqual({
      name: "Fast_copy2",
      interval: "T#5ms",
      priority: 2,
      watchdog_ms: 20,
      programs: [
        // Main_copy is a POU's name, Pump1_copy another instance's
        { name: "Main_copy2", type: "Main", inputs: {}, outputs: {} },
        { name: "Pump1_copy2", type: "Pump", inputs: { Start: "Go" }, outputs: {} },
      ],
    });
    expect(result.tasks![0]).toBe(project.tasks[0]); // the original is untouched
    expect(withoutTask(result, "Fast").tasks!.map((t) => t.name)).toEqual(["Fast_copy2", "Fast_copy", "Slow"]);
    expect(duplicateTask(project, "Nothing", "X")).toBe("There is no task Nothing.");
    expect(duplicateTask(project, "Fast", "slow")).toBe("There is already a task called slow.");
    expect(duplicateTask(project, "Fast", "2x")).toMatch(/^2x is not an IEC identifier/);
  });

  it("copies a configuration's task inside its resource", () => {
    const project = {
      name: "p",
      configuration: {
        name: "Cell",
        resources: [
          { name: "Cpu", tasks: [{ name: "T1", programs: ["Main"] }], programs: [{ name: "Main_copy", type: "Main" }] },
        ],
      },
    };
    const result = duplicateTask(project, "T1", taskCopyName(project, "T1")) as Project;
    const tasks = result.configuration!.resources![0]!.tasks!;
    expect(tasks.map((t) => [t.name, asInstance(t.programs![0]!).name])).toEqual([
      ["T1", "Main"],
      ["T1_copy", "Main_copy2"],
    ]);
  });
});
