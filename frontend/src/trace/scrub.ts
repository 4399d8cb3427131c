// The trace chart and the scan history's timeline move together (issue 23): a click on the chart shows the
// scan of the sample under the cursor, and the scan shown puts the chart's cursor on its sample.

/** The index of the sample of `scan` in `scans` (ascending, as the ring holds them), else of the newest sample
 * before it; null when every sample is later. */
export function sampleOfScan(scans: ArrayLike<number>, scan: number): number | null {
  let low = 0;
  let high = scans.length - 1;
  let found: number | null = null;
  while (low <= high) {
    const middle = (low + high) >> 1;
    if (scans[middle]! <= scan) {
      found = middle;
      low = middle + 1;
    } else {
      high = middle - 1;
    }
  }
  return found;
}
