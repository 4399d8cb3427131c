// Bottom panels (zustand): which panel is shown, the diagnostics of the last Check, and the place
// a clicked diagnostic asks the editors to reveal. The check call is injected for tests.
import { useStore } from "zustand";
import { createStore, type StoreApi } from "zustand/vanilla";
import { checkUnsaved } from "../api/client";
import type { CheckReport, Diagnostic } from "../generated/api";
import type { Project } from "../generated/api";
import { storedSize, storeSize } from "./layout";
import { gvlOfDiagnostic, gvlTab } from "./gvls";
import { partOf } from "./parts";

export type PanelId = "diagnostics" | "watch" | "io" | "log" | "breakpoints" | "trace" | "tests" | "xref";

/** A place to reveal: a POU, and in it a network/element (diagrams) or a line (texts). */
export interface Focus {
  pou: string;
  network?: string | null;
  element?: string | null;
  line?: number | null;
  /** The declarations or the body (diagnostics name the file `<POU>/declarations` or `<POU>/body`). */
  part?: "declarations" | "body" | null;
  /** A method or property of the function block `pou` (its texts are the files `<FB>.<member>/...`). */
  member?: string | null;
  /** The property accessor the place is in (the files `<FB>.<property>.GET/...`), else none. */
  accessor?: "GET" | "SET" | null;
  /** An action or named transition of an SFC POU the place is in ("actions/Fill"; the file `<POU>/actions/Fill`). */
  body?: string | null;
  /** Increases with every request, so revealing the same place twice still moves the editor. */
  seq: number;
}

export interface PanelsData {
  panel: PanelId;
  /** Diagnostics of the last Check (null before the first). */
  diagnostics: Diagnostic[] | null;
  checking: boolean;
  checkError: string | null;
  focus: Focus | null;
  /** Height of the panels in px as the user dragged it (null: the layout's default). */
  height: number | null;
}

export interface PanelsActions {
  show(panel: PanelId): void;
  /** Runs Check on the saved project and shows the diagnostics panel. */
  /** Checks the working copy as it is (unsaved changes included; nothing is saved). */
  check(project: Project): Promise<void>;
  /** Shows `diagnostics` (e.g. a refused compile) as the current list. */
  showDiagnostics(diagnostics: Diagnostic[]): void;
  /** Asks the editors to reveal where a diagnostic points. */
  reveal(target: Omit<Focus, "seq">): void;
  /** Sets the panels' height, kept within PANEL_HEIGHT_LIMITS of the window's height. */
  setHeight(px: number, windowHeight: number): void;
  /** Forgets the project's diagnostics and focus (the panel height stays). */
  clear(): void;
}

export type PanelsState = PanelsData & PanelsActions;

/** Where a diagnostic points, or null when it names no POU. */
/** The operator panel a diagnostic is about (a widget's binding: file `hmi/<name>.json`), or null. */
export function panelOf(d: Diagnostic): string | null {
  return /^hmi\/([A-Za-z_][A-Za-z0-9_]*)\.json$/.exec(d.file ?? "")?.[1] ?? null;
}

export function focusOf(d: Diagnostic): Omit<Focus, "seq"> | null {
  const list = gvlOfDiagnostic(d);
  const projectPart = list === null ? partOf(d) : gvlTab(list);
  if (projectPart) return { pou: projectPart, network: null, element: null, line: d.line ?? null, part: null };
  if (!d.pou) return null;
  const part = d.file?.endsWith("/declarations") ? "declarations" : d.file?.endsWith("/body") ? "body" : null;
  const method = /^([A-Za-z_][A-Za-z0-9_]*)\.([A-Za-z_][A-Za-z0-9_]*)(?:\.(GET|SET))?\/(declarations|body)$/i.exec(
    d.file ?? "",
  );
  if (method)
    return { pou: method[1]!, member: method[2]!, accessor: accessorOf(method[3]), line: d.line ?? null, part };
  const sfcPart = /^[^/]+\/((?:actions|transitions)\/[^/]+)$/.exec(d.file ?? "")?.[1] ?? null;
  return {
    pou: d.pou,
    network: d.network ?? null,
    element: d.element ?? null,
    line: d.line ?? null,
    part: part ?? (sfcPart ? "body" : null),
    body: sfcPart,
  };
}

/** A POU named as the engine names a method's or accessor's code (`COUNTER.SCALED`, `TANK.LEVEL.GET`, a halt's
 * place): its FB, the member and the accessor. */
export function methodPlace(pou: string): { pou: string; member: string; accessor: "GET" | "SET" | null } | null {
  const match = /^([A-Za-z_][A-Za-z0-9_]*)\.([A-Za-z_][A-Za-z0-9_]*)(?:\.(GET|SET)\b)?/i.exec(pou);
  return match ? { pou: match[1]!, member: match[2]!, accessor: accessorOf(match[3]) } : null;
}

const accessorOf = (word: string | undefined) => (word ? (word.toUpperCase() as "GET" | "SET") : null);

export const emptyPanels: PanelsData = {
  panel: "diagnostics",
  diagnostics: null,
  checking: false,
  checkError: null,
  focus: null,
  height: null,
};

/** The panels stay at least `min` px high and leave the editor at least `editor` px of the window. */
export const PANEL_HEIGHT_LIMITS = { min: 80, editor: 160 };

export const clampHeight = (px: number, windowHeight: number): number =>
  Math.round(Math.max(PANEL_HEIGHT_LIMITS.min, Math.min(px, windowHeight - PANEL_HEIGHT_LIMITS.editor)));

export function createPanelsStore(
  check: (project: Project) => Promise<CheckReport> = checkUnsaved,
): StoreApi<PanelsState> {
  let call = 0;
  return createStore<PanelsState>()((set, get) => ({
    ...emptyPanels,
    height: storedSize("panels"),
    show: (panel) => set({ panel }),
    async check(project) {
      const mine = ++call;
      set({ checking: true, checkError: null, panel: "diagnostics" });
      try {
        const report = await check(project);
        if (mine === call) set({ checking: false, diagnostics: report.diagnostics });
      } catch (err) {
        if (mine === call) set({ checking: false, checkError: err instanceof Error ? err.message : String(err) });
      }
    },
    showDiagnostics: (diagnostics) => set({ diagnostics, checkError: null, panel: "diagnostics" }),
    reveal: (target) => set({ focus: { ...target, seq: (get().focus?.seq ?? 0) + 1 } }),
    setHeight: (px, windowHeight) => {
      const height = clampHeight(px, windowHeight);
      storeSize("panels", height);
      set({ height });
    },
    clear: () => set({ ...emptyPanels, height: get().height }),
  }));
}

export const panelsStore = createPanelsStore();

export function usePanels<T>(selector: (state: PanelsState) => T): T {
  return useStore(panelsStore, selector);
}
