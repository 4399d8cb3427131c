import { useEffect, useState, type CSSProperties, type FormEvent } from "react";
import type { ProjectSummary } from "../api/client";
import { appStore, useAppStore } from "../store/workspace";
import { lastProject, rememberProject } from "./session";
import { useWorkspace } from "../store/project";
import { WorkspaceView } from "./WorkspaceView";
import { NewFromExample } from "../hmi/NewFromExample";
import { ViewBoundary } from "../ui/ViewBoundary";
import { useHidden, useStoredSize } from "../store/layout";
import { PanelLeftClose, PanelLeftOpen } from "lucide-react";
import { SidePanel } from "../ui/SidePanel";
import { ThemeToggle } from "../ui/ThemeToggle";
import { ToolButton } from "../ui/ToolButton";
import { FormError } from "../ui/FormError";

const HEALTH_POLL_MS = 15_000;
/** The project list and the project tree may be dragged between these widths (px). */
const SIDE_MIN_PX = 160;
const SIDE_MAX_PX = 520;

function HealthIndicator() {
  const status = useAppStore((s) => s.healthStatus);
  const health = useAppStore((s) => s.health);
  const error = useAppStore((s) => s.healthError);
  const label =
    status === "ok"
      ? `Server ok${health?.version ? ` · v${health.version}` : ""}`
      : status === "down"
        ? "Server unreachable"
        : "Checking server…";
  return (
    <div className={`health health-${status}`} role="status" title={error ?? undefined}>
      <span className="health-dot" aria-hidden="true" />
      {label}
    </div>
  );
}

function formatModified(iso: string): string {
  const date = new Date(iso);
  return Number.isNaN(date.getTime()) ? iso : date.toLocaleString();
}

/** The located problems of a project whose files do not load, one per line ("pous/Main.st:3:1: message"). */
function problemsText(project: ProjectSummary): string {
  return (project.problems ?? [])
    .map((p) => {
      const where = [p.file, p.line, p.column].filter((part) => part !== null && part !== undefined).join(":");
      return where ? `${where}: ${p.message}` : p.message;
    })
    .join("\n");
}

function ProjectRow({ project }: { project: ProjectSummary }) {
  const selected = useAppStore((s) => s.selectedProject === project.name);
  const selectProject = useAppStore((s) => s.selectProject);
  return (
    <li>
      <button
        type="button"
        className="project"
        aria-current={selected ? "true" : undefined}
        onClick={() => selectProject(project.name)}
      >
        <span className="project-name">{project.name}</span>
        {project.revision === null ? (
          <span className="project-meta project-broken" title={problemsText(project)}>
            cannot be loaded: {problemsText(project).split("\n")[0]}
          </span>
        ) : (
          <span className="project-meta">
            {project.pou_count} POU{project.pou_count === 1 ? "" : "s"} · rev {project.revision.slice(0, 7)} ·{" "}
            {formatModified(project.modified)}
          </span>
        )}
      </button>
    </li>
  );
}

/** "New project": a name field that creates an empty project and opens it. */
function NewProject() {
  const createProject = useAppStore((s) => s.createProject);
  const [open, setOpen] = useState(false);
  const [name, setName] = useState("");
  const [error, setError] = useState<string | null>(null);
  const [busy, setBusy] = useState(false);
  if (!open) {
    return (
      <button type="button" className="new-project-button" onClick={() => setOpen(true)}>
        New project
      </button>
    );
  }
  const submit = async (e: FormEvent) => {
    e.preventDefault();
    setBusy(true);
    const problem = await createProject(name);
    setBusy(false);
    setError(problem);
    if (!problem) {
      setOpen(false);
      setName("");
    }
  };
  return (
    <form className="new-project" onSubmit={(e) => void submit(e)} aria-label="New project">
      <input
        aria-label="Project name"
        autoFocus
        value={name}
        onChange={(e) => setName(e.target.value)}
        placeholder="project name"
        spellCheck={false}
      />
      <button type="submit" disabled={busy}>
        Create
      </button>
      <button type="button" onClick={() => setOpen(false)}>
        Cancel
      </button>
      <FormError error={error} className="new-project-error" />
    </form>
  );
}

