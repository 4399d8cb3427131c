// Editors loaded on first use, each in its own chunk, so the app opens with the LD editor only
// (issue 22, item 8): CodeMirror comes with the ST editor.
import { lazy } from "react";

export const LazyStEditor = lazy(() => import("../st/StEditor").then((m) => ({ default: m.StEditor })));

/** What shows while an editor's code loads. */
export const LOADING = <p className="placeholder">Loading the editor…</p>;
