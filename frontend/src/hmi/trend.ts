// The samples of a panel's trend: the last span of virtual time, one sample per scan it was shown.

/** Samples kept: times in seconds, then one column per path. */
export function appendSample(
  columns: (number | null)[][],
  timeMs: number,
  values: readonly (number | null)[],
  spanMs: number,
): (number | null)[][] {
  const times = columns[0] ?? [];
  const last = times[times.length - 1];
  if (last != null && timeMs / 1000 <= last) return columns; // the same (or an older) scan: nothing new
  const start = timeMs / 1000 - spanMs / 1000;
  const keep = times.findIndex((t) => t != null && t >= start);
  const from = keep < 0 ? times.length : keep;
  return [[...times.slice(from), timeMs / 1000], ...values.map((v, i) => [...(columns[i + 1] ?? []).slice(from), v])];
}
