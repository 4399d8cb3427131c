import { describe, expect, it, vi } from "vitest";
import {
  ApiError,
  errorFromResponse,
  getHealth,
  getLibrary,
  getProject,
  getSymbols,
  listProjects,
  requestHeaders,
  requestJson,
  saveProject,
  SaveConflictError,
} from "./client";

function jsonResponse(body: unknown, status = 200, statusText = ""): Response {
  return new Response(JSON.stringify(body), {
    status,
    statusText,
    headers: { "Content-Type": "application/json" },
  });
}

function stubFetch(impl: (input: RequestInfo | URL, init?: RequestInit) => Promise<Response>) {
  const fetchMock = vi.fn(impl);
  vi.stubGlobal("fetch", fetchMock);
  return fetchMock;
}

describe("errorFromResponse", () => {
  it("uses a string detail as the message and keeps status and detail", async () => {
    const err = await errorFromResponse(jsonResponse({ detail: "Project 'demo' not found" }, 404, "Not Found"));
    expect(err).toBeInstanceOf(ApiError);
    expect(err).toBeInstanceOf(Error);
    expect(err.message).toBe("Project 'demo' not found");
    expect(err.status).toBe(404);
    expect(err.detail).toBe("Project 'demo' not found");
  });

  it("joins FastAPI validation errors with their locations", async () => {
    const detail = [
      { loc: ["body", "pous", 0, "name"], msg: "Field required", type: "missing" },
      { loc: ["body", "name"], msg: "String should have at least 1 character", type: "string_too_short" },
    ];
    const err = await errorFromResponse(jsonResponse({ detail }, 422, "Unprocessable Entity"));
    expect(err.message).toBe("body.pous.0.name: Field required; body.name: String should have at least 1 character");
    expect(err.status).toBe(422);
    expect(err.detail).toEqual(detail);
  });

  it("falls back to the status line when the body is not JSON", async () => {
    const response = new Response("<html>Bad Gateway</html>", { status: 502, statusText: "Bad Gateway" });
    const err = await errorFromResponse(response);
    expect(err.message).toBe("HTTP 502 Bad Gateway");
    expect(err.status).toBe(502);
    expect(err.detail).toBeUndefined();
  });

  it("falls back to the status line for an empty body or JSON without detail", async () => {
    expect((await errorFromResponse(new Response(null, { status: 500 }))).message).toBe("HTTP 500");
    const err = await errorFromResponse(jsonResponse({ error: "nope" }, 503, "Service Unavailable"));
    expect(err.message).toBe("HTTP 503 Service Unavailable");
    expect(err.detail).toBeUndefined();
  });
});

describe("requestJson", () => {
  it("returns the parsed body of a 2xx response and asks for JSON", async () => {
    const fetchMock = stubFetch(async () => jsonResponse({ status: "ok", version: "0.1.0" }));
    await expect(getHealth()).resolves.toEqual({ status: "ok", version: "0.1.0" });
    expect(fetchMock).toHaveBeenCalledTimes(1);
    const [url, init] = fetchMock.mock.calls[0]!;
    expect(url).toBe("/api/health");
    expect(new Headers(init?.headers).get("Accept")).toBe("application/json");
  });

  it("throws the server's detail for a non-2xx response", async () => {
    stubFetch(async () => jsonResponse({ detail: "workspace is read-only" }, 409, "Conflict"));
    const err = await requestJson("/api/x").catch((e: unknown) => e);
    expect(err).toBeInstanceOf(ApiError);
    expect((err as ApiError).message).toBe("workspace is read-only");
    expect((err as ApiError).status).toBe(409);
  });

  it("turns a network failure into an ApiError with status 0", async () => {
    stubFetch(async () => {
      throw new TypeError("Failed to fetch");
    });
    const err = await requestJson("/api/health").catch((e: unknown) => e);
    expect(err).toBeInstanceOf(ApiError);
    expect((err as ApiError).status).toBe(0);
    expect((err as ApiError).message).toContain("Failed to fetch");
  });

  it("says JSON on every state-changing request, body or not, and keeps a type given (issue 18)", async () => {
    const fetchMock = stubFetch(async () => jsonResponse({}));
    await requestJson("/api/projects/p/check", { method: "POST" });
    await requestJson("/api/import/plcopen", { method: "POST", headers: { "Content-Type": "application/xml" } });
    await requestJson("/api/projects");
    const types = fetchMock.mock.calls.map(([, init]) => new Headers(init?.headers).get("Content-Type"));
    expect(types).toEqual(["application/json", "application/xml", null]);
    expect(new Headers(requestHeaders({ method: "DELETE" })).get("Content-Type")).toBe("application/json");
  });

  it("sends the browser to the sign-in page when the server answers 401", async () => {
    stubFetch(async () => jsonResponse({ detail: { message: "sign in first" } }, 401));
    const assign = vi.fn();
    vi.stubGlobal("location", { ...window.location, pathname: "/", assign });
    const err = await requestJson("/api/projects").catch((e: unknown) => e);
    expect((err as ApiError).status).toBe(401);
    expect(assign).toHaveBeenCalledWith("/login?next=%2F");
  });

  it("rejects a 2xx response that is not JSON", async () => {
    stubFetch(async () => new Response("<!doctype html><html></html>", { status: 200 }));
    await expect(requestJson("/api/projects")).rejects.toThrow(/not JSON/);
  });
});

