// REST calls of online mode (issue 6): create a simulation from the saved project, reset, read its
// statistics, delete it. Run, stop and single cycle go over the websocket with everything else.
import { requestHeaders, requestJson } from "../api/client";
import type { SimulationInfo } from "../generated/api";

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
