import { lazy, StrictMode, Suspense } from "react";
import { createRoot } from "react-dom/client";
import App from "./app/App";
import { panelTarget } from "./hmi/panelTarget";
import "./styles.css";
import { showInitialTheme } from "./ui/theme";

showInitialTheme();
const root = document.getElementById("root");
if (!root) throw new Error("index.html has no #root element");

// `/?panel=<project>/<panel>`: a panel in a window of its own (hmi/PanelWindow.tsx); else the app.
const target = panelTarget(window.location.search);
const PanelWindow = lazy(() => import("./hmi/PanelWindow").then((m) => ({ default: m.PanelWindow })));

createRoot(root).render(
  <StrictMode>
    {target ? (
      <Suspense fallback={null}>
        <PanelWindow {...target} />
      </Suspense>
    ) : (
      <App />
    )}
  </StrictMode>,
);
