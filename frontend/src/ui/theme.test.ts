// @vitest-environment jsdom
// The theme chosen in one session is the one the next opens with; without a choice the system's decides.
import { describe, expect, it } from "vitest";
import { applyTheme, initialTheme } from "./theme";

const prefers = (dark: boolean) => () => ({ matches: dark }) as MediaQueryList;

describe("the light and dark themes (issue 22 item 7)", () => {
  it("follows the system until the user chooses, then keeps the choice", () => {
    const storage = new Map<string, string>();
    const store = {
      getItem: (k: string) => storage.get(k) ?? null,
      setItem: (k: string, v: string) => void storage.set(k, v),
    } as Storage;
    expect(initialTheme(store, prefers(true))).toBe("dark");
    expect(initialTheme(store, prefers(false))).toBe("light");
    const root = document.createElement("html");
    applyTheme("light", store, root);
    expect(root.dataset.theme).toBe("light");
    expect(initialTheme(store, prefers(true))).toBe("light");
    applyTheme("dark", store, root);
    expect(initialTheme(store, prefers(false))).toBe("dark");
  });
});
