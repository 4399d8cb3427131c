import { cleanup, configure } from "@testing-library/react";
import { afterEach } from "vitest";

// Unmount what each test rendered (vitest runs without globals, so testing-library cannot hook itself).
afterEach(() => {
  cleanup();
});

// findBy* and waitFor give up after 1 s by default; a lazily loaded part of the app (a panel, the
// Declarations tab) took longer on the busy 2-core machine, so wait up to 10 s (a real hang still fails).
configure({ asyncUtilTimeout: 10_000 });
