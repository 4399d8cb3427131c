// REST calls of online mode (issue 6): create a simulation from the saved project, reset, read its
// statistics, delete it. Run, stop and single cycle go over the websocket with everything else.
import { http, unwrap } from "../api/client";
import type { HistoryDiff, HistoryMark, SimulationInfo } from "../generated/api";

const simulation = (sim_id: string) => ({ params: { path: { sim_id } } });

/** Compiles the saved project into a new simulation; a 422 ApiError carries the compile diagnostics. */
export function createSimulation(project: string): Promise<SimulationInfo> {
  return unwrap(http.POST("/api/projects/{name}/simulations", { params: { path: { name: project } } }));
}

/** Opens a recording (the file `ladderlab run --record` writes or "Download recording" gives) as a history-only
 * simulation of the saved project; `file` names it in the server's messages (409: another revision of the project,
 * 422: not a recording). */
export function openRecording(project: string, text: string, file: string): Promise<SimulationInfo> {
  return unwrap(
    http.POST("/api/projects/{name}/recordings", {
      params: { path: { name: project }, query: { file } },
      body: text,
      bodySerializer: (body: string) => body,
      headers: { "Content-Type": "application/json" },
    }),
  );
}

export function getSimulation(id: string): Promise<SimulationInfo> {
  return unwrap(http.GET("/api/simulations/{sim_id}", simulation(id)));
}

/** Every simulation the server runs (finding one this way asks nothing that may 404). */
export function listSimulations(): Promise<SimulationInfo[]> {
  return unwrap(http.GET("/api/simulations"));
}

/** Warm reset keeps RETAIN variables; cold resets everything to its initial value. */
export function resetSimulation(id: string, cold = false): Promise<SimulationInfo> {
  return unwrap(http.POST("/api/simulations/{sim_id}/reset", { ...simulation(id), body: { cold } }));
}

/** Shows past scan `scan` (numbered as `values.scan` numbers scans) until `goLive`; the live scans go on. A 409
 * ApiError says why it was refused, e.g. that its replay did not end within the server's history_timeout_s. */
export function seekScan(id: string, scan: number): Promise<SimulationInfo> {
  return unwrap(http.POST("/api/simulations/{sim_id}/seek", { ...simulation(id), body: { scan } }));
}

/** Shows the live scans again after `seekScan`. */
export function goLive(id: string): Promise<SimulationInfo> {
  return unwrap(http.POST("/api/simulations/{sim_id}/live", simulation(id)));
}

export async function deleteSimulation(id: string): Promise<void> {
  await unwrap(http.DELETE("/api/simulations/{sim_id}", simulation(id)));
}

/** What to look for in the scan history: where `path` changed, or where `condition` became TRUE. */
export type HistoryQuery = { path: string } | { condition: string };

/** The next (1) or previous (-1) scan from `scan` that the history finds for `query`; null: none kept. */
export async function findInHistory(
  id: string,
  scan: number,
  direction: 1 | -1,
  query: HistoryQuery,
): Promise<number | null> {
  const found = await unwrap(
    http.GET("/api/simulations/{sim_id}/history/find", {
      params: { path: { sim_id: id }, query: { scan, direction, ...query } },
    }),
  );
  return found.scan ?? null;
}

/** One step through the scan shown: the first replays it from the scan before and halts at its first network or
 * line, each next at the next one, `back` at the one before (the values come with the frames; `history.stepping`
 * says where). */
export function historyStep(
  id: string,
  granularity: "statement" | "over" | "back" = "statement",
): Promise<SimulationInfo> {
  return unwrap(http.POST("/api/simulations/{sim_id}/history/step", { ...simulation(id), body: { granularity } }));
}

/** The newest scans of the history with an input or a runtime error: the timeline's marks. */
export function historyMarks(id: string): Promise<HistoryMark[]> {
  return unwrap(http.GET("/api/simulations/{sim_id}/history/marks", simulation(id)));
}

/** The variables whose values differ between the ends of two scans of the history, with both values. */
export function historyDiff(id: string, first: number, second: number): Promise<HistoryDiff> {
  return unwrap(
    http.GET("/api/simulations/{sim_id}/history/diff", { params: { path: { sim_id: id }, query: { first, second } } }),
  );
}

/** The websocket address of a simulation, on the origin the app was served from. */
export function monitorUrl(id: string, location: Pick<Location, "protocol" | "host"> = window.location): string {
  return `${location.protocol === "https:" ? "wss" : "ws"}://${location.host}/api/simulations/${encodeURIComponent(id)}/ws`;
}

export interface SimulationApi {
  createSimulation(project: string): Promise<SimulationInfo>;
  getSimulation(id: string): Promise<SimulationInfo>;
  listSimulations(): Promise<SimulationInfo[]>;
  resetSimulation(id: string, cold?: boolean): Promise<SimulationInfo>;
  deleteSimulation(id: string): Promise<void>;
  seekScan(id: string, scan: number): Promise<SimulationInfo>;
  goLive(id: string): Promise<SimulationInfo>;
}

export const simulationApi: SimulationApi = {
  createSimulation,
  getSimulation,
  listSimulations,
  resetSimulation,
  deleteSimulation,
  seekScan,
  goLive,
};
