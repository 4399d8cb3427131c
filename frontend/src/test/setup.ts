import { cleanup } from "@testing-library/react";
import { afterEach } from "vitest";

// Unmount what each test rendered (vitest runs without globals, so testing-library cannot hook itself).
afterEach(() => {
  cleanup();
});
