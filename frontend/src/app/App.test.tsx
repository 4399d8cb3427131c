// @vitest-environment jsdom
import { render, screen, within } from "@testing-library/react";
import { beforeEach, describe, expect, it } from "vitest";
import App from "./App";
import { appStore, initialData } from "../store/workspace";
import { stubFetch } from "../test/fetchStub";

function respond(routes: Record<string, () => Response>) {
  stubFetch(({ path }) => {
    const route = routes[path];
    if (!route) throw new Error(`unexpected fetch ${path}`);
    return route();
  });
}

const json = (body: unknown, status = 200) =>
  new Response(JSON.stringify(body), { status, headers: { "Content-Type": "application/json" } });

beforeEach(() => {
  appStore.setState(initialData);
});

describe("App", () => {
  it("shows the projects and a healthy server", async () => {
    respond({
      "/api/health": () => json({ status: "ok", version: "0.1.0" }),
      "/api/projects": () =>
        json([{ name: "conveyor", revision: "r4", modified: "2024-05-01T10:00:00Z", pou_count: 3 }]),
    });
    render(<App />);
    expect(screen.getByRole("heading", { level: 1 })).toHaveProperty("textContent", "LadderLab");
    const nav = screen.getByRole("navigation", { name: "Projects" });
    expect(await within(nav).findByText("conveyor")).toBeTruthy();
    expect(within(nav).getByText(/3 POUs · rev r4/)).toBeTruthy();
    expect(await screen.findByText("Server ok · v0.1.0")).toBeTruthy();
  });

  it("shows an empty state with the server's message when the list cannot be loaded", async () => {
    respond({
      "/api/health": () => json({ status: "ok", version: "0.1.0" }),
      "/api/projects": () => json({ detail: "Not Found" }, 404),
    });
    render(<App />);
    const alert = await screen.findByRole("alert");
    expect(alert.textContent).toContain("Could not load the project list.");
    expect(alert.textContent).toContain("Not Found");
  });

  it("says the server is unreachable when the health check fails", async () => {
    respond({
      "/api/health": () => {
        throw new TypeError("Failed to fetch");
      },
      "/api/projects": () => json([]),
    });
    render(<App />);
    expect(await screen.findByText("Server unreachable")).toBeTruthy();
    expect(await screen.findByText("No projects in the workspace yet.")).toBeTruthy();
  });
});
