import { describe, expect, it, vi } from "vitest";
import { ApiError, type Api, type Health, type ProjectSummary } from "../api/client";
import { createAppStore } from "./workspace";

const demo: ProjectSummary = { name: "demo", revision: "r1", modified: "2024-01-01T00:00:00Z", pou_count: 2 };
const alpha: ProjectSummary = { name: "alpha", revision: "r7", modified: "2024-02-01T00:00:00Z", pou_count: 1 };

function fakeApi(overrides: Partial<Api> = {}): Api {
  return {
    getHealth: vi.fn(async (): Promise<Health> => ({ status: "ok", version: "0.1.0" })),
    listProjects: vi.fn(async () => [demo, alpha]),
    createProject: vi.fn(async (name: string) => ({
      name,
      revision: "r0",
      modified: "2024-03-01T00:00:00Z",
      pou_count: 0,
    })),
    ...overrides,
  };
}

/** A promise plus the functions that settle it, to control the order of answers. */
function deferred<T>() {
  let resolve!: (value: T) => void;
  let reject!: (reason: unknown) => void;
  const promise = new Promise<T>((res, rej) => {
    resolve = res;
    reject = rej;
  });
  return { promise, resolve, reject };
}

describe("projects", () => {
  it("starts idle and empty", () => {
    const s = createAppStore(fakeApi()).getState();
    expect(s.projectsStatus).toBe("idle");
    expect(s.projects).toEqual([]);
    expect(s.selectedProject).toBeNull();
  });

  it("loads the list sorted by name, going through 'loading'", async () => {
    const pending = deferred<ProjectSummary[]>();
    const store = createAppStore(fakeApi({ listProjects: () => pending.promise }));
    const done = store.getState().loadProjects();
    expect(store.getState().projectsStatus).toBe("loading");
    pending.resolve([demo, alpha]);
    await done;
    const s = store.getState();
    expect(s.projectsStatus).toBe("ready");
    expect(s.projects.map((p) => p.name)).toEqual(["alpha", "demo"]);
    expect(s.projectsError).toBeNull();
  });

  it("records the error message and empties the list when loading fails", async () => {
    const listProjects = vi
      .fn<Api["listProjects"]>()
      .mockResolvedValueOnce([demo])
      .mockRejectedValueOnce(new ApiError("Not Found", 404, "Not Found"));
    const store = createAppStore(fakeApi({ listProjects }));
    await store.getState().loadProjects();
    store.getState().selectProject("demo");
    await store.getState().loadProjects();
    const s = store.getState();
    expect(s.projectsStatus).toBe("error");
    expect(s.projectsError).toBe("Not Found");
    expect(s.projects).toEqual([]);
    expect(s.selectedProject).toBeNull();
  });

  it("clears a previous error on the next successful load", async () => {
    const listProjects = vi
      .fn<Api["listProjects"]>()
      .mockRejectedValueOnce(new Error("down"))
      .mockResolvedValueOnce([demo]);
    const store = createAppStore(fakeApi({ listProjects }));
    await store.getState().loadProjects();
    expect(store.getState().projectsError).toBe("down");
    await store.getState().loadProjects();
    expect(store.getState().projectsStatus).toBe("ready");
    expect(store.getState().projectsError).toBeNull();
  });

  it("ignores an older answer that arrives after a newer one", async () => {
    const first = deferred<ProjectSummary[]>();
    const second = deferred<ProjectSummary[]>();
    const listProjects = vi
      .fn<Api["listProjects"]>()
      .mockReturnValueOnce(first.promise)
      .mockReturnValueOnce(second.promise);
    const store = createAppStore(fakeApi({ listProjects }));
    const a = store.getState().loadProjects();
    const b = store.getState().loadProjects();
    second.resolve([alpha]);
    await b;
    first.reject(new Error("stale failure"));
    await a;
    expect(store.getState().projectsStatus).toBe("ready");
    expect(store.getState().projects).toEqual([alpha]);
  });

  it("selects only listed projects and keeps the selection across reloads while it exists", async () => {
    const listProjects = vi
      .fn<Api["listProjects"]>()
      .mockResolvedValueOnce([demo, alpha])
      .mockResolvedValueOnce([demo])
      .mockResolvedValueOnce([alpha]);
    const store = createAppStore(fakeApi({ listProjects }));
    await store.getState().loadProjects();
    store.getState().selectProject("ghost");
    expect(store.getState().selectedProject).toBeNull();
    store.getState().selectProject("demo");
    expect(store.getState().selectedProject).toBe("demo");
    await store.getState().loadProjects();
    expect(store.getState().selectedProject).toBe("demo");
    await store.getState().loadProjects();
    expect(store.getState().selectedProject).toBeNull();
    store.getState().selectProject("alpha");
    store.getState().selectProject(null);
    expect(store.getState().selectedProject).toBeNull();
  });
});

describe("health", () => {
  it("is ok with the version when the server says ok", async () => {
    const store = createAppStore(fakeApi());
    expect(store.getState().healthStatus).toBe("unknown");
    await store.getState().checkHealth();
    expect(store.getState().healthStatus).toBe("ok");
    expect(store.getState().health).toEqual({ status: "ok", version: "0.1.0" });
    expect(store.getState().healthError).toBeNull();
  });

  it("is down when the request fails, and recovers", async () => {
    const getHealth = vi
      .fn<Api["getHealth"]>()
      .mockRejectedValueOnce(new ApiError("Cannot reach the LadderLab server (Failed to fetch)", 0))
      .mockResolvedValueOnce({ status: "ok", version: "0.2.0" });
    const store = createAppStore(fakeApi({ getHealth }));
    await store.getState().checkHealth();
    expect(store.getState().healthStatus).toBe("down");
    expect(store.getState().health).toBeNull();
    expect(store.getState().healthError).toMatch(/Cannot reach/);
    await store.getState().checkHealth();
    expect(store.getState().healthStatus).toBe("ok");
    expect(store.getState().health?.version).toBe("0.2.0");
  });

  it("is down when the server reports a status other than ok", async () => {
    const store = createAppStore(fakeApi({ getHealth: async () => ({ status: "degraded", version: "1" }) }));
    await store.getState().checkHealth();
    expect(store.getState().healthStatus).toBe("down");
    expect(store.getState().healthError).toContain("degraded");
  });
});

describe("new project", () => {
  it("creates the project, reloads the list and selects it", async () => {
    const fresh: ProjectSummary = { name: "fresh", revision: "r0", modified: "2024-03-01T00:00:00Z", pou_count: 0 };
    const api = fakeApi({ listProjects: vi.fn(async () => [demo, fresh]) });
    const store = createAppStore(api);
    expect(await store.getState().createProject(" fresh ")).toBeNull();
    expect(api.createProject).toHaveBeenCalledWith("fresh");
    expect(store.getState().projects.map((p) => p.name)).toEqual(["demo", "fresh"]);
    expect(store.getState().selectedProject).toBe("fresh");
  });

  it("returns the server's refusal and keeps the selection", async () => {
    const api = fakeApi({
      createProject: vi.fn(async () => {
        throw new ApiError("a project named demo already exists", 409);
      }),
    });
    const store = createAppStore(api);
    await store.getState().loadProjects();
    store.getState().selectProject("alpha");
    expect(await store.getState().createProject("demo")).toBe("a project named demo already exists");
    expect(store.getState().selectedProject).toBe("alpha");
  });

  it("refuses an empty name without asking the server", async () => {
    const api = fakeApi();
    expect(await createAppStore(api).getState().createProject("  ")).toBe("Enter a name for the project.");
    expect(api.createProject).not.toHaveBeenCalled();
  });
});
