// A React error boundary around one area of the app (the shell, an editor, a panel): a failure in
// that area shows its error there with "Reload this view", and everything else keeps working. The
// project, drafts, watch list, trace and the simulation's connection live in the stores, not in the
// views, so nothing of them is lost when a view fails or is reloaded (issue 17).
import { Component, Fragment, type ReactNode } from "react";

export interface ViewBoundaryProps {
  /** What the area is, in the user's words ("The LD editor of Main", "The online log"). */
  name: string;
  children: ReactNode;
  /** The grid area the failed view's message takes (the view's own, in the shell's grid layouts). */
  gridArea?: string;
  /** Called by "Reload this view" before the area is mounted again (e.g. to fetch its data again). */
  onReload?(): void;
}

interface ViewBoundaryState {
  error: Error | null;
  /** Increases with every reload, so the area is mounted afresh (no state of the failed one kept). */
  generation: number;
}

export class ViewBoundary extends Component<ViewBoundaryProps, ViewBoundaryState> {
  override state: ViewBoundaryState = { error: null, generation: 0 };

  static getDerivedStateFromError(error: unknown): Partial<ViewBoundaryState> {
    return { error: error instanceof Error ? error : new Error(String(error)) };
  }

  private reload = () => {
    this.props.onReload?.();
    this.setState((s) => ({ error: null, generation: s.generation + 1 }));
  };

  override render(): ReactNode {
    const { error, generation } = this.state;
    // Keyed by the generation, so a reload mounts the area afresh (no state of the failed one kept).
    if (!error) return <Fragment key={generation}>{this.props.children}</Fragment>;
    return (
      <div
        className="view-error"
        role="alert"
        aria-label={`${this.props.name} failed`}
        style={this.props.gridArea ? { gridArea: this.props.gridArea } : undefined}
      >
        <p className="view-error-title">
          {this.props.name} failed. The project, your unsaved changes, the watch list, the trace and the simulation are
          kept.
        </p>
        <pre className="view-error-message">{`${error.name}: ${error.message}`}</pre>
        <button type="button" onClick={this.reload}>
          Reload this view
        </button>
      </div>
    );
  }
}
