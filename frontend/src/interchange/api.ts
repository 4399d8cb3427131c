// REST calls of the interchange endpoints (issue 6): PLCopen XML import/export and ST export.
import { exportSt, http, unwrap } from "../api/client";
import type { ImportReport, StExport } from "../generated/api";

const project = (name: string) => ({ params: { path: { name } } });

/** `GET /api/projects/{name}/export/st`: the whole saved project as one ST text. */
export function exportProjectSt(name: string): Promise<StExport> {
  return unwrap(http.GET("/api/projects/{name}/export/st", project(name)));
}

/** `GET /api/projects/{name}/export/plcopen`: the saved project as a PLCopen TC6 XML document. */
export async function exportPlcopen(name: string): Promise<string> {
  const xml: unknown = await unwrap(
    http.GET("/api/projects/{name}/export/plcopen", {
      ...project(name),
      parseAs: "text",
      headers: { Accept: "application/xml" },
    }),
  );
  return String(xml);
}

/**
 * `POST /api/import/plcopen?name=`: stores the XML document as a new project. Without a name the
 * server takes the document's own project name.
 */
export function importPlcopen(xml: string, name?: string): Promise<ImportReport> {
  return unwrap(
    http.POST("/api/import/plcopen", {
      params: { query: name?.trim() ? { name: name.trim() } : {} },
      body: xml,
      bodySerializer: (text: string) => text,
      headers: { "Content-Type": "application/xml" },
    }),
  );
}

/** The calls the interchange UI makes; tests pass fakes. */
export interface InterchangeApi {
  exportProjectSt(project: string): Promise<StExport>;
  exportPouSt(project: string, pou: string): Promise<StExport>;
  exportPlcopen(project: string): Promise<string>;
  importPlcopen(xml: string, name?: string): Promise<ImportReport>;
}

export const interchangeApi: InterchangeApi = { exportProjectSt, exportPouSt: exportSt, exportPlcopen, importPlcopen };
