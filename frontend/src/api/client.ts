// Typed helpers for the LadderLab HTTP API (served under /api by the FastAPI backend).
import type { ProjectSummary } from "../generated/api";
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

/** Renders FastAPI's `detail` (a string or a list of `{loc, msg}` validation errors) as text. */
function detailText(detail: unknown): string | null {
  if (typeof detail === "string") return detail.trim() || null;
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

/** Fetches `path` and returns its JSON body; throws ApiError for network errors, non-2xx and non-JSON. */
export async function requestJson<T>(path: string, init?: RequestInit): Promise<T> {
  let response: Response;
  try {
    response = await fetch(path, {
      ...init,
      headers: { Accept: "application/json", ...init?.headers },
    });
  } catch (err) {
    const reason = err instanceof Error ? err.message : String(err);
    throw new ApiError(`Cannot reach the LadderLab server (${reason})`, 0);
  }
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

export function getProject(name: string): Promise<Project> {
  return requestJson<Project>(`/api/projects/${encodeURIComponent(name)}`);
}

/** The calls the store needs; tests pass fakes. */
export interface Api {
  getHealth(): Promise<Health>;
  listProjects(): Promise<ProjectSummary[]>;
}

export const api: Api = { getHealth, listProjects };
