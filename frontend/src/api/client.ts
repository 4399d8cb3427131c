// Typed helpers for the LadderLab HTTP API (served under /api by the FastAPI backend).
import type {
  CheckReport,
  ConflictDetail,
  LibraryEntry,
  ProjectDocument,
  ProjectSummary,
  SaveResult,
  StExport,
  SymbolTable,
  VariableChildren,
} from "../generated/api";
import type { Project } from "../generated/project";

export type { ProjectSummary };

/** `GET /api/health`. */
export interface Health {
  status: string;
  version: string;
}

/** A failed API call: `status` is the HTTP status (0 when the server could not be reached). */
export class ApiError extends Error {
  override readonly name = "ApiError";
  readonly status: number;
  /** The server's JSON `detail` (FastAPI: a string, or a list of validation errors), if any. */
  readonly detail: unknown;

  constructor(message: string, status: number, detail: unknown = undefined) {
    super(message);
    this.status = status;
    this.detail = detail;
  }
}

/**
 * Renders the server's `detail` as text: a string, our `{message, ...}` objects (ErrorDetail,
 * ConflictDetail), or FastAPI's list of `{loc, msg}` validation errors.
 */
function detailText(detail: unknown): string | null {
  if (typeof detail === "string") return detail.trim() || null;
  if (detail && typeof detail === "object" && typeof (detail as { message?: unknown }).message === "string") {
    return (detail as { message: string }).message.trim() || null;
  }
  if (Array.isArray(detail)) {
    const parts = detail.map((item: unknown) => {
      if (item && typeof item === "object" && "msg" in item) {
        const { loc, msg } = item as { loc?: unknown; msg: unknown };
        const where = Array.isArray(loc) ? loc.join(".") : "";
        return where ? `${where}: ${String(msg)}` : String(msg);
      }
      return typeof item === "string" ? item : JSON.stringify(item);
    });
    return parts.length ? parts.join("; ") : null;
  }
  if (detail !== undefined && detail !== null) return JSON.stringify(detail);
  return null;
}

/** Turns a non-2xx response into an ApiError carrying the server's JSON `detail` when it sent one. */
export async function errorFromResponse(response: Response): Promise<ApiError> {
  const fallback = `${response.status} ${response.statusText}`.trim();
  let detail: unknown = undefined;
  try {
    const body: unknown = JSON.parse(await response.text());
    if (body && typeof body === "object" && "detail" in body) {
      detail = (body as { detail: unknown }).detail;
    }
  } catch {
    // Not JSON (a proxy error page, an empty body): the status line has to do.
  }
  const text = detailText(detail);
  return new ApiError(text ?? `HTTP ${fallback}`, response.status, detail);
}

/**
 * The headers of a request: the server takes a state-changing request (POST, PUT, PATCH, DELETE) only
 * with a JSON body (or the PLCopen import's XML), so such a request without a Content-Type of its own
 * says JSON, body or not (docs/security.md: a cross-site page cannot send that without the server's
 * consent).
 */
export function requestHeaders(init?: RequestInit): Headers {
  const headers = new Headers(init?.headers);
  if (!headers.has("Accept")) headers.set("Accept", "application/json");
  const method = (init?.method ?? "GET").toUpperCase();
  if (method !== "GET" && method !== "HEAD" && !headers.has("Content-Type")) {
    headers.set("Content-Type", "application/json");
  }
  return headers;
}

/** Where the browser goes when a server that needs sign-in says this browser has not (HTTP 401). */
export function signInAgain(location: Pick<Location, "pathname" | "assign"> = window.location): void {
  location.assign(`/login?next=${encodeURIComponent(location.pathname)}`);
}

/** Fetches `path` and returns its JSON body; throws ApiError for network errors, non-2xx and non-JSON. */
export async function requestJson<T>(path: string, init?: RequestInit): Promise<T> {
  let response: Response;
  try {
    response = await fetch(path, { ...init, headers: requestHeaders(init) });
  } catch (err) {
    const reason = err instanceof Error ? err.message : String(err);
    throw new ApiError(`Cannot reach the LadderLab server (${reason})`, 0);
  }
  if (response.status === 401) signInAgain();
  if (!response.ok) throw await errorFromResponse(response);
  try {
    return (await response.json()) as T;
  } catch {
    throw new ApiError(`The server sent a response to ${path} that is not JSON`, response.status);
  }
}

