// REST calls of online mode (issue 6): create a simulation from the saved project, reset, read its
// statistics, delete it. Run, stop and single cycle go over the websocket with everything else.
import { http, unwrap } from "../api/client";
import type { SimulationInfo } from "../generated/api";

const simulation = (sim_id: string) => ({ params: { path: { sim_id } } });

/** Compiles the saved project into a new simulation; a 422 ApiError carries the compile diagnostics. */
export function createSimulation(project: string): Promise<SimulationInfo> {
  return unwrap(http.POST("/api/projects/{name}/simulations", { params: { path: { name: project } } }));
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

export async function deleteSimulation(id: string): Promise<void> {
  await unwrap(http.DELETE("/api/simulations/{sim_id}", simulation(id)));
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
}

export const simulationApi: SimulationApi = {
  createSimulation,
  getSimulation,
  listSimulations,
  resetSimulation,
  deleteSimulation,
};
