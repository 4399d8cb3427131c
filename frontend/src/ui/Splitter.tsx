// The edge between a panel and the editor: dragging it (or the arrow keys when it has the focus) gives
// the panel more or less room. Used by the project list, the project tree and the bottom panels.
import type { KeyboardEvent, PointerEvent as ReactPointerEvent } from "react";

/** Step of the keyboard resize (an arrow key on the focused edge). */
const KEY_STEP_PX = 24;

export interface SplitterProps {
  /** What the edge resizes, in the user's words ("Resize the panels"). */
  label: string;
  /** "vertical": an edge between columns (drag left/right); "horizontal": between rows (drag up/down). */
  orientation: "vertical" | "horizontal";
  /** 1 when dragging right or down grows the panel (a panel on the left), -1 when it shrinks it. */
  grow: 1 | -1;
  /** The panel's size now, in px (the stored one, or as drawn). */
  size(edge: HTMLElement): number;
  /** The size asked for; the owner keeps it within its limits. */
  onResize(px: number): void;
  value: number | null;
  className: string;
}

export function Splitter({ label, orientation, grow, size, onResize, value, className }: SplitterProps) {
  const vertical = orientation === "vertical";
  const onPointerDown = (e: ReactPointerEvent<HTMLDivElement>) => {
    e.preventDefault();
    const start = vertical ? e.clientX : e.clientY;
    const startSize = size(e.currentTarget);
    const move = (ev: PointerEvent) => onResize(startSize + grow * ((vertical ? ev.clientX : ev.clientY) - start));
    const up = () => {
      window.removeEventListener("pointermove", move);
      window.removeEventListener("pointerup", up);
    };
    window.addEventListener("pointermove", move);
    window.addEventListener("pointerup", up);
  };
  const onKeyDown = (e: KeyboardEvent<HTMLDivElement>) => {
    const [less, more] = vertical ? ["ArrowLeft", "ArrowRight"] : ["ArrowUp", "ArrowDown"];
    const direction = e.key === more ? 1 : e.key === less ? -1 : 0;
    if (!direction) return;
    e.preventDefault();
    onResize(size(e.currentTarget) + grow * direction * KEY_STEP_PX);
  };
  return (
    <div
      className={`splitter splitter-${orientation} ${className}`}
      role="separator"
      aria-orientation={orientation}
      aria-label={label}
      aria-valuenow={value ?? undefined}
      tabIndex={0}
      onPointerDown={onPointerDown}
      onKeyDown={onKeyDown}
    />
  );
}
