// The trace's ring buffer: the last `capacity` samples (scan, virtual time, one number per path),
// in typed arrays so 10,000 samples of 20 variables cost no garbage per chunk. BOOLs are stored
// as 1/0, values that are no number (a null from an unreadable path) as NaN.
import type { Value } from "../online/protocol";

/** The largest buffer the server's protocol allows (MAX_TRACE_SAMPLES). */
export const MAX_SAMPLES = 10_000;

/** A value of a trace chunk as a number: TRUE 1, FALSE 0, "NaN"/"Infinity" as such, else NaN. */
export function sampleNumber(value: Value | undefined): number {
  if (typeof value === "boolean") return value ? 1 : 0;
  if (typeof value === "number") return value;
  if (typeof value === "string") return Number(value); // "NaN", "Infinity", "-Infinity" from non-finite REALs
  return NaN;
}

/** Columns in time order, oldest first (copies: safe to hand to a chart). */
export interface SampleColumns {
  scans: Float64Array;
  times: Float64Array;
  values: Float64Array[];
}

export class SampleRing {
  readonly capacity: number;
  readonly width: number;
  private readonly scans: Float64Array;
  private readonly times: Float64Array;
  private readonly columns: Float64Array[];
  /** Index of the next write. */
  private head = 0;
  private count = 0;
  /** Samples pushed since the buffer was made, including overwritten ones. */
  total = 0;

  constructor(capacity: number, width: number) {
    if (!Number.isInteger(capacity) || capacity < 1 || capacity > MAX_SAMPLES)
      throw new RangeError(`capacity must be 1..${MAX_SAMPLES}, not ${capacity}`);
    this.capacity = capacity;
    this.width = width;
    this.scans = new Float64Array(capacity);
    this.times = new Float64Array(capacity);
    this.columns = Array.from({ length: width }, () => new Float64Array(capacity));
  }

  get length(): number {
    return this.count;
  }

  push(scan: number, timeMs: number, values: readonly number[]): void {
    const i = this.head;
    this.scans[i] = scan;
    this.times[i] = timeMs;
    this.columns.forEach((column, c) => (column[i] = values[c] ?? NaN));
    this.head = (i + 1) % this.capacity;
    this.count = Math.min(this.count + 1, this.capacity);
    this.total++;
  }

  /** Buffer position of the `index`-th oldest sample. */
  private at(index: number): number {
    return (this.head - this.count + index + this.capacity) % this.capacity;
  }

  /** One sample (0 = oldest): scan, time and values. */
  sample(index: number): { scan: number; timeMs: number; values: number[] } {
    if (index < 0 || index >= this.count) throw new RangeError(`no sample ${index} (holding ${this.count})`);
    const i = this.at(index);
    return { scan: this.scans[i]!, timeMs: this.times[i]!, values: this.columns.map((c) => c[i]!) };
  }

  columnsInOrder(): SampleColumns {
    const start = this.at(0);
    const ordered = (source: Float64Array): Float64Array => {
      const out = new Float64Array(this.count);
      const first = Math.min(this.count, this.capacity - start);
      out.set(source.subarray(start, start + first));
      out.set(source.subarray(0, this.count - first), first);
      return out;
    };
    return { scans: ordered(this.scans), times: ordered(this.times), values: this.columns.map(ordered) };
  }
}
