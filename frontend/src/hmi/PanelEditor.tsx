// The panel editor: a palette (click to add, or drag onto the canvas), the canvas (click to select,
// Shift+click to add to the selection, drag to move, the corner handle to resize, the keys below) and
// the properties of the selection (bindings with the operand autocomplete of the LD and FBD editors).
// Keys on the canvas: Delete, arrows (a grid step), Ctrl+Z / Ctrl+Y, Ctrl+D duplicate, Ctrl+A, Escape.
// Every edit is one step of the panel's undo history (hmi/history.ts) and marks the project unsaved.
import { useRef, useState, type PointerEvent as ReactPointerEvent } from "react";
import type { Panel } from "../generated/api";
import { canRedo, canUndo } from "../store/history";
import {
  addWidget,
  alignWidgets,
  deleteWidgets,
  distributeWidgets,
  duplicateWidgets,
  freeSpot,
  makeWidget,
  moveWidgets,
  PALETTE,
  paletteEntry,
  resizeWidget,
  widgetsOf,
  type Alignment,
  type Widget,
  type WidgetType,
} from "./model";
import { liveOf, PanelCanvas } from "./PanelCanvas";
import { PanelProperties, WidgetProperties } from "./Properties";
import { usePanelHistory } from "./history";
import { emptyMonitor } from "../online/monitor";

const DRAG_TYPE = "application/x-ladderlab-widget";
const OFFLINE = liveOf(emptyMonitor);
const ALIGNMENTS: { how: Alignment; label: string }[] = [
  { how: "left", label: "Align left" },
  { how: "center", label: "Align centres" },
  { how: "right", label: "Align right" },
  { how: "top", label: "Align top" },
  { how: "middle", label: "Align middles" },
  { how: "bottom", label: "Align bottom" },
];

type Drag =
  | { kind: "move"; x: number; y: number; dx: number; dy: number }
  | { kind: "resize"; id: string; x: number; y: number; w: number; h: number; dw: number; dh: number };

