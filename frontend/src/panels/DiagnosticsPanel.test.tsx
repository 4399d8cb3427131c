// @vitest-environment jsdom
// The Diagnostics panel: places in the user's words (issue 22 item 5) and each code's catalogue entry
// (issue 19 item 5: docs/diagnostics.md through src/generated/diagnostics.ts).
import { fireEvent, render, screen, waitFor } from "@testing-library/react";
import { beforeEach, describe, expect, it } from "vitest";
import type { Diagnostic } from "../generated/api";
import { DiagnosticsPanel, placeOf } from "./DiagnosticsPanel";
import { emptyPanels, panelsStore } from "../store/panels";

beforeEach(() => panelsStore.setState(emptyPanels));

const typo: Diagnostic = {
  code: "ST-UNKNOWN-VAR",
  severity: "error",
  message: "unknown variable 'Strat' - did you mean 'Start'?",
  pou: "Main",
  file: "Main/body",
  line: 1,
  column: 10,
};

describe("the Diagnostics panel", () => {
  it("names an LD/FBD element in the user's words, never by its ids, when the server says where it is", () => {
    const coil = { code: "LD-NOT-BOOL", message: "m", pou: "Main", network: "n2", element: "coil4" };
    expect(placeOf({ ...coil, place: 'network 2 "Motor", coil Motor' })).toBe('Main, network 2 "Motor", coil Motor');
    expect(placeOf(coil)).toBe("Main, network n2, element coil4"); // an older server: the ids are all there is
    expect(placeOf(typo)).toBe("Main, line 1:10");
  });

  it("opens the catalogue entry of a code: what it means, an example and the fix", async () => {
    panelsStore.setState({ diagnostics: [typo] });
    render(<DiagnosticsPanel onReveal={() => undefined} />);
    const code = screen.getByRole("button", { name: "ST-UNKNOWN-VAR" });
    // the catalogue is loaded on first use (issue 22 item 8): the summary arrives with it
    await waitFor(() => expect(code.getAttribute("title")).toBe("A name is used that is not declared."));
    expect(screen.queryByRole("note")).toBeNull();
    fireEvent.click(code);
    const entry = screen.getByRole("note", { name: "About ST-UNKNOWN-VAR" });
    expect(entry.querySelector("pre")?.textContent).toBe("Motor := Strat;");
    expect(entry.textContent).toContain(
      "Fix: declare the variable, or correct the name (the message suggests the nearest declared one).",
    );
    fireEvent.click(code);
    expect(screen.queryByRole("note")).toBeNull();
  });
});
