// @vitest-environment jsdom
// The sizes the user drags the side panels to are kept within their limits and across reloads.
import { act, renderHook } from "@testing-library/react";
import { describe, expect, it } from "vitest";
import { storedSize, useStoredSize } from "./layout";

describe("side panel sizes (issue 22 item 7)", () => {
  it("keeps a dragged width within its limits, stored for the next session", () => {
    localStorage.clear();
    const { result, unmount } = renderHook(() => useStoredSize("tree", 160, 480));
    expect(result.current[0]).toBeNull(); // the default width until the user drags
    act(() => result.current[1](300.6));
    expect(result.current[0]).toBe(301);
    act(() => result.current[1](40));
    expect(result.current[0]).toBe(160);
    act(() => result.current[1](9000));
    expect(result.current[0]).toBe(480);
    unmount();
    expect(storedSize("tree")).toBe(480);
    expect(renderHook(() => useStoredSize("tree", 160, 480)).result.current[0]).toBe(480);
    expect(storedSize("projects")).toBeNull();
  });
});
