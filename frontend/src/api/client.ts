// The LadderLab HTTP API, typed from the server's OpenAPI document: `http` is an openapi-fetch client
// over `paths` (src/generated/api.ts, `make schema`), so a call names a real route, sends the body the
// route takes and gets the type it answers. What every call shares is here: the headers the server's
// security rules ask for (docs/security.md), sign-in on a 401, and failures as ApiError with the
// server's message. Features keep their calls next to them (online/api.ts, tests/api.ts ...), each a
// one-line use of `http`.
import createClient, { type Middleware } from "openapi-fetch";
import type {
  CheckReport,
  Health,
  ConflictDetail,
  LibraryEntry,
  ProjectDocument,
  ProjectSummary,
  Project,
  SaveResult,
  StExport,
  SymbolTable,
  VariableChildren,
  paths,
} from "../generated/api";

export type { Health, ProjectSummary };

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

/** A non-2xx response as an ApiError, from the body openapi-fetch parsed (`{detail}` when the server sent JSON). */
export function errorOf(response: Response, body: unknown): ApiError {
  const detail =
    body && typeof body === "object" && "detail" in body ? (body as { detail: unknown }).detail : undefined;
  const text = detailText(detail);
  return new ApiError(text ?? `HTTP ${`${response.status} ${response.statusText}`.trim()}`, response.status, detail);
}

/**
 * The server takes a state-changing request (POST, PUT, PATCH, DELETE) only with a JSON body (or the
 * PLCopen import's XML), so such a request without a Content-Type of its own says JSON, body or not
 * (docs/security.md: a cross-site page cannot send that without the server's consent).
 */
export function requestHeaders(method: string, headers: Headers): Headers {
  if (!headers.has("Accept")) headers.set("Accept", "application/json");
  if (method !== "GET" && method !== "HEAD" && !headers.has("Content-Type")) {
    headers.set("Content-Type", "application/json");
  }
  return headers;
}

/** Where the browser goes when a server that needs sign-in says this browser has not (HTTP 401). */
export function signInAgain(location: Pick<Location, "pathname" | "assign"> = window.location): void {
  location.assign(`/login?next=${encodeURIComponent(location.pathname)}`);
}

const serverRules: Middleware = {
  onRequest({ request }) {
    requestHeaders(request.method.toUpperCase(), request.headers);
    return request;
  },
  onResponse({ response }) {
    if (response.status === 401) signInAgain();
    return response;
  },
};

/** The typed client of the whole API (global fetch looked up per call, so tests can stub it). */
export const http = createClient<paths>({
  baseUrl: typeof window === "undefined" ? "" : window.location.origin,
  fetch: (request) => globalThis.fetch(request),
});
http.use(serverRules);

/**
 * The data of an openapi-fetch call, or an ApiError: the server's message for a non-2xx answer,
 * "cannot reach" (status 0) when there was no answer at all.
 */
export async function unwrap<T>(call: Promise<{ data?: T; error?: unknown; response: Response }>): Promise<T> {
  let result: { data?: T; error?: unknown; response: Response };
  try {
    result = await call;
  } catch (err) {
    if (err instanceof ApiError) throw err;
    const reason = err instanceof Error ? err.message : String(err);
    throw new ApiError(`Cannot reach the LadderLab server (${reason})`, 0);
  }
  if (!result.response.ok) throw errorOf(result.response, result.error);
  return result.data as T;
}

const project = (name: string) => ({ params: { path: { name } } });

export function getHealth(): Promise<Health> {
  return unwrap(http.GET("/api/health"));
}

export async function listProjects(): Promise<ProjectSummary[]> {
  const body: unknown = await unwrap(http.GET("/api/projects"));
  if (!Array.isArray(body)) throw new ApiError("GET /api/projects did not return a list", 200, body);
  return body as ProjectSummary[];
}

/** `GET /api/projects/{name}`: the project and the revision a save must name. */
export function getProject(name: string): Promise<ProjectDocument> {
  return unwrap(http.GET("/api/projects/{name}", project(name)));
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
export async function saveProject(name: string, revision: string, body: Project): Promise<SaveResult> {
  try {
    return await unwrap(
      http.PUT("/api/projects/{name}", { ...project(name), body, headers: { "If-Match": `"${revision}"` } }),
    );
  } catch (err) {
    if (err instanceof ApiError && err.status === 409 && isConflict(err.detail))
      throw new SaveConflictError(err.detail);
    throw err;
  }
}

/** `GET /api/library?project=`: standard and the project's own functions and FBs. */
export function getLibrary(name: string): Promise<LibraryEntry[]> {
  return unwrap(http.GET("/api/library", { params: { query: { project: name } } }));
}

/** `GET /api/projects/{name}/pous/{pou}/symbols`: the POU's declarations and the globals. */
export function getSymbols(name: string, pou: string): Promise<SymbolTable> {
  return unwrap(http.GET("/api/projects/{name}/pous/{pou}/symbols", { params: { path: { name, pou } } }));
}

/** What the variable at `path` holds (the instance tree, ON-10); the programs and globals for "". */
export function getVariables(name: string, path: string): Promise<VariableChildren> {
  return unwrap(http.GET("/api/projects/{name}/variables", { params: { path: { name }, query: { path } } }));
}

/** `POST /api/projects`: a new empty project. */
export function createProject(name: string): Promise<ProjectSummary> {
  return unwrap(http.POST("/api/projects", { body: { name } }));
}

/** `POST /api/projects/{name}/check`: every diagnostic of the saved project, located. */
export function checkProject(name: string): Promise<CheckReport> {
  return unwrap(http.POST("/api/projects/{name}/check", project(name)));
}

/** `POST /api/check`: every diagnostic of a project as sent (the unsaved working copy), nothing stored. */
export function checkUnsaved(project: Project): Promise<CheckReport> {
  return unwrap(http.POST("/api/check", { body: project }));
}

/** `GET /api/projects/{name}/export/st?pou=`: a saved POU as ST, with the lines each network became. */
export function exportSt(name: string, pou: string): Promise<StExport> {
  return unwrap(http.GET("/api/projects/{name}/export/st", { params: { path: { name }, query: { pou } } }));
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