function ProjectList() {
  const projects = useAppStore((s) => s.projects);
  const status = useAppStore((s) => s.projectsStatus);
  const error = useAppStore((s) => s.projectsError);
  const loadProjects = useAppStore((s) => s.loadProjects);

  let content;
  if (status === "error") {
    content = (
      <div className="empty" role="alert">
        <p>Could not load the project list.</p>
        <p className="empty-detail">{error}</p>
      </div>
    );
  } else if ((status === "idle" || status === "loading") && projects.length === 0) {
    content = <p className="empty">Loading projects…</p>;
  } else if (projects.length === 0) {
    content = <p className="empty">No projects in the workspace yet.</p>;
  } else {
    content = (
      <ul className="project-list">
        {projects.map((p) => (
          <ProjectRow key={p.name} project={p} />
        ))}
      </ul>
    );
  }

  return (
    <nav className="sidebar" aria-label="Projects">
      <div className="sidebar-head">
        <h2>Projects</h2>
        <button type="button" onClick={() => void loadProjects()} disabled={status === "loading"}>
          Reload
        </button>
      </div>
      <NewProject />
      <NewFromExample />
      {content}
    </nav>
  );
}

function MainArea() {
  const selected = useAppStore((s) => s.selectedProject);
  const open = useWorkspace((s) => s.open);
  useEffect(() => {
    if (selected) void open(selected);
  }, [selected, open]);
  return (
    <main className="main">
      {selected ? (
        <ViewBoundary key={selected} name={`The project ${selected}`}>
          <WorkspaceView />
        </ViewBoundary>
      ) : (
        <p className="placeholder">Select a project to open it.</p>
      )}
    </main>
  );
}

export default function App() {
  const loadProjects = useAppStore((s) => s.loadProjects);
  const checkHealth = useAppStore((s) => s.checkHealth);
  const selected = useAppStore((s) => s.selectedProject);
  const listed = useAppStore((s) => s.projectsStatus === "ready");
  const [projectsHidden, toggleProjects] = useHidden("projects");
  const [projectsWidth, resizeProjects] = useStoredSize("projects", SIDE_MIN_PX, SIDE_MAX_PX);

  useEffect(() => {
    void loadProjects();
  }, [loadProjects]);

  // After a reload the project open last opens again (app/session.ts keeps the rest of the session).
  useEffect(() => {
    if (listed && appStore.getState().selectedProject === null) {
      const last = lastProject(localStorage);
      if (last) appStore.getState().selectProject(last);
    }
  }, [listed]);
  useEffect(() => {
    if (selected) rememberProject(selected, localStorage);
  }, [selected]);

  useEffect(() => {
    void checkHealth();
    const timer = window.setInterval(() => void checkHealth(), HEALTH_POLL_MS);
    return () => window.clearInterval(timer);
  }, [checkHealth]);

  return (
    <ViewBoundary name="LadderLab">
      <div
        className={`app${projectsHidden ? " projects-hidden" : ""}`}
        style={projectsWidth ? ({ "--projects-width": `${projectsWidth}px` } as CSSProperties) : undefined}
      >
        <header className="header">
          <ToolButton
            icon={projectsHidden ? PanelLeftOpen : PanelLeftClose}
            label={projectsHidden ? "Show projects" : "Hide projects"}
            className="panel-toggle"
            aria-pressed={!projectsHidden}
            onClick={toggleProjects}
          />
          <h1>LadderLab</h1>
          <span className="header-end">
            <HealthIndicator />
            <ThemeToggle />
          </span>
        </header>
        {projectsHidden ? null : (
          <SidePanel
            name="The project list"
            gridArea="sidebar"
            resizeLabel="Resize the project list"
            splitterClass="projects-splitter"
            width={projectsWidth}
            onResize={resizeProjects}
          >
            <ProjectList />
          </SidePanel>
        )}
        <MainArea />
      </div>
    </ViewBoundary>
  );
}
