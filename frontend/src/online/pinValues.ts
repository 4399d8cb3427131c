// Values on every pin of an LD box or FBD block, CODESYS style (issue 17), shared by both editors.
// An FB instance's pins are its variables (every pin, wired or not: a TON's ET), read by path; a
// function's outputs are the engine's probes `<box>.<PIN>`; what feeds a function's inputs the
// editor says (an operand variable, a wire from another block, the rung's power). Each value shows
// as IEC text by the pin's type: the variable's own type from the server, a probe's declared pin type,
// or for a generic pin (ANY_NUM...) the type of the inputs declared alike (ADD of REALs gives a REAL).
import type { LibraryEntry } from "../generated/api";
import { powerKey, type MonitorState } from "./monitor";
import type { ElementSubscription } from "./protocol";
import { preparedText, shownOf, shownPath, type Prepared, type ValueShown } from "./shown";

/** Where one pin's value comes from online. */
export type PinSource =
  /** A variable: an FB instance's pin, or an operand. */
  | { path: string }
  /**
   * An engine probe (an element id); its type when known, or a path whose value has the same type. `read`:
   * the probe of the value a block read over a feedback wire (the previous scan's), shown instead of `probe`
   * when the engine records it (FBD `<block>.<PIN>`, docs/diagrams.md "Feedback").
   */
  | { probe: string; read?: string; type?: string; typeOf?: string }
  /** A value that never changes (LD: the power of the left rail). */
  | { constant: boolean }
  /** Nothing to show: a literal or an expression is its own text. */
  | null;

export interface PinRef {
  side: "in" | "out";
  name: string;
  /** The declared type (TIME, BOOL, ANY_NUM...), when the library knows the pin. */
  type?: string;
}

export interface PinBinding extends PinRef {
  source: PinSource;
}

/** The key of a pin's value: `in:PT`, `out:ET`. */
export const pinKey = (side: PinRef["side"], name: string): string => `${side}:${name.toUpperCase()}`;

/**
 * Where each pin of a box gets its value: from the FB instance at `instance` (a path such as
 * MAIN.RUNTIMER; null for a function) for every pin the FB declares, else from `feed`.
 */
export function bindBoxPins(
  entry: LibraryEntry | undefined,
  instance: string | null,
  pins: readonly PinRef[],
  feed: (pin: PinRef) => PinSource,
): PinBinding[] {
  const held =
    instance && entry?.kind === "function_block"
      ? new Set([...entry.inputs, ...entry.in_outs, ...entry.outputs].map((p) => p.name.toUpperCase()))
      : new Set<string>();
  return pins.map((pin) => ({
    ...pin,
    source: held.has(pin.name.toUpperCase()) ? { path: `${instance}.${pin.name.toUpperCase()}` } : feed(pin),
  }));
}

/** The variable paths the pins need subscribed (their values, and the types of probes). */
export function pinPaths(pins: readonly PinBinding[]): string[] {
  return pins.flatMap(({ source: s }) =>
    s && "path" in s ? [s.path] : s && "probe" in s && s.typeOf ? [s.typeOf] : [],
  );
}

/** The probe ids the pins need subscribed. */
export function pinProbes(pins: readonly PinBinding[]): string[] {
  return pins.flatMap(({ source: s }) => (s && "probe" in s ? [s.probe] : []));
}

const generic = (type: string | undefined) => type === undefined || /^ANY/i.test(type);

/** The type a source's value has, as far as the monitor knows it. */
function typeOfSource(source: PinSource, monitor: MonitorState): string | undefined {
  if (!source || "constant" in source) return source ? "BOOL" : undefined;
  if ("path" in source) return monitor.types[source.path]?.name;
  return source.type ?? (source.typeOf ? monitor.types[source.typeOf]?.name : undefined);
}

/** A probe's type: its pin's declared type, or for a generic pin that of an input declared alike. */
function probeType(pin: PinBinding, pins: readonly PinBinding[], monitor: MonitorState): string | undefined {
  const own = pin.source && "probe" in pin.source ? typeOfSource(pin.source, monitor) : undefined;
  if (own !== undefined) return own;
  if (!generic(pin.type)) return pin.type;
  for (const other of pins) {
    if (other === pin || other.side !== "in" || other.type?.toUpperCase() !== pin.type?.toUpperCase()) continue;
    const type = typeOfSource(other.source, monitor);
    if (type !== undefined) return type;
  }
  return undefined;
}

/** What each pin shows now, by `pinKey`; pins without a value (yet, or not run in the last scan) are left out. */
export function pinValues(
  pins: readonly PinBinding[],
  monitor: MonitorState,
  instance: string,
  prepared: Prepared = {},
): Record<string, ValueShown> {
  const shown: Record<string, ValueShown> = {};
  for (const pin of pins) {
    const source = pin.source;
    let value: ValueShown | null = null;
    if (!source) continue;
    if ("path" in source) value = shownPath(monitor, source.path, prepared);
    else if ("constant" in source) value = { ...shownOf(source.constant), forced: false, prepared: null };
    else {
      const read = source.read === undefined ? undefined : monitor.power[powerKey(instance, source.read)];
      const probe = read !== undefined ? read : monitor.power[powerKey(instance, source.probe)];
      if (probe !== undefined && probe !== null)
        value = { ...shownOf(probe, probeType(pin, pins, monitor)), forced: false, prepared: preparedText(undefined) };
    }
    if (value) shown[pinKey(pin.side, pin.name)] = value;
  }
  return shown;
}

/** What a diagram (LD or FBD) subscribes for the networks it shows, and how the values map back. */
export interface DiagramBinding {
  instance: string;
  /** Paths to subscribe, upper case, without repeats. */
  paths: string[];
  elements: ElementSubscription[];
  /** Upper-case operand text -> its path. */
  pathOf: ReadonlyMap<string, string>;
  /** Box or block id -> where each of its pins gets its value. */
  pins: ReadonlyMap<string, readonly PinBinding[]>;
}

/** The binding of what a diagram's networks in view name: element/probe ids, operands, box pins. */
export function diagramBinding(
  instance: string,
  ids: readonly string[],
  pathOf: ReadonlyMap<string, string>,
  pins: ReadonlyMap<string, readonly PinBinding[]>,
): DiagramBinding {
  const paths = new Set([...pathOf.values(), ...[...pins.values()].flatMap(pinPaths)]);
  return {
    instance,
    paths: [...paths],
    elements: ids.length ? [{ pou_instance: instance, ids: [...ids] }] : [],
    pathOf,
    pins,
  };
}

/** The values a diagram shows now: each operand's variable (by upper-case text) and every box pin (by box id). */
export function diagramValues(
  monitor: MonitorState,
  binding: DiagramBinding,
  prepared: Prepared = {},
): { operands: Record<string, ValueShown>; pins: Record<string, Record<string, ValueShown>> } {
  const operands: Record<string, ValueShown> = {};
  for (const [operand, path] of binding.pathOf) {
    const shown = shownPath(monitor, path, prepared);
    if (shown) operands[operand] = shown;
  }
  const pins: Record<string, Record<string, ValueShown>> = {};
  for (const [box, bound] of binding.pins) pins[box] = pinValues(bound, monitor, binding.instance, prepared);
  return { operands, pins };
}