/** `selected`: the widgets selected when it opens (a diagnostic's widget, hmi/shell.tsx). */
export function PanelEditor({ name, selected: initial = [] }: { name: string; selected?: string[] }) {
  const { panel, commit, undoStep, redoStep, history } = usePanelHistory(name);
  const [selected, setSelected] = useState<string[]>(initial);
  const [drag, setDrag] = useState<Drag | null>(null);
  const svg = useRef<SVGSVGElement | null>(null);
  if (!panel) return <p className="placeholder">There is no panel {name} in this project.</p>;
  const selection = new Set(selected);

  /** Panel pixels of a pointer position. */
  const at = (clientX: number, clientY: number) => {
    const box = svg.current!.getBoundingClientRect();
    return {
      x: ((clientX - box.left) / box.width) * (panel.width ?? 800),
      y: ((clientY - box.top) / box.height) * (panel.height ?? 480),
    };
  };

  const add = (type: WidgetType, x?: number, y?: number) => {
    const entry = paletteEntry(type);
    const spot = x === undefined || y === undefined ? freeSpot(panel, entry.w, entry.h) : { x, y };
    const widget = makeWidget(panel, type, spot.x, spot.y);
    commit(addWidget(panel, widget));
    setSelected([widget.id]);
  };

  // While dragging, the panel shown has the drag applied (one undo step when it ends).
  const shown: Panel =
    drag?.kind === "move"
      ? moveWidgets(panel, selection, drag.dx, drag.dy)
      : drag?.kind === "resize"
        ? resizeWidget(panel, drag.id, drag.w + drag.dw, drag.h + drag.dh)
        : panel;

  const onWidgetDown = (widget: Widget, e: ReactPointerEvent<SVGGElement>) => {
    e.stopPropagation();
    svg.current?.focus();
    let next = selected;
    if (e.shiftKey)
      next = selection.has(widget.id) ? selected.filter((id) => id !== widget.id) : [...selected, widget.id];
    else if (!selection.has(widget.id)) next = [widget.id];
    setSelected(next);
    if (!next.includes(widget.id)) return;
    svg.current?.setPointerCapture(e.pointerId);
    const p = at(e.clientX, e.clientY);
    setDrag({ kind: "move", x: p.x, y: p.y, dx: 0, dy: 0 });
  };

  const onHandleDown = (widget: Widget, e: ReactPointerEvent) => {
    e.stopPropagation();
    svg.current?.setPointerCapture(e.pointerId);
    const p = at(e.clientX, e.clientY);
    setDrag({ kind: "resize", id: widget.id, x: p.x, y: p.y, w: widget.w, h: widget.h, dw: 0, dh: 0 });
  };

  const onMove = (e: ReactPointerEvent) => {
    if (!drag) return;
    const p = at(e.clientX, e.clientY);
    setDrag(
      drag.kind === "move"
        ? { ...drag, dx: p.x - drag.x, dy: p.y - drag.y }
        : { ...drag, dw: p.x - drag.x, dh: p.y - drag.y },
    );
  };

  const onUp = () => {
    if (drag && shown !== panel && (drag.kind === "resize" || drag.dx || drag.dy)) commit(shown);
    setDrag(null);
  };

  const onKey = (e: React.KeyboardEvent) => {
    const ctrl = e.ctrlKey || e.metaKey;
    const key = e.key.toLowerCase();
    const grid = panel.grid || 1;
    const nudge: Record<string, [number, number]> = {
      arrowleft: [-grid, 0],
      arrowright: [grid, 0],
      arrowup: [0, -grid],
      arrowdown: [0, grid],
    };
    if (ctrl && key === "z") undoStep();
    else if (ctrl && key === "y") redoStep();
    else if (ctrl && key === "a") setSelected(widgetsOf(panel).map((w) => w.id));
    else if (ctrl && key === "d" && selected.length) {
      const [next, made] = duplicateWidgets(panel, selection);
      commit(next);
      setSelected(made);
    } else if ((key === "delete" || key === "backspace") && selected.length) {
      commit(deleteWidgets(panel, selection));
      setSelected([]);
    } else if (nudge[key] && selected.length) commit(moveWidgets(panel, selection, ...nudge[key]!));
    else if (key === "escape") setSelected([]);
    else return;
    e.preventDefault();
  };

  const single = selected.length === 1 ? widgetsOf(panel).find((w) => w.id === selected[0]) : undefined;
  return (
    <div className="hmi-editor" aria-label={`Panel editor ${name}`}>
      <nav className="hmi-palette" aria-label="Widget palette">
        <h3>Widgets</h3>
        {PALETTE.map((entry) => (
          <button
            key={entry.type}
            type="button"
            draggable
            onDragStart={(e) => {
              e.dataTransfer.setData(DRAG_TYPE, entry.type);
              e.dataTransfer.effectAllowed = "copy";
            }}
            onClick={() => add(entry.type)}
          >
            {entry.title}
          </button>
        ))}
      </nav>
      <div className="hmi-run">
        <div className="hmi-toolbar" role="toolbar" aria-label="Panel editing">
          <button type="button" disabled={!canUndo(history)} onClick={undoStep} title="Undo (Ctrl+Z)">
            Undo
          </button>
          <button type="button" disabled={!canRedo(history)} onClick={redoStep} title="Redo (Ctrl+Y)">
            Redo
          </button>
          {ALIGNMENTS.map(({ how, label }) => (
            <button
              key={how}
              type="button"
              disabled={selected.length < 2}
              onClick={() => commit(alignWidgets(panel, selected, how))}
            >
              {label}
            </button>
          ))}
          <button
            type="button"
            disabled={selected.length < 3}
            onClick={() => commit(distributeWidgets(panel, selected, "x"))}
          >
            Space across
          </button>
          <button
            type="button"
            disabled={selected.length < 3}
            onClick={() => commit(distributeWidgets(panel, selected, "y"))}
          >
            Space down
          </button>
          <button
            type="button"
            disabled={!selected.length}
            onClick={() => (commit(deleteWidgets(panel, selection)), setSelected([]))}
          >
            Delete
          </button>
        </div>
        <div className="hmi-stage">
          <PanelCanvas
            panel={shown}
            live={OFFLINE}
            act={null}
            editing
            canvasProps={{
              ref: svg,
              tabIndex: 0,
              "aria-label": `Panel ${name} canvas`,
              onKeyDown: onKey,
              onPointerDown: () => setSelected([]),
              onPointerMove: onMove,
              onPointerUp: onUp,
              onPointerCancel: () => setDrag(null),
              onDragOver: (e) => {
                if (e.dataTransfer.types.includes(DRAG_TYPE)) e.preventDefault();
              },
              onDrop: (e) => {
                const type = e.dataTransfer.getData(DRAG_TYPE) as WidgetType;
                if (!type) return;
                e.preventDefault();
                const p = at(e.clientX, e.clientY);
                add(type, p.x, p.y);
              },
            }}
            widgetProps={(widget) => ({ onPointerDown: (e) => onWidgetDown(widget, e) })}
            overlay={widgetsOf(shown)
              .filter((w) => selection.has(w.id))
              .map((w) => (
                <g key={w.id} data-selected={w.id}>
                  <rect className="hmi-selection" x={w.x - 2} y={w.y - 2} width={w.w + 4} height={w.h + 4} />
                  {selected.length === 1 ? (
                    <rect
                      className="hmi-handle"
                      aria-label={`Resize ${w.id}`}
                      x={w.x + w.w - 4}
                      y={w.y + w.h - 4}
                      width={9}
                      height={9}
                      onPointerDown={(e) => onHandleDown(w, e)}
                    />
                  ) : null}
                </g>
              ))}
          />
        </div>
      </div>
      <aside className="hmi-properties" aria-label="Properties">
        {single ? (
          <WidgetProperties
            key={single.id}
            panel={panel}
            widget={single}
            onChange={(next, id) => {
              commit(next);
              if (id !== single.id) setSelected([id]);
            }}
          />
        ) : (
          <PanelProperties panel={panel} onChange={commit} selected={selected.length} />
        )}
      </aside>
    </div>
  );
}