export function getHealth(): Promise<Health> {
  return requestJson<Health>("/api/health");
}

export async function listProjects(): Promise<ProjectSummary[]> {
  const body = await requestJson<unknown>("/api/projects");
  if (!Array.isArray(body)) {
    throw new ApiError("GET /api/projects did not return a list", 200, body);
  }
  return body as ProjectSummary[];
}

const projectPath = (name: string) => `/api/projects/${encodeURIComponent(name)}`;

/** `GET /api/projects/{name}`: the project and the revision a save must name. */
export function getProject(name: string): Promise<ProjectDocument> {
  return requestJson<ProjectDocument>(projectPath(name));
}

/** A save refused because the project changed since `base_revision` (HTTP 409). */
export class SaveConflictError extends ApiError {
  readonly conflict: ConflictDetail;

  constructor(conflict: ConflictDetail) {
    super(conflict.message, 409, conflict);
    this.conflict = conflict;
  }
}

const isConflict = (detail: unknown): detail is ConflictDetail =>
  !!detail && typeof detail === "object" && typeof (detail as ConflictDetail).current_revision === "string";

/** `PUT /api/projects/{name}` with `If-Match: <revision>`; a 409 becomes a SaveConflictError. */
export async function saveProject(name: string, revision: string, project: Project): Promise<SaveResult> {
  try {
    return await requestJson<SaveResult>(projectPath(name), {
      method: "PUT",
      headers: { "Content-Type": "application/json", "If-Match": `"${revision}"` },
      body: JSON.stringify(project),
    });
  } catch (err) {
    if (err instanceof ApiError && err.status === 409 && isConflict(err.detail))
      throw new SaveConflictError(err.detail);
    throw err;
  }
}

/** `GET /api/library?project=`: standard and the project's own functions and FBs. */
export function getLibrary(project: string): Promise<LibraryEntry[]> {
  return requestJson<LibraryEntry[]>(`/api/library?project=${encodeURIComponent(project)}`);
}

/** `GET /api/projects/{name}/pous/{pou}/symbols`: the POU's declarations and the globals. */
export function getSymbols(project: string, pou: string): Promise<SymbolTable> {
  return requestJson<SymbolTable>(`${projectPath(project)}/pous/${encodeURIComponent(pou)}/symbols`);
}

/** What the variable at `path` holds (the instance tree, ON-10); the programs and globals for "". */
export function getVariables(project: string, path: string): Promise<VariableChildren> {
  return requestJson<VariableChildren>(`${projectPath(project)}/variables?path=${encodeURIComponent(path)}`);
}

/** `POST /api/projects`: a new empty project. */
export function createProject(name: string): Promise<ProjectSummary> {
  return requestJson<ProjectSummary>("/api/projects", {
    method: "POST",
    headers: { "Content-Type": "application/json" },
    body: JSON.stringify({ name }),
  });
}

/** `POST /api/check`: every diagnostic of a project as sent (the unsaved working copy), nothing stored. */
export function checkUnsaved(project: Project): Promise<CheckReport> {
  return requestJson<CheckReport>("/api/check", {
    method: "POST",
    headers: { "Content-Type": "application/json" },
    body: JSON.stringify(project),
  });
}

/** `GET /api/projects/{name}/export/st?pou=`: a saved POU as ST, with the lines each network became. */
export function exportSt(project: string, pou: string): Promise<StExport> {
  return requestJson<StExport>(`${projectPath(project)}/export/st?pou=${encodeURIComponent(pou)}`);
}

/** The calls the stores need; tests pass fakes. */
export interface Api {
  getHealth(): Promise<Health>;
  listProjects(): Promise<ProjectSummary[]>;
  createProject(name: string): Promise<ProjectSummary>;
}

export const api: Api = { getHealth, listProjects, createProject };

/** The calls the open project needs. */
export interface ProjectApi {
  getProject(name: string): Promise<ProjectDocument>;
  saveProject(name: string, revision: string, project: Project): Promise<SaveResult>;
  getLibrary(project: string): Promise<LibraryEntry[]>;
  getSymbols(project: string, pou: string): Promise<SymbolTable>;
}

export const projectApi: ProjectApi = { getProject, saveProject, getLibrary, getSymbols };
