// @vitest-environment jsdom
import { fireEvent, render, screen, within } from "@testing-library/react";
import { useState } from "react";
import { describe, expect, it } from "vitest";
import type { Diagnostic } from "../generated/api";
import { DeclarationsEditor, type DeclarationsEditorProps } from "./DeclarationsEditor";

const TEXT = "VAR\n    Start : BOOL;    (* push button *)\n    Count : INT := 5;\nEND_VAR";

/** The editor over text held in state, as the workspace holds a POU's declarations. */
function setup(text: string, props: Partial<DeclarationsEditorProps> = {}) {
  let latest = text;
  function Host() {
    const [value, setValue] = useState(text);
    latest = value;
    return <DeclarationsEditor text={value} onChange={setValue} types={["BOOL", "INT", "TON"]} {...props} />;
  }
  const view = render(<Host />);
  const cell = (label: string) => screen.getByLabelText(label) as HTMLInputElement;
  return { ...view, cell, text: () => latest };
}

describe("declarations table and text (issue 7 Declarations)", () => {
  it("shows each declaration as a row and writes table edits back as ST text", () => {
    const t = setup(TEXT);
    expect(t.cell("Name of Start").value).toBe("Start");
    expect(t.cell("Comment of Start").value).toBe("push button");
    expect(t.cell("Initial value of Count").value).toBe("5");
    fireEvent.change(t.cell("Type of Count"), { target: { value: "DINT" } });
    fireEvent.change(t.cell("Address of Start"), { target: { value: "%IX0.0" } });
    expect(t.text()).toBe(
      "VAR\n    Start AT %IX0.0 : BOOL;         (* push button *)\n    Count           : DINT := 5;\nEND_VAR",
    );
    expect(t.cell("Type of Count").getAttribute("list")).toBeTruthy();
  });

  it("adds, reorders and removes rows", () => {
    const t = setup(TEXT);
    fireEvent.click(screen.getByRole("button", { name: "Add variable" }));
    expect(t.cell("Name of NewVar").value).toBe("NewVar");
    fireEvent.click(screen.getByRole("button", { name: "Move NewVar up" }));
    fireEvent.click(screen.getByRole("button", { name: "Remove Start" }));
    expect(t.text()).toBe("VAR\n    NewVar : BOOL;\n    Count  : INT := 5;\nEND_VAR");
    fireEvent.change(screen.getByLabelText("Class of Count"), { target: { value: "VAR_OUTPUT" } });
    expect(t.text()).toBe("VAR\n    NewVar : BOOL;\nEND_VAR\nVAR_OUTPUT\n    Count : INT := 5;\nEND_VAR");
  });

  it("shows text edits in the table and table edits in the text", () => {
    const t = setup(TEXT);
    fireEvent.click(screen.getByRole("tab", { name: "Text" }));
    const area = screen.getByRole("textbox", { name: "Declarations text" }) as HTMLTextAreaElement;
    fireEvent.change(area, { target: { value: "VAR_INPUT\n  Level : REAL;\nEND_VAR" } });
    fireEvent.click(screen.getByRole("tab", { name: "Table" }));
    expect(t.cell("Type of Level").value).toBe("REAL");
    expect(screen.getByLabelText("Class of Level")).toHaveProperty("value", "VAR_INPUT");
    fireEvent.change(t.cell("Name of Level"), { target: { value: "Height" } });
    fireEvent.click(screen.getByRole("tab", { name: "Text" }));
    expect((screen.getByRole("textbox", { name: "Declarations text" }) as HTMLTextAreaElement).value).toBe(
      "VAR_INPUT\n    Height : REAL;\nEND_VAR",
    );
  });

  it("keeps a half-typed row while the user types", () => {
    const t = setup(TEXT);
    fireEvent.change(t.cell("Type of Count"), { target: { value: "" } });
    expect(t.cell("Type of Count").value).toBe("");
    fireEvent.change(t.cell("Type of Count"), { target: { value: "U" } });
    expect(t.text()).toContain("Count : U := 5;");
  });

  it("puts the backend's problems on the row of their line, others under the table", () => {
    const diagnostics: Diagnostic[] = [
      { code: "ST-UNKNOWN-TYPE", message: "unknown type 'NOPE'", file: "Main/declarations", line: 3 },
      { code: "ST-X", message: "somewhere else", file: "Main/declarations", line: 9 },
    ];
    const t = setup(TEXT.replace("INT := 5", "NOPE"), { diagnostics });
    const row = t.cell("Name of Count").closest("tr")!;
    expect(row.className).toContain("has-problem");
    expect(within(row).getByRole("alert").textContent).toBe("unknown type 'NOPE'");
    expect(screen.getByRole("list", { name: "Declaration problems" }).textContent).toBe("line 9: somewhere else");
  });

  it("stays read-only where the table would lose text", () => {
    setup("VAR\n  (* inputs *)\n  x : INT;\nEND_VAR");
    expect(screen.getByRole("status").textContent).toContain("a comment between declarations, line 2");
    expect((screen.getByRole("button", { name: "Add variable" }) as HTMLButtonElement).disabled).toBe(true);
  });

  it("disables editing with the reason while online", () => {
    const t = setup(TEXT, { readOnly: "Online: go offline to edit." });
    expect(screen.getByText("Online: go offline to edit.")).toBeTruthy();
    expect(t.cell("Name of Start").disabled).toBe(true);
    fireEvent.click(screen.getByRole("tab", { name: "Text" }));
    expect((screen.getByRole("textbox", { name: "Declarations text" }) as HTMLTextAreaElement).readOnly).toBe(true);
  });

  it("reveals a focused line: its row in the table, or the text when the table cannot show it", () => {
    const t = setup(TEXT, { focus: { line: 3, seq: 1 } });
    expect(t.cell("Name of Count").closest("tr")!.className).toContain("focused");
  });
});
