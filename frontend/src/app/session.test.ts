// @vitest-environment jsdom
import { describe, expect, it, vi } from "vitest";
import type { ProjectApi } from "../api/client";
import type { SimulationInfo } from "../generated/api";
import type { Project } from "../generated/api";
import { motorMain } from "../ld/fixtures";
import type { SimulationApi } from "../online/api";
import { createOnlineStore, type SocketLike } from "../online/store";
import { MemoryStorage } from "../test/memoryStorage";
import { traceStoreFor } from "../trace/store";
import { keepSession, lastProject, loadSession, rememberProject, restoreSession } from "./session";
import { createWorkspaceStore } from "../store/project";

const project: Project = {
  name: "demo",
  pous: [
    { name: "Main", kind: "program", language: "ld", declarations: "", body: motorMain },
    { name: "Calc", kind: "program", language: "st", declarations: "", body: "" },
    { name: "Types", kind: "program", language: "st", declarations: "", body: "" },
  ],
};

const simulation = (id: string, of = "demo") => ({ id, project: of, instances: {} }) as unknown as SimulationInfo;

function stores(running: string[] = []) {
  const api: ProjectApi = {
    getProject: vi.fn(async () => ({ name: "demo", revision: "r1", modified: "2024-05-01T10:00:00Z", project })),
    saveProject: vi.fn(),
    getLibrary: vi.fn(async () => []),
    getSymbols: vi.fn(async (_p: string, pou: string) => ({ pou, symbols: [], globals: [], diagnostics: [] })),
  };
  const sims: SimulationApi = {
    createSimulation: vi.fn(async () => simulation("s9")),
    getSimulation: vi.fn(async (id: string) => simulation(id)),
    listSimulations: vi.fn(async () => running.map((id) => simulation(id))),
    resetSimulation: vi.fn(),
    deleteSimulation: vi.fn(async () => undefined),
    seekScan: vi.fn(),
    goLive: vi.fn(),
  };
  const sockets: string[] = [];
  const socket = (url: string) => {
    sockets.push(url);
    return { readyState: 0, send: vi.fn(), close: vi.fn() } as unknown as SocketLike;
  };
  const online = createOnlineStore(sims, socket, (id) => `ws://test/${id}`);
  const storage = new MemoryStorage();
  return {
    workspace: createWorkspaceStore(api, storage),
    online,
    trace: traceStoreFor(online),
    storage,
    sockets,
  };
}

describe("the session of a project (issue 17: restored after a reload)", () => {
  it("keeps the watch list, its expanded rows, the trace setup, the tabs and the simulation, and restores them", async () => {
    const before = stores(["s1"]);
    await before.workspace.getState().open("demo");
    const stop = keepSession("demo", before, before.storage);
    before.workspace.getState().openPou("Main");
    before.workspace.getState().openPou("Calc");
    before.workspace.getState().openPou("Main");
    before.online.getState().addWatch("Main.RunTimer");
    before.online.getState().toggleWatchExpanded("Main.RunTimer");
    before.trace.getState().addPath("Main.RunTimer.ET");
    before.trace.getState().setCapacity(500);
    await before.online.getState().attach("demo", "s1");
    stop();
    before.online.getState().addWatch("after.stop"); // no longer kept

    // The page reloads: fresh stores, the same storage; the simulation still runs on the server.
    const after = stores(["s1"]);
    await after.workspace.getState().open("demo");
    expect(await restoreSession("demo", after, before.storage)).toBe(true);
    expect(after.online.getState()).toMatchObject({
      watch: ["Main.RunTimer"],
      watchExpanded: ["MAIN.RUNTIMER"],
      simulation: "s1",
      phase: "connecting",
    });
    expect(after.sockets).toEqual(["ws://test/s1"]);
    expect(after.trace.getState()).toMatchObject({ paths: ["Main.RunTimer.ET"], capacity: 500 });
    expect(after.workspace.getState()).toMatchObject({ tabs: ["Main", "Calc"], active: "Main" });
  });

  it("starts offline when the simulation is gone, and ignores an unreadable entry", async () => {
    const s = stores([]);
    s.storage.setItem("ladderlab:session:demo", JSON.stringify({ watch: ["A"], simulation: "gone" }));
    await s.workspace.getState().open("demo");
    expect(await restoreSession("demo", s, s.storage)).toBe(false);
    expect(s.online.getState()).toMatchObject({ phase: "offline", simulation: null, watch: ["A"] });
    s.storage.setItem("ladderlab:session:demo", "{not json");
    expect(loadSession("demo", s.storage)).toMatchObject({ watch: [], tabs: [], simulation: null });
  });

  it("opens the tabs of a session kept before the parts had their own keys as those parts (issue 22)", async () => {
    const s = stores([]);
    // kept by an older version: the parts' tabs were named by their labels, so "Types" was the Types editor
    const legacy = { tabs: ["Types", "Main", "Global variables", "Library manager"], active: "Types" };
    s.storage.setItem("ladderlab:session:demo", JSON.stringify(legacy));
    await s.workspace.getState().open("demo");
    await restoreSession("demo", s, s.storage);
    expect(s.workspace.getState()).toMatchObject({
      tabs: ["part:types", "Main", "part:globals", "part:libraries"],
      active: "part:types",
    });
    // the POU called Types has a tab of its own beside the Types editor, and both are kept under their keys
    const stop = keepSession("demo", s, s.storage);
    s.workspace.getState().openPou("Types");
    stop();
    expect(loadSession("demo", s.storage)).toMatchObject({
      tabs: ["part:types", "Main", "part:globals", "part:libraries", "Types"],
      active: "Types",
    });
  });

  it("remembers the project open last", () => {
    const storage = new MemoryStorage();
    expect(lastProject(storage)).toBeNull();
    rememberProject("demo", storage);
    expect(lastProject(storage)).toBe("demo");
  });
});
