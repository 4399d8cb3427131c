// GET /api/projects/{name}/xref: the cross-reference list of the saved project.
import { http, unwrap } from "../api/client";
import type { XrefList } from "../generated/api";

export function getXref(project: string): Promise<XrefList> {
  return unwrap(http.GET("/api/projects/{name}/xref", { params: { path: { name: project } } }));
}
