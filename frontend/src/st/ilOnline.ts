// IL online (docs/il.md "Online"): the accumulator (current result) after every line, as the engine's
// probes `L<line>:<type>` of the POU instance record it, shown at the end of its line. A line a jump
// skipped in the last scan has no value (the probe says it did not run) and shows none.
import { powerKey, type MonitorState } from "../online/monitor";
import { shownOf, type ValueShown } from "../online/shown";

const PROBE = /^L(\d+):(.+)$/;

/** One line's accumulator: the document offset of the line's end and the value shown there. */
export interface AccumulatorMark {
  pos: number;
  shown: ValueShown;
}

/** The probe ids of an instance's accumulator values in `monitor`: line -> [id, type]. `part`: an IL action or
 * transition of an SFC POU ("actions/Count"), whose probes carry it as prefix. */
function probes(monitor: MonitorState, instance: string, part: string): Map<number, [string, string]> {
  const prefix = powerKey(instance, part ? `${part}/` : "");
  const found = new Map<number, [string, string]>();
  for (const key of Object.keys(monitor.power)) {
    if (!key.startsWith(prefix)) continue;
    const match = PROBE.exec(key.slice(prefix.length));
    if (match) found.set(Number(match[1]), [key, match[2]!]);
  }
  return found;
}

/** The accumulator marks of IL `body` for `instance`: one at the end of each line that ran in the last scan.
 * `part`: the body is an IL action or transition of an SFC POU ("actions/Count"), not the POU's own. */
export function accumulatorMarks(body: string, monitor: MonitorState, instance: string, part = ""): AccumulatorMark[] {
  const byLine = probes(monitor, instance, part);
  if (byLine.size === 0) return [];
  const marks: AccumulatorMark[] = [];
  let start = 0;
  body.split("\n").forEach((text, index) => {
    const probe = byLine.get(index + 1);
    const value = probe ? monitor.power[probe[0]] : undefined;
    if (probe && value !== undefined && value !== null)
      marks.push({ pos: start + text.length, shown: { ...shownOf(value, probe[1]), forced: false, prepared: null } });
    start += text.length + 1;
  });
  return marks;
}
