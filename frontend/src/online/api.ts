// REST calls of online mode (issue 6): create a simulation from the saved project, reset, read its
// statistics, delete it. Run, stop and single cycle go over the websocket with everything else.
import { requestHeaders, requestJson } from "../api/client";
import type { HistoryDiff, HistoryFound, HistoryMark, SimulationInfo } from "../generated/api";

const simulationPath = (id: string) => `/api/simulations/${encodeURIComponent(id)}`;

/** Compiles the saved project into a new simulation; a 422 ApiError carries the compile diagnostics. */
export function createSimulation(project: string): Promise<SimulationInfo> {
  return requestJson<SimulationInfo>(`/api/projects/${encodeURIComponent(project)}/simulations`, {
    method: "POST",
    headers: { "Content-Type": "application/json" },
    body: "{}",
  });
}

export function getSimulation(id: string): Promise<SimulationInfo> {
  return requestJson<SimulationInfo>(simulationPath(id));
}

/** Every simulation the server runs (finding one this way asks nothing that may 404). */
export function listSimulations(): Promise<SimulationInfo[]> {
  return requestJson<SimulationInfo[]>("/api/simulations");
}

/** Warm reset keeps RETAIN variables; cold resets everything to its initial value. */
export function resetSimulation(id: string, cold = false): Promise<SimulationInfo> {
  return requestJson<SimulationInfo>(`${simulationPath(id)}/reset`, {
    method: "POST",
    headers: { "Content-Type": "application/json" },
    body: JSON.stringify({ cold }),
  });
}

export async function deleteSimulation(id: string): Promise<void> {
  await fetch(simulationPath(id), { method: "DELETE", headers: requestHeaders({ method: "DELETE" }) });
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
  const params = new URLSearchParams({ scan: String(scan), direction: String(direction), ...query });
  const found = await requestJson<HistoryFound>(`${simulationPath(id)}/history/find?${params.toString()}`);
  return found.scan ?? null;
}

/** The newest scans of the history with an input or a runtime error: the timeline's marks. */
export function historyMarks(id: string): Promise<HistoryMark[]> {
  return requestJson<HistoryMark[]>(`${simulationPath(id)}/history/marks`);
}

/** The variables whose values differ between the ends of two scans of the history, with both values. */
export function historyDiff(id: string, first: number, second: number): Promise<HistoryDiff> {
  const params = new URLSearchParams({ first: String(first), second: String(second) });
  return requestJson<HistoryDiff>(`${simulationPath(id)}/history/diff?${params.toString()}`);
}

/** The websocket address of a simulation, on the origin the app was served from. */
export function monitorUrl(id: string, location: Pick<Location, "protocol" | "host"> = window.location): string {
  return `${location.protocol === "https:" ? "wss" : "ws"}://${location.host}${simulationPath(id)}/ws`;
}

export interface SimulationApi {
  createSimulation(project: string): Promise<SimulationInfo>;
  getSimulation(id: string): Promise<SimulationInfo>;
  listSimulations(): Promise<SimulationInfo[]>;
  resetSimulation(id: string, cold?: boolean): Promise<SimulationInfo>;
  deleteSimulation(id: string): Promise<void>;
}

export const simulationApi: SimulationApi = {
  createSimulation,
  getSimulation,
  listSimulations,
  resetSimulation,
  deleteSimulation,
};
