// A side column of the app (the project list, the project tree): its content in its own error boundary and,
// beside it, the splitter that resizes it by dragging or with the arrow keys. One component for both, so
// they resize and fail alike.
import type { ReactNode } from "react";
import { Splitter } from "./Splitter";
import { ViewBoundary } from "./ViewBoundary";

interface SidePanelProps {
  /** The boundary's name in its error message ("The project tree"). */
  name: string;
  /** Its area in the app's CSS grid. */
  gridArea: string;
  /** The splitter's accessible name ("Resize the project tree"). */
  resizeLabel: string;
  splitterClass: string;
  /** The width the user dragged it to, or null for the layout's own. */
  width: number | null;
  onResize(width: number): void;
  children: ReactNode;
}

export function SidePanel({ name, gridArea, resizeLabel, splitterClass, width, onResize, children }: SidePanelProps) {
  return (
    <>
      <ViewBoundary name={name} gridArea={gridArea}>
        {children}
      </ViewBoundary>
      <Splitter
        label={resizeLabel}
        orientation="vertical"
        grow={1}
        className={`side-splitter ${splitterClass}`}
        value={width}
        size={(edge) => width ?? edge.previousElementSibling!.getBoundingClientRect().width}
        onResize={onResize}
      />
    </>
  );
}
