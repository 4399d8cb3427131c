// Application state (zustand). `createAppStore` takes the API so tests can pass fakes;
// the app uses the `appStore` singleton through the `useAppStore` hook.
import { useStore } from "zustand";
import { createStore, type StoreApi } from "zustand/vanilla";
import { api as defaultApi, type Api, type Health, type ProjectSummary } from "../api/client";

export type LoadStatus = "idle" | "loading" | "ready" | "error";
export type HealthStatus = "unknown" | "ok" | "down";

export interface AppData {
  projects: ProjectSummary[];
  projectsStatus: LoadStatus;
  projectsError: string | null;
  health: Health | null;
  healthStatus: HealthStatus;
  healthError: string | null;
  selectedProject: string | null;
}

export interface AppActions {
  loadProjects(): Promise<void>;
  checkHealth(): Promise<void>;
  selectProject(name: string | null): void;
  /** Creates an empty project and opens it; the error message when refused, else null. */
  createProject(name: string): Promise<string | null>;
}

export type AppState = AppData & AppActions;

export const initialData: AppData = {
  projects: [],
  projectsStatus: "idle",
  projectsError: null,
  health: null,
  healthStatus: "unknown",
  healthError: null,
  selectedProject: null,
};

function message(err: unknown): string {
  return err instanceof Error ? err.message : String(err);
}

export function createAppStore(api: Api = defaultApi): StoreApi<AppState> {
  // Only the latest call of each kind may write its result (older, slower answers are dropped).
  let projectsCall = 0;
  let healthCall = 0;

  return createStore<AppState>()((set, get) => ({
    ...initialData,

    async loadProjects() {
      const call = ++projectsCall;
      set({ projectsStatus: "loading", projectsError: null });
      try {
        const projects = await api.listProjects();
        if (call !== projectsCall) return;
        const sorted = [...projects].sort((a, b) => a.name.localeCompare(b.name));
        const selected = get().selectedProject;
        set({
          projects: sorted,
          projectsStatus: "ready",
          selectedProject: sorted.some((p) => p.name === selected) ? selected : null,
        });
      } catch (err) {
        if (call !== projectsCall) return;
        set({ projects: [], projectsStatus: "error", projectsError: message(err), selectedProject: null });
      }
    },

    async checkHealth() {
      const call = ++healthCall;
      try {
        const health = await api.getHealth();
        if (call !== healthCall) return;
        if (health.status === "ok") {
          set({ health, healthStatus: "ok", healthError: null });
        } else {
          set({ health, healthStatus: "down", healthError: `server reports status "${health.status}"` });
        }
      } catch (err) {
        if (call !== healthCall) return;
        set({ health: null, healthStatus: "down", healthError: message(err) });
      }
    },

    selectProject(name) {
      if (name !== null && !get().projects.some((p) => p.name === name)) return;
      set({ selectedProject: name });
    },

    async createProject(text) {
      const name = text.trim();
      if (!name) return "Enter a name for the project.";
      try {
        await api.createProject(name);
      } catch (err) {
        return message(err);
      }
      await get().loadProjects();
      get().selectProject(name);
      return null;
    },
  }));
}

export const appStore = createAppStore();

export function useAppStore<T>(selector: (state: AppState) => T): T {
  return useStore(appStore, selector);
}
