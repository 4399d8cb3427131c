// @vitest-environment jsdom
import { fireEvent, render, screen, waitFor } from "@testing-library/react";
import { describe, expect, it, vi } from "vitest";
import { ApiError } from "../api/client";
import type { ImportReport, StExport } from "../generated/api";
import type { InterchangeApi } from "./api";
import { ExportMenu } from "./ExportMenu";
import { ImportPlcopen, importSummary } from "./ImportPlcopen";

function fakeApi(overrides: Partial<InterchangeApi> = {}): InterchangeApi {
  return {
    exportProjectSt: vi.fn(async (): Promise<StExport> => ({
      text: "PROGRAM Main\nEND_PROGRAM\nFUNCTION_BLOCK Fb\nEND_FUNCTION_BLOCK\n",
    })),
    exportPouSt: vi.fn(async (_p: string, pou: string): Promise<StExport> => ({
      text: `PROGRAM ${pou}\nEND_PROGRAM\n`,
    })),
    exportPlcopen: vi.fn(async () => "<project/>"),
    importPlcopen: vi.fn(async (): Promise<ImportReport> => ({
      project: { name: "first_steps", revision: "r1", modified: "m", pou_count: 3 },
      diagnostics: [],
    })),
    ...overrides,
  };
}

const refused = (message: string) =>
  new ApiError(message, 422, {
    message,
    diagnostics: [{ code: "LD-7", message: "coil without operand", pou: "Main", network: "2", severity: "error" }],
  });

describe("ExportMenu (issue 9: export project as PLCopen XML / ST, one POU as ST)", () => {
  it("downloads each export under its file name", async () => {
    const api = fakeApi();
    const download = vi.fn();
    render(<ExportMenu project="plant" pou="Main" unsaved={false} api={api} download={download} />);
    fireEvent.click(screen.getByRole("button", { name: "PLCopen XML" }));
    await waitFor(() => expect(download).toHaveBeenCalledTimes(1));
    expect(download).toHaveBeenLastCalledWith("plant.xml", "<project/>", "application/xml");
    fireEvent.click(screen.getByRole("button", { name: "Project as ST" }));
    await waitFor(() => expect(download).toHaveBeenCalledTimes(2));
    expect(download).toHaveBeenLastCalledWith(
      "plant.st",
      "PROGRAM Main\nEND_PROGRAM\nFUNCTION_BLOCK Fb\nEND_FUNCTION_BLOCK\n",
      "text/plain;charset=utf-8",
    );
    fireEvent.click(screen.getByRole("button", { name: "Main as ST" }));
    await waitFor(() => expect(download).toHaveBeenCalledTimes(3));
    expect(download).toHaveBeenLastCalledWith("Main.st", "PROGRAM Main\nEND_PROGRAM\n", "text/plain;charset=utf-8");
    expect(api.exportPouSt).toHaveBeenCalledWith("plant", "Main");
  });

  it("offers no POU export without an active POU and marks that the saved version is exported", () => {
    render(<ExportMenu project="plant" pou={null} unsaved api={fakeApi()} download={vi.fn()} />);
    expect(screen.getAllByRole("button", { name: /as ST$/ }).map((b) => b.textContent)).toEqual(["Project as ST"]);
    expect(screen.getByText("Export (saved version):")).toBeTruthy();
  });

  it("lists the diagnostics that block an export and downloads nothing", async () => {
    const download = vi.fn();
    render(
      <ExportMenu
        project="plant"
        pou="Main"
        unsaved={false}
        api={fakeApi({
          exportPlcopen: vi.fn(async () => Promise.reject(refused("the project cannot be exported as PLCopen XML"))),
        })}
        download={download}
      />,
    );
    fireEvent.click(screen.getByRole("button", { name: "PLCopen XML" }));
    const alert = await screen.findByRole("alert");
    expect(alert.textContent).toContain("PLCopen XML export failed: the project cannot be exported as PLCopen XML");
    expect(alert.textContent).toContain("error · Main, network 2: coil without operand");
    expect(download).not.toHaveBeenCalled();
    fireEvent.click(screen.getByRole("button", { name: "Dismiss" }));
    expect(screen.queryByRole("alert")).toBeNull();
  });
});

