// Where the print view's document comes from: embedded in the page by `ladderlab doc` (a script element
// of type application/json, so the file works offline and Chromium prints it without a server), or
// fetched from GET /api/projects/{name}/document for the project and POUs in the page's query.
import { http, unwrap } from "../api/client";
import type { PrintDocument } from "../generated/api";

export const EMBEDDED_ID = "ladderlab-document";

export interface PrintRequest {
  project: string;
  pous: string[];
}

/** The project and POUs named by a print page's query (`?project=motor&pou=Main&pou=Scaling`). */
export function requestOf(search: string): PrintRequest | null {
  const query = new URLSearchParams(search);
  const project = query.get("project");
  return project ? { project, pous: query.getAll("pou") } : null;
}

/** The URL of the print page of `project` (only `pous`; none: every POU). */
export function printUrl(project: string, pous: readonly string[] = []): string {
  const query = new URLSearchParams([["project", project], ...pous.map((p): [string, string] => ["pou", p])]);
  return `/print/print.html?${query.toString()}`;
}

export function embeddedDocument(doc: Document): PrintDocument | null {
  const script = doc.getElementById(EMBEDDED_ID);
  return script?.textContent ? (JSON.parse(script.textContent) as PrintDocument) : null;
}

export function fetchDocument(request: PrintRequest): Promise<PrintDocument> {
  const query = request.pous.length ? { pou: request.pous } : {};
  return unwrap(http.GET("/api/projects/{name}/document", { params: { path: { name: request.project }, query } }));
}
