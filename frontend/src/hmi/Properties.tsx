// The properties of the selected widget (or of the panel when none is): every field of its type, each
// committed as one undo step on Enter or when the field loses focus. Bindings use the operand editor of
// the LD and FBD editors, with the project's programs', plants' and global variables as suggestions.
import { useEffect, useMemo, useState, type ReactNode } from "react";
import { projectApi } from "../api/client";
import type { SymbolInfo, IndicatorState as State, Motion, Panel, SwitchPosition as Position } from "../generated/api";
import { OperandEditor } from "../ui/OperandEditor";
import { plainSymbol, useWorkspace } from "../store/project";
import { candidates } from "../trace/candidates";
import { SYMBOL_SHAPES, updateWidget, type Widget, type WidgetType } from "./model";

type Kind = "text" | "number" | "bool" | "color" | "path" | "shape" | "positions" | "states" | "paths" | "motion";
interface Field {
  key: string;
  label: string;
  kind: Kind;
}

const f = (key: string, label: string, kind: Kind): Field => ({ key, label, kind });
const BIND = f("bind", "Variable", "path");
const COMMON: Field[] = [
  f("label", "Caption", "text"),
  f("x", "x", "number"),
  f("y", "y", "number"),
  f("w", "Width", "number"),
  f("h", "Height", "number"),
  f("visible", "Visible while", "path"),
  f("move_x", "Move across by", "motion"),
  f("move_y", "Move down by", "motion"),
];
const RANGE = [f("min", "Min", "number"), f("max", "Max", "number")];

/** The fields of each widget type, after its id and before the common ones. */
const FIELDS: Record<WidgetType, Field[]> = {
  push_button: [BIND, f("nc", "Normally closed", "bool"), f("color", "Colour", "color")],
  toggle_switch: [BIND],
  selector_switch: [BIND, f("positions", "Positions", "positions")],
  emergency_stop: [BIND, f("nc", "Normally closed", "bool")],
  lamp: [
    BIND,
    f("on_color", "On colour", "color"),
    f("off_color", "Off colour", "color"),
    f("blink", "Blink when on", "bool"),
    f("blink_ms", "Blink half period ms", "number"),
  ],
  multistate: [BIND, f("states", "States", "states"), f("default_text", "Other values", "text")],
  numeric_display: [BIND, f("decimals", "Decimals", "number"), f("unit", "Unit", "text")],
  numeric_input: [BIND, ...RANGE],
  slider: [BIND, ...RANGE, f("step", "Step", "number"), f("vertical", "Vertical", "bool")],
  bar: [
    BIND,
    ...RANGE,
    f("low_alarm", "Low alarm", "number"),
    f("high_alarm", "High alarm", "number"),
    f("tank", "Tank", "bool"),
    f("vertical", "Vertical", "bool"),
    f("color", "Colour", "color"),
  ],
  seven_segment: [BIND, f("digits", "Digits", "number"), f("color", "Colour", "color")],
  label: [
    f("text", "Text", "text"),
    f("size", "Size", "number"),
    f("bold", "Bold", "bool"),
    f("color", "Colour", "color"),
  ],
  trend: [f("paths", "Variables", "paths"), f("span_s", "Span s", "number"), ...RANGE],
  symbol: [
    f("shape", "Shape", "shape"),
    BIND,
    ...RANGE,
    f("fault", "Fault while", "path"),
    f("color", "Colour", "color"),
  ],
};

/** Paths the bindings suggest: programs' and plants' variables (PROGRAM.var, inst.Q), then the globals. */
function useBindingSymbols(): SymbolInfo[] {
  const project = useWorkspace((s) => s.name);
  const pous = useWorkspace((s) => s.project?.pous);
  const changed = useWorkspace((s) => s.changed);
  const library = useWorkspace((s) => s.library);
  const names = useMemo(
    () =>
      (pous ?? [])
        .filter((p) => (p.kind === "program" || p.kind === "plant") && !changed.includes(p.name)) // saved ones only
        .map((p) => p.name),
    [pous, changed],
  );
  const [found, setFound] = useState<SymbolInfo[]>([]);
  useEffect(() => {
    if (!project || !names.length) return;
    let current = true;
    Promise.all(names.map((pou) => projectApi.getSymbols(project, pou))).then(
      (tables) => current && setFound(candidates(tables, library).map((c) => plainSymbol(c.path, c.type))),
      () => undefined, // no symbols: bindings still take typed paths
    );
    return () => void (current = false);
  }, [project, names, library]);
  return found;
}

function Row({ label, children }: { label: string; children: ReactNode }) {
  return (
    <label>
      <span>{label}</span>
      {children}
    </label>
  );
}

