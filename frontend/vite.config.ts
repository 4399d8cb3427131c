import react from "@vitejs/plugin-react";
import { defineConfig } from "vitest/config";

// The FastAPI backend (`ladderlab serve`, default port 8000) serves the built app from
// backend/ladderlab/server/static; during `npm run dev` Vite proxies /api to it instead.
const BACKEND = "http://127.0.0.1:8000";

export default defineConfig({
  plugins: [react()],
  build: {
    outDir: "../backend/ladderlab/server/static",
    emptyOutDir: true,
  },
  server: {
    proxy: {
      "/api": {
        target: BACKEND,
        changeOrigin: true,
        ws: true,
        // The backend takes state-changing requests and websockets only from its own origin
        // (docs/security.md); what this dev server forwards comes from it, so it says so.
        configure: (proxy) => {
          const fromBackend = (req: {
            getHeader(name: string): unknown;
            setHeader(name: string, value: string): void;
          }) => {
            if (req.getHeader("origin")) req.setHeader("origin", BACKEND);
          };
          proxy.on("proxyReq", fromBackend);
          proxy.on("proxyReqWs", fromBackend);
        },
      },
    },
  },
  test: {
    // Most tests are pure logic and run in node; a file that renders or needs the DOM says
    // `// @vitest-environment jsdom` (setting up jsdom for every file took 40 % of the run).
    environment: "node",
    include: ["src/**/*.test.{ts,tsx}"],
    setupFiles: ["src/test/setup.ts"],
    restoreMocks: true,
    unstubGlobals: true,
    // jsdom renders of the whole app shell take 1-2 s alone and over 5 s (the default limit) on a busy
    // 2-core machine; a hang still fails, after 30 s.
    testTimeout: 30_000,
  },
});
