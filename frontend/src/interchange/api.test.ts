// @vitest-environment jsdom
import { afterEach, describe, expect, it, vi } from "vitest";
import { ApiError } from "../api/client";
import { jsonResponse as json, stubFetch } from "../test/fetchStub";
import { exportPlcopen, exportProjectSt, importPlcopen } from "./api";

afterEach(() => vi.unstubAllGlobals());

describe("interchange REST calls (issue 9: interchange in the UI)", () => {
  it("posts the raw XML with the project name in the query", async () => {
    const fetched = stubFetch(() =>
      json({ project: { name: "plant 2", revision: "r", modified: "m", pou_count: 1 }, diagnostics: [] }, 201),
    );
    const report = await importPlcopen("<project/>", " plant 2 ");
    expect(report.project.name).toBe("plant 2");
    const [sent] = fetched.sent;
    expect([sent!.method, sent!.path, sent!.body]).toEqual([
      "POST",
      "/api/import/plcopen?name=plant%202",
      "<project/>",
    ]);
    expect(sent!.headers.get("Content-Type")).toBe("application/xml");
  });

  it("leaves the name out when none is given, so the document's name is used", async () => {
    const fetched = stubFetch(() =>
      json({ project: { name: "doc", revision: "r", modified: "m", pou_count: 0 } }, 201),
    );
    await importPlcopen("<project/>", "  ");
    expect(fetched.sent.map((c) => c.path)).toEqual(["/api/import/plcopen"]);
  });

  it("turns a refused import into an ApiError carrying the diagnostics", async () => {
    const diagnostics = [{ code: "XML-1", message: "not well-formed", line: 3, column: 1, severity: "error" }];
    vi.stubGlobal(
      "fetch",
      vi.fn(async () => json({ detail: { message: "the document cannot be imported", diagnostics } }, 422)),
    );
    const err = await importPlcopen("<x").catch((e: unknown) => e);
    expect(err).toBeInstanceOf(ApiError);
    expect((err as ApiError).status).toBe(422);
    expect((err as ApiError).message).toBe("the document cannot be imported");
    expect((err as ApiError).detail).toEqual({ message: "the document cannot be imported", diagnostics });
  });

  it("fetches the PLCopen export as text and the project ST export as JSON", async () => {
    const fetched = stubFetch((request) =>
      request.path.endsWith("/plcopen")
        ? new Response("<project name='a b'/>", { status: 200 })
        : json({ text: "PROGRAM Main\nEND_PROGRAM\n" }),
    );
    expect(await exportPlcopen("a b")).toBe("<project name='a b'/>");
    expect((await exportProjectSt("a b")).text).toBe("PROGRAM Main\nEND_PROGRAM\n");
    expect(fetched.sent.map((c) => c.path)).toEqual([
      "/api/projects/a%20b/export/plcopen",
      "/api/projects/a%20b/export/st",
    ]);
  });

  it("reports a refused XML export with the server's message", async () => {
    vi.stubGlobal(
      "fetch",
      vi.fn(async () =>
        json({ detail: { message: "the project cannot be exported as PLCopen XML", diagnostics: [] } }, 422),
      ),
    );
    await expect(exportPlcopen("p")).rejects.toThrow("the project cannot be exported as PLCopen XML");
  });

  it("reports an unreachable server as status 0", async () => {
    vi.stubGlobal(
      "fetch",
      vi.fn(async () => Promise.reject(new TypeError("Failed to fetch"))),
    );
    const err = (await exportPlcopen("p").catch((e: unknown) => e)) as ApiError;
    expect(err.status).toBe(0);
    expect(err.message).toBe("Cannot reach the LadderLab server (Failed to fetch)");
  });
});
