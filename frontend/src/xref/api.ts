// GET /api/projects/{name}/xref: the cross-reference list of the saved project.
import { requestJson } from "../api/client";
import type { XrefList } from "../generated/api";

export function getXref(project: string): Promise<XrefList> {
  return requestJson<XrefList>(`/api/projects/${encodeURIComponent(project)}/xref`);
}
