// REST calls of the interchange endpoints (issue 6): PLCopen XML import/export and ST export.
// The JSON ones go through requestJson; the XML export is a text download, so it needs its own
// fetch with the same error handling (a 422 carries the diagnostics that block the export).
import { ApiError, errorFromResponse, exportSt, requestJson, signInAgain } from "../api/client";
import type { ImportReport, StExport } from "../generated/api";

const projectPath = (name: string) => `/api/projects/${encodeURIComponent(name)}`;

/** `GET /api/projects/{name}/export/st`: the whole saved project as one ST text. */
export function exportProjectSt(project: string): Promise<StExport> {
  return requestJson<StExport>(`${projectPath(project)}/export/st`);
}

/** `GET /api/projects/{name}/export/plcopen`: the saved project as a PLCopen TC6 XML document. */
export async function exportPlcopen(project: string): Promise<string> {
  let response: Response;
  try {
    response = await fetch(`${projectPath(project)}/export/plcopen`, { headers: { Accept: "application/xml" } });
  } catch (err) {
    throw new ApiError(`Cannot reach the LadderLab server (${err instanceof Error ? err.message : String(err)})`, 0);
  }
  if (response.status === 401) signInAgain();
  if (!response.ok) throw await errorFromResponse(response);
  return response.text();
}

/**
 * `POST /api/import/plcopen?name=`: stores the XML document as a new project. Without a name the
 * server takes the document's own project name.
 */
export function importPlcopen(xml: string, name?: string): Promise<ImportReport> {
  const query = name?.trim() ? `?name=${encodeURIComponent(name.trim())}` : "";
  return requestJson<ImportReport>(`/api/import/plcopen${query}`, {
    method: "POST",
    headers: { "Content-Type": "application/xml" },
    body: xml,
  });
}

/** The calls the interchange UI makes; tests pass fakes. */
export interface InterchangeApi {
  exportProjectSt(project: string): Promise<StExport>;
  exportPouSt(project: string, pou: string): Promise<StExport>;
  exportPlcopen(project: string): Promise<string>;
  importPlcopen(xml: string, name?: string): Promise<ImportReport>;
}

export const interchangeApi: InterchangeApi = { exportProjectSt, exportPouSt: exportSt, exportPlcopen, importPlcopen };
