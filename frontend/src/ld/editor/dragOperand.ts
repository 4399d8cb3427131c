// Dragging a variable from the diagram to the watch list. SVG elements take no part in HTML drag
// and drop, so a press on an element remembers its variable here until the mouse is released;
// a drop target reads it in its own mouseup handler, which runs before the window's clears it.
let dragged: string | null = null;

export function setDraggedOperand(operand: string | null): void {
  dragged = operand;
  if (operand !== null) window.addEventListener("mouseup", clear, { once: true });
}

/** The variable being dragged, if a press on an element is still held. */
export const draggedOperand = (): string | null => dragged;

function clear(): void {
  dragged = null;
}
