// @vitest-environment jsdom
import { act, fireEvent, render, screen } from "@testing-library/react";
import { beforeEach, describe, expect, it } from "vitest";
import { BottomPanels } from "./BottomPanels";
import { clampHeight, emptyPanels, PANEL_HEIGHT_LIMITS, panelsStore } from "../store/panels";

beforeEach(() => panelsStore.setState(emptyPanels));

describe("resizing the bottom panels by their top edge", () => {
  it("keeps the height between the minimum and what leaves the editor its room", () => {
    expect(clampHeight(10, 900)).toBe(PANEL_HEIGHT_LIMITS.min);
    expect(clampHeight(300.4, 900)).toBe(300);
    expect(clampHeight(5000, 900)).toBe(900 - PANEL_HEIGHT_LIMITS.editor);
  });

  it("grows with Arrow up and a drag upwards, shrinks with Arrow down, and survives clearing the project's panels", () => {
    render(<BottomPanels onReveal={() => undefined} pathOfOperand={() => null} />);
    const edge = screen.getByRole("separator", { name: "Resize the panels" });
    act(() => panelsStore.getState().setHeight(200, window.innerHeight));
    fireEvent.keyDown(edge, { key: "ArrowUp" });
    expect(panelsStore.getState().height).toBe(224);
    fireEvent.keyDown(edge, { key: "ArrowDown" });
    fireEvent.keyDown(edge, { key: "ArrowDown" });
    expect(panelsStore.getState().height).toBe(176);
    fireEvent.pointerDown(edge, { clientY: 500 });
    fireEvent.pointerMove(window, { clientY: 380 });
    expect(panelsStore.getState().height).toBe(296);
    fireEvent.pointerUp(window, { clientY: 380 });
    fireEvent.pointerMove(window, { clientY: 100 });
    expect(panelsStore.getState().height).toBe(296); // released: later moves do nothing
    expect(edge.getAttribute("aria-valuenow")).toBe("296");
    act(() => panelsStore.getState().clear());
    expect(panelsStore.getState().height).toBe(296);
  });
});
