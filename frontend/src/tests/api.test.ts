// @vitest-environment jsdom
// The run stream (issue 20): JSON lines arrive in chunks cut anywhere; each complete line is one event.
import { afterEach, describe, expect, it, vi } from "vitest";
import type { TestEvent } from "../generated/api";
import { stubFetch } from "../test/fetchStub";
import { runTests } from "./api";

afterEach(() => vi.unstubAllGlobals());

describe("runTests", () => {
  it("hands out each line of the stream as it completes, whatever the chunks", async () => {
    const lines = ['{"type":"file","file":{"file":"tests/a.st","tests":[]}}', '{"type":"done"}'];
    const text = lines.join("\n") + "\n";
    const chunks = [text.slice(0, 7), text.slice(7, 40), text.slice(40, 62), text.slice(62)];
    const body = new ReadableStream<Uint8Array>({
      start(controller) {
        for (const chunk of chunks) controller.enqueue(new TextEncoder().encode(chunk));
        controller.close();
      },
    });
    const fetched = stubFetch(() => new Response(body, { status: 200 }));
    const events: TestEvent[] = [];
    await runTests({ name: "p" }, { file: "tests/a.st" }, (e) => events.push(e));
    expect(events.map((e) => e.type)).toEqual(["file", "done"]);
    const [sent] = fetched.sent;
    expect([sent!.method, sent!.path]).toEqual(["POST", "/api/tests/run"]);
    expect(JSON.parse(sent!.body)).toEqual({ project: { name: "p" }, file: "tests/a.st" });
  });

  it("turns a refused run into an error with the server's message", async () => {
    vi.stubGlobal(
      "fetch",
      vi.fn(async () => new Response(JSON.stringify({ detail: { message: "no such file" } }), { status: 404 })),
    );
    await expect(runTests({ name: "p" }, {}, () => undefined)).rejects.toThrow("no such file");
  });
});
