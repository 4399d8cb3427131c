// What the chart draws, from the ring's columns: x is the time in ms since the first sample (the
// trigger's scan when there is one); in the lane view every BOOL gets its own 0/1 lane on a scale
// of its own (lane k spans k*LANE .. k*LANE+1), stacked, numbers keep the left axis.
import type { DisplayType } from "../generated/monitor";
import { formatSample, type Kind } from "./csv";
import type { SampleColumns } from "./ring";

/** Distance between BOOL lanes (a lane is 1 high, so 0.4 separates them). */
export const LANE = 1.4;

export interface SeriesPlan {
  path: string;
  kind: Kind;
  /** "y" for numbers (and BOOLs outside the lane view), "lanes" for BOOL lanes. */
  scale: "y" | "lanes";
  /** Added to the 0/1 of a BOOL lane. */
  offset: number;
  /** How the server says to show the path's values (an enumeration's names), when it said. */
  type?: DisplayType | null;
}

export interface ChartData {
  /** x first, then one array per path; null where a value is no finite number (a gap). */
  data: (number | null)[][];
  series: SeriesPlan[];
  lanes: number;
}

export function chartData(
  paths: readonly string[],
  kinds: readonly (Kind | null)[],
  columns: SampleColumns,
  originMs: number,
  laneView: boolean,
  types: readonly (DisplayType | null)[] = [],
): ChartData {
  let lanes = 0;
  const series = paths.map((path, c): SeriesPlan => {
    const kind = kinds[c] ?? "number";
    if (kind === "bool" && laneView) return { path, kind, scale: "lanes", offset: LANE * lanes++ };
    const type = types[c];
    return type ? { path, kind, scale: "y", offset: 0, type } : { path, kind, scale: "y", offset: 0 };
  });
  const x = Array.from(columns.times, (t) => t - originMs);
  const ys = columns.values.map((column, c) =>
    Array.from(column, (v) => (Number.isFinite(v) ? v + series[c]!.offset : null)),
  );
  return { data: [x, ...ys], series, lanes };
}

/** A value under the cursor as the legend shows it: BOOLs TRUE/FALSE (lane offset removed), an
 * enumeration's value by name. */
export function legendValue(plan: SeriesPlan, value: number | null | undefined): string {
  if (value === null || value === undefined) return "—";
  if (plan.kind === "bool") return value - plan.offset ? "TRUE" : "FALSE";
  return formatSample(value, plan.kind, plan.type);
}
