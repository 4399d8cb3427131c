// @vitest-environment jsdom
import { afterEach, describe, expect, it, vi } from "vitest";
import {
  ApiError,
  checkProject,
  errorOf,
  getHealth,
  getLibrary,
  getProject,
  getSymbols,
  listProjects,
  requestHeaders,
  saveProject,
  SaveConflictError,
} from "./client";
import { importPlcopen } from "../interchange/api";
import { deleteSimulation } from "../online/api";

function jsonResponse(body: unknown, status = 200, statusText = ""): Response {
  return new Response(JSON.stringify(body), {
    status,
    statusText,
    headers: { "Content-Type": "application/json" },
  });
}

/** Stubs the global fetch; the client calls it with one Request. */
function stubFetch(impl: (request: Request) => Promise<Response>) {
  const fetchMock = vi.fn(impl);
  vi.stubGlobal("fetch", fetchMock);
  return fetchMock;
}

const sent = (mock: ReturnType<typeof stubFetch>, call = 0): Request => mock.mock.calls[call]![0];
const pathOf = (request: Request) => {
  const url = new URL(request.url);
  return url.pathname + url.search;
};

afterEach(() => vi.unstubAllGlobals());

describe("errorOf", () => {
  const response = (status: number, statusText = "") => new Response(null, { status, statusText });

  it("uses a string detail as the message and keeps status and detail", () => {
    const err = errorOf(response(404, "Not Found"), { detail: "Project 'demo' not found" });
    expect(err).toBeInstanceOf(ApiError);
    expect(err).toBeInstanceOf(Error);
    expect([err.message, err.status, err.detail]).toEqual([
      "Project 'demo' not found",
      404,
      "Project 'demo' not found",
    ]);
  });

  it("joins FastAPI validation errors with their locations", () => {
    const detail = [
      { loc: ["body", "pous", 0, "name"], msg: "Field required", type: "missing" },
      { loc: ["body", "name"], msg: "String should have at least 1 character", type: "string_too_short" },
    ];
    const err = errorOf(response(422, "Unprocessable Entity"), { detail });
    expect(err.message).toBe("body.pous.0.name: Field required; body.name: String should have at least 1 character");
    expect(err.detail).toEqual(detail);
  });

  it("falls back to the status line when the body is not JSON or has no detail", () => {
    expect(errorOf(response(502, "Bad Gateway"), "<html>Bad Gateway</html>").message).toBe("HTTP 502 Bad Gateway");
    expect(errorOf(response(500), undefined).message).toBe("HTTP 500");
    const err = errorOf(response(503, "Service Unavailable"), { error: "nope" });
    expect([err.message, err.detail]).toEqual(["HTTP 503 Service Unavailable", undefined]);
  });
});

describe("the HTTP client", () => {
  it("returns the parsed body of a 2xx response and asks for JSON", async () => {
    const fetchMock = stubFetch(async () => jsonResponse({ status: "ok", version: "0.1.0" }));
    await expect(getHealth()).resolves.toEqual({ status: "ok", version: "0.1.0" });
    expect(fetchMock).toHaveBeenCalledTimes(1);
    expect(pathOf(sent(fetchMock))).toBe("/api/health");
    expect(sent(fetchMock).headers.get("Accept")).toBe("application/json");
  });

  it("throws the server's detail for a non-2xx response", async () => {
    stubFetch(async () => jsonResponse({ detail: "workspace is read-only" }, 409, "Conflict"));
    const err = await listProjects().catch((e: unknown) => e);
    expect(err).toBeInstanceOf(ApiError);
    expect([(err as ApiError).message, (err as ApiError).status]).toEqual(["workspace is read-only", 409]);
  });

  it("turns a network failure into an ApiError with status 0", async () => {
    stubFetch(async () => {
      throw new TypeError("Failed to fetch");
    });
    const err = await getHealth().catch((e: unknown) => e);
    expect(err).toBeInstanceOf(ApiError);
    expect((err as ApiError).status).toBe(0);
    expect((err as ApiError).message).toContain("Failed to fetch");
  });

  it("says JSON on every state-changing request, body or not, and keeps a type given (issue 18)", async () => {
    const fetchMock = stubFetch(async () => jsonResponse({ diagnostics: [] }));
    await checkProject("p");
    await importPlcopen("<project/>").catch(() => undefined);
    await deleteSimulation("s1").catch(() => undefined);
    await listProjects().catch(() => undefined);
    const types = fetchMock.mock.calls.map(([request]) => [request.method, request.headers.get("Content-Type")]);
    expect(types).toEqual([
      ["POST", "application/json"],
      ["POST", "application/xml"],
      ["DELETE", "application/json"],
      ["GET", null],
    ]);
    expect(await sent(fetchMock, 1).text()).toBe("<project/>");
    expect(requestHeaders("PUT", new Headers()).get("Content-Type")).toBe("application/json");
  });

  it("sends the browser to the sign-in page when the server answers 401", async () => {
    stubFetch(async () => jsonResponse({ detail: { message: "sign in first" } }, 401));
    const assign = vi.fn();
    vi.stubGlobal("location", { ...window.location, pathname: "/", assign });
    const err = await listProjects().catch((e: unknown) => e);
    expect((err as ApiError).status).toBe(401);
    expect(assign).toHaveBeenCalledWith("/login?next=%2F");
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
    const doc = { name: "a b/c", revision: "r1", modified: "2024-01-01T00:00:00Z", project: { name: "a b/c" } };
    const fetchMock = stubFetch(async () => jsonResponse(doc));
    await expect(getProject("a b/c")).resolves.toEqual(doc);
    expect(pathOf(sent(fetchMock))).toBe("/api/projects/a%20b%2Fc");
  });

  it("saveProject sends the revision in If-Match and the project as JSON", async () => {
    const fetchMock = stubFetch(async () => jsonResponse({ revision: "r2", modified: "2024-01-02T00:00:00Z" }));
    await expect(saveProject("demo", "r1", { name: "demo" })).resolves.toEqual({
      revision: "r2",
      modified: "2024-01-02T00:00:00Z",
    });
    const request = sent(fetchMock);
    expect([pathOf(request), request.method, request.headers.get("If-Match")]).toEqual([
      "/api/projects/demo",
      "PUT",
      '"r1"',
    ]);
    expect(await request.json()).toEqual({ name: "demo" });
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
    expect(fetchMock.mock.calls.map(([request]) => pathOf(request))).toEqual([
      "/api/library?project=my%20proj",
      "/api/projects/demo/pous/Main/symbols",
    ]);
  });
});
