// A stand-in for the global fetch in tests of what the app asks the server: the typed client
// (api/client.ts) calls fetch with one Request; the handler gets it as method, path (with query),
// headers and body text, and `sent` keeps every request in order.
import { vi } from "vitest";

export interface SentRequest {
  method: string;
  path: string;
  headers: Headers;
  body: string;
}

export function stubFetch(answer: (request: SentRequest) => Promise<Response> | Response) {
  const sent: SentRequest[] = [];
  const mock = vi.fn(async (request: Request) => {
    const url = new URL(request.url);
    const record = {
      method: request.method,
      path: url.pathname + url.search,
      headers: request.headers,
      body: await request.clone().text(),
    };
    sent.push(record);
    return answer(record);
  });
  vi.stubGlobal("fetch", mock);
  return { mock, sent };
}

export const jsonResponse = (body: unknown, status = 200, statusText = ""): Response =>
  new Response(JSON.stringify(body), { status, statusText, headers: { "Content-Type": "application/json" } });