describe("ImportPlcopen (issue 9: import a PLCopen XML file into a new project)", () => {
  const pick = (text: string) => {
    fireEvent.click(screen.getByRole("button", { name: "Import PLCopen XML…" }));
    const file = new File([text], "first_steps.xml", { type: "application/xml" });
    fireEvent.change(screen.getByLabelText("PLCopen XML file"), { target: { files: [file] } });
  };

  it("posts the file's text with the chosen name, reports the warnings and opens the project", async () => {
    const warning = { code: "XML-20", message: "action block dropped", pou: "plc_prg", severity: "warning" as const };
    const api = fakeApi({
      importPlcopen: vi.fn(async () => ({
        project: { name: "steps", revision: "r1", modified: "m", pou_count: 1 },
        diagnostics: [warning],
      })),
    });
    const onStored = vi.fn();
    const onOpen = vi.fn();
    render(<ImportPlcopen api={api} onStored={onStored} onOpen={onOpen} />);
    pick("<project>x</project>");
    fireEvent.change(screen.getByLabelText("New project name"), { target: { value: "steps" } });
    fireEvent.click(screen.getByRole("button", { name: "Import" }));
    const report = await screen.findByRole("status");
    expect(report.textContent).toContain("Imported steps: 1 POU, 1 warning.");
    expect(report.textContent).toContain("warning · plc_prg: action block dropped");
    expect(api.importPlcopen).toHaveBeenCalledWith("<project>x</project>", "steps");
    expect(onStored).toHaveBeenCalledWith("steps");
    fireEvent.click(screen.getByRole("button", { name: "Open steps" }));
    expect(onOpen).toHaveBeenCalledWith("steps");
  });

  it("offers Open only once the project list is refreshed (a click before it would open nothing)", async () => {
    let refreshed = () => {};
    const onStored = vi.fn(() => new Promise<void>((resolve) => (refreshed = resolve)));
    render(
      <ImportPlcopen
        api={fakeApi({
          importPlcopen: vi.fn(async () => ({
            project: { name: "steps", revision: "r1", modified: "m", pou_count: 1 },
            diagnostics: [],
          })),
        })}
        onStored={onStored}
        onOpen={vi.fn()}
      />,
    );
    pick("<project>x</project>");
    fireEvent.click(screen.getByRole("button", { name: "Import" }));
    await screen.findByRole("status");
    await waitFor(() => expect(onStored).toHaveBeenCalledWith("steps"));
    expect(screen.queryByRole("button", { name: "Open steps" })).toBeNull();
    refreshed();
    await screen.findByRole("button", { name: "Open steps" });
  });

  it("shows why a document was refused and stores nothing", async () => {
    const onStored = vi.fn();
    render(
      <ImportPlcopen
        api={fakeApi({ importPlcopen: vi.fn(async () => Promise.reject(refused("the document cannot be imported"))) })}
        onStored={onStored}
        onOpen={vi.fn()}
      />,
    );
    pick("<broken");
    fireEvent.click(screen.getByRole("button", { name: "Import" }));
    expect((await screen.findByRole("alert")).textContent).toContain(
      "The import failed: the document cannot be imported",
    );
    expect(onStored).not.toHaveBeenCalled();
    expect(screen.queryByRole("button", { name: /^Open / })).toBeNull();
  });

  it("keeps Import disabled until a file is chosen", () => {
    render(<ImportPlcopen api={fakeApi()} onStored={vi.fn()} onOpen={vi.fn()} />);
    fireEvent.click(screen.getByRole("button", { name: "Import PLCopen XML…" }));
    expect(screen.getByRole("button", { name: "Import" }).hasAttribute("disabled")).toBe(true);
  });

  it("summarises counts with singular and plural", () => {
    const summary = (pou_count: number, warnings: number) =>
      importSummary({
        project: { name: "p", revision: "r", modified: "m", pou_count },
        diagnostics: Array.from({ length: warnings }, () => ({ code: "W", message: "w" })),
      });
    expect(summary(0, 0)).toBe("Imported p: 0 POUs, no warnings.");
    expect(summary(1, 2)).toBe("Imported p: 1 POU, 2 warnings.");
  });
});
