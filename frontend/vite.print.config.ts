import react from "@vitejs/plugin-react";
import { defineConfig } from "vite";

// The print view (print.html, src/print) as one script and one style sheet, so `ladderlab doc` can put
// the whole page into a single HTML file that opens (and Chromium prints) without a server. Built after
// the app into the server's static folder, served at /print/print.html.
export default defineConfig({
  plugins: [react()],
  base: "./",
  build: {
    outDir: "../backend/ladderlab/server/static/print",
    emptyOutDir: true,
    cssCodeSplit: false,
    // One file by design (above): it loads only when a document is printed, so the app's 500 kB chunk
    // warning (issue 22 item 8) does not apply. It grew from 500 to 750 kB when the printed ST came to be
    // highlighted by the ST editor's own language (one tokenizer, issue 19); 800 kB still flags an unexpected growth.
    chunkSizeWarningLimit: 800,
    assetsInlineLimit: 100_000_000,
    rollupOptions: {
      input: "print.html",
      output: { inlineDynamicImports: true, entryFileNames: "print.js", assetFileNames: "print[extname]" },
    },
  },
});
