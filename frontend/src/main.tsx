import { StrictMode } from "react";
import { createRoot } from "react-dom/client";
import App from "./App";
import { panelTarget, PanelWindow } from "./hmi/PanelWindow";
import "./styles.css";

const root = document.getElementById("root");
if (!root) throw new Error("index.html has no #root element");

// `/?panel=<project>/<panel>`: a panel in a window of its own (hmi/PanelWindow.tsx); else the app.
const target = panelTarget(window.location.search);

createRoot(root).render(<StrictMode>{target ? <PanelWindow {...target} /> : <App />}</StrictMode>);