/** A text or number field that commits on Enter or when it loses focus. */
function TextField({
  label,
  value,
  number,
  onCommit,
}: {
  label: string;
  value: string | number | null | undefined;
  number?: boolean;
  onCommit(value: string): void;
}) {
  const [text, setText] = useState<string | null>(null);
  const shown = text ?? (value == null ? "" : String(value));
  const commit = () => {
    if (text !== null && text !== String(value ?? "")) onCommit(text);
    setText(null);
  };
  return (
    <input
      aria-label={label}
      type={number ? "number" : "text"}
      value={shown}
      onChange={(e) => setText(e.target.value)}
      onKeyDown={(e) => {
        e.stopPropagation();
        if (e.key === "Enter") commit();
        if (e.key === "Escape") setText(null);
      }}
      onBlur={commit}
    />
  );
}

/** A variable path: shown as a button; editing it opens the operand editor with suggestions. */
function PathField({
  label,
  value,
  symbols,
  onCommit,
}: {
  label: string;
  value: string | null | undefined;
  symbols: readonly SymbolInfo[];
  onCommit(value: string): void;
}) {
  const [editing, setEditing] = useState(false);
  if (editing)
    return (
      <OperandEditor
        label={label}
        initial={value ?? ""}
        suggestions={symbols}
        onCommit={(text) => {
          setEditing(false);
          if (text.trim() !== (value ?? "")) onCommit(text.trim());
        }}
        onCancel={() => setEditing(false)}
      />
    );
  return (
    <button
      type="button"
      aria-label={`${label}: ${value || "none"}`}
      className="hmi-path"
      onClick={() => setEditing(true)}
    >
      {value || "(none)"}
    </button>
  );
}

const literal = (text: string): string | number | boolean => {
  const t = text.trim();
  if (/^true$/i.test(t)) return true;
  if (/^false$/i.test(t)) return false;
  const n = Number(t);
  return t !== "" && Number.isFinite(n) ? n : t;
};