describe("endpoints", () => {
  it("listProjects returns the list and rejects anything else", async () => {
    const rows = [{ name: "demo", revision: "r3", modified: "2024-01-01T00:00:00Z", pou_count: 2 }];
    stubFetch(async () => jsonResponse(rows));
    await expect(listProjects()).resolves.toEqual(rows);

    stubFetch(async () => jsonResponse({ projects: rows }));
    await expect(listProjects()).rejects.toThrow(ApiError);
  });

  it("getProject escapes the project name and returns the document", async () => {
    const doc = {
      name: "a b/c",
      revision: "r1",
      modified: "2024-01-01T00:00:00Z",
      project: { name: "a b/c", pous: [] },
    };
    const fetchMock = stubFetch(async () => jsonResponse(doc));
    await expect(getProject("a b/c")).resolves.toEqual(doc);
    expect(fetchMock.mock.calls[0]![0]).toBe("/api/projects/a%20b%2Fc");
  });

  it("saveProject sends the revision in If-Match and the project as JSON", async () => {
    const fetchMock = stubFetch(async () => jsonResponse({ revision: "r2", modified: "2024-01-02T00:00:00Z" }));
    await expect(saveProject("demo", "r1", { name: "demo" })).resolves.toEqual({
      revision: "r2",
      modified: "2024-01-02T00:00:00Z",
    });
    const [url, init] = fetchMock.mock.calls[0]!;
    expect(url).toBe("/api/projects/demo");
    expect(init?.method).toBe("PUT");
    expect(new Headers(init?.headers).get("If-Match")).toBe('"r1"');
    expect(JSON.parse(String(init?.body))).toEqual({ name: "demo" });
  });

  it("saveProject turns a 409 into a SaveConflictError with both revisions", async () => {
    const detail = {
      message: "changed since r1",
      base_revision: "r1",
      current_revision: "r9",
      current_modified: "2024-03-01T08:00:00Z",
    };
    stubFetch(async () => jsonResponse({ detail }, 409, "Conflict"));
    const err = await saveProject("demo", "r1", { name: "demo" }).catch((e: unknown) => e);
    expect(err).toBeInstanceOf(SaveConflictError);
    expect((err as SaveConflictError).conflict).toEqual(detail);
    expect((err as SaveConflictError).message).toBe("changed since r1");
  });

  it("uses the message of an ErrorDetail", async () => {
    stubFetch(async () => jsonResponse({ detail: { message: "project 'x' not found", diagnostics: [] } }, 404));
    await expect(getProject("x")).rejects.toThrow("project 'x' not found");
  });

  it("getLibrary and getSymbols ask the documented paths", async () => {
    const fetchMock = stubFetch(async () => jsonResponse([]));
    await getLibrary("my proj");
    await getSymbols("demo", "Main");
    expect(fetchMock.mock.calls.map((c) => c[0])).toEqual([
      "/api/library?project=my%20proj",
      "/api/projects/demo/pous/Main/symbols",
    ]);
  });
});