export function WidgetProperties({
  panel,
  widget,
  onChange,
}: {
  panel: Panel;
  widget: Widget;
  onChange(panel: Panel, id: string): void;
}) {
  const symbols = useBindingSymbols();
  const set = (patch: Record<string, unknown>) =>
    onChange(updateWidget(panel, widget.id, patch as Partial<Widget>), widget.id);
  const data = widget as unknown as Record<string, unknown>;
  const field = ({ key, label, kind }: Field) => {
    const value = data[key];
    const id = `${label} of ${widget.id}`;
    switch (kind) {
      case "text":
        return <TextField label={id} value={value as string} onCommit={(t) => set({ [key]: t })} />;
      case "number":
        return (
          <TextField
            label={id}
            number
            value={value as number}
            onCommit={(t) => set({ [key]: t.trim() === "" ? null : Number(t) })}
          />
        );
      case "bool":
        return (
          <input type="checkbox" aria-label={id} checked={!!value} onChange={(e) => set({ [key]: e.target.checked })} />
        );
      case "color":
        return (
          <input
            type="color"
            aria-label={id}
            value={(value as string) ?? "#546e7a"}
            onChange={(e) => set({ [key]: e.target.value })}
          />
        );
      case "path":
        return (
          <PathField label={id} value={value as string} symbols={symbols} onCommit={(t) => set({ [key]: t || null })} />
        );
      case "shape":
        return (
          <select aria-label={id} value={value as string} onChange={(e) => set({ [key]: e.target.value })}>
            {SYMBOL_SHAPES.map((s) => (
              <option key={s} value={s}>
                {s}
              </option>
            ))}
          </select>
        );
      case "paths": {
        const paths = value as string[];
        return (
          <span>
            {paths.map((p, i) => (
              <PathField
                key={i}
                label={`${id} ${i + 1}`}
                value={p}
                symbols={symbols}
                onCommit={(t) =>
                  set({ [key]: t ? paths.map((x, j) => (j === i ? t : x)) : paths.filter((_, j) => j !== i) })
                }
              />
            ))}
            {paths.length < 4 ? (
              <button type="button" onClick={() => set({ [key]: [...paths, ""] })}>
                + variable
              </button>
            ) : null}
          </span>
        );
      }
      case "motion": {
        const motion = value as Motion | null | undefined;
        return (
          <span>
            <PathField
              label={id}
              value={motion?.path}
              symbols={symbols}
              onCommit={(t) => set({ [key]: t ? { min: 0, max: 100, distance: 100, ...motion, path: t } : null })}
            />
            {motion ? (
              <>
                <TextField
                  label={`${id} min`}
                  number
                  value={motion.min ?? 0}
                  onCommit={(t) => set({ [key]: { ...motion, min: Number(t) } })}
                />
                <TextField
                  label={`${id} max`}
                  number
                  value={motion.max ?? 100}
                  onCommit={(t) => set({ [key]: { ...motion, max: Number(t) } })}
                />
                <TextField
                  label={`${id} pixels`}
                  number
                  value={motion.distance}
                  onCommit={(t) => set({ [key]: { ...motion, distance: Math.round(Number(t)) } })}
                />
              </>
            ) : null}
          </span>
        );
      }
      case "positions": {
        const positions = value as Position[];
        return (
          <span>
            {positions.map((p, i) => (
              <span key={i}>
                <TextField
                  label={`${id} ${i + 1} label`}
                  value={p.label}
                  onCommit={(t) => set({ [key]: positions.map((x, j) => (j === i ? { ...x, label: t } : x)) })}
                />
                <TextField
                  label={`${id} ${i + 1} value`}
                  value={String(p.value)}
                  onCommit={(t) => set({ [key]: positions.map((x, j) => (j === i ? { ...x, value: literal(t) } : x)) })}
                />
              </span>
            ))}
            {positions.length < 3 ? (
              <button
                type="button"
                onClick={() =>
                  set({ [key]: [...positions, { label: String(positions.length), value: positions.length }] })
                }
              >
                + position
              </button>
            ) : (
              <button type="button" onClick={() => set({ [key]: positions.slice(0, 2) })}>
                − position
              </button>
            )}
          </span>
        );
      }
      case "states": {
        const states = value as State[];
        return (
          <span>
            {states.map((s, i) => (
              <span key={i}>
                <TextField
                  label={`${id} ${i + 1} value`}
                  value={String(s.value)}
                  onCommit={(t) => set({ [key]: states.map((x, j) => (j === i ? { ...x, value: literal(t) } : x)) })}
                />
                <TextField
                  label={`${id} ${i + 1} text`}
                  value={s.text}
                  onCommit={(t) => set({ [key]: states.map((x, j) => (j === i ? { ...x, text: t } : x)) })}
                />
                <input
                  type="color"
                  aria-label={`${id} ${i + 1} colour`}
                  value={s.color ?? "#5f6368"}
                  onChange={(e) =>
                    set({ [key]: states.map((x, j) => (j === i ? { ...x, color: e.target.value } : x)) })
                  }
                />
              </span>
            ))}
            <button
              type="button"
              onClick={() => set({ [key]: [...states, { value: states.length, text: `state ${states.length}` }] })}
            >
              + state
            </button>
          </span>
        );
      }
    }
  };
  return (
    <section aria-label={`Properties of ${widget.id}`}>
      <h3>
        {widget.type.replace(/_/g, " ")} {widget.id}
      </h3>
      <Row label="Id">
        <TextField
          label={`Id of ${widget.id}`}
          value={widget.id}
          onCommit={(t) => {
            const id = t.trim();
            if (/^[A-Za-z_][A-Za-z0-9_-]{0,63}$/.test(id) && !(panel.widgets ?? []).some((w) => w.id === id))
              onChange(updateWidget(panel, widget.id, { id }), id);
          }}
        />
      </Row>
      {[...FIELDS[widget.type], ...COMMON].map((fd) => (
        <Row key={fd.key} label={fd.label}>
          {field(fd)}
        </Row>
      ))}
    </section>
  );
}

export function PanelProperties({
  panel,
  onChange,
  selected,
}: {
  panel: Panel;
  onChange(panel: Panel): void;
  selected: number;
}) {
  const set = (patch: Partial<Panel>) => onChange({ ...panel, ...patch });
  return (
    <section aria-label={`Properties of panel ${panel.name}`}>
      <h3>Panel {panel.name}</h3>
      {selected > 1 ? (
        <p className="hmi-notice">{selected} widgets selected: align or space them with the toolbar.</p>
      ) : null}
      <Row label="Title">
        <TextField label="Panel title" value={panel.title} onCommit={(t) => set({ title: t })} />
      </Row>
      <Row label="Width">
        <TextField label="Panel width" number value={panel.width ?? 800} onCommit={(t) => set({ width: Number(t) })} />
      </Row>
      <Row label="Height">
        <TextField
          label="Panel height"
          number
          value={panel.height ?? 480}
          onCommit={(t) => set({ height: Number(t) })}
        />
      </Row>
      <Row label="Grid">
        <TextField label="Panel grid" number value={panel.grid ?? 10} onCommit={(t) => set({ grid: Number(t) })} />
      </Row>
      <Row label="Background">
        <input
          type="color"
          aria-label="Panel background"
          value={panel.background ?? "#eceff1"}
          onChange={(e) => set({ background: e.target.value })}
        />
      </Row>
    </section>
  );
}
