// CSV export of a trace: one row per sample, oldest first; columns time_ms (virtual time of the
// scan), scan, then one per traced path under its canonical name. BOOLs read TRUE/FALSE as in IEC,
// an enumeration's values by name (as declared), other numbers in JavaScript's shortest exact form,
// non-finite REALs as NaN/Infinity/-Infinity.
import type { DisplayType } from "../generated/monitor";
import { formatValue } from "../online/values";
import type { SampleColumns } from "./ring";

export type Kind = "bool" | "number";

/** A field quoted as RFC 4180 asks when it holds a comma, a quote or a line break (paths like A[1,2]). */
export function csvField(text: string): string {
  return /[",\r\n]/.test(text) ? `"${text.replaceAll('"', '""')}"` : text;
}

/** A sample as the table, the legend and the CSV show it; `type`: the server's DisplayType of its path. */
export function formatSample(value: number, kind: Kind, type?: DisplayType | null): string {
  if (kind === "bool" && !Number.isNaN(value)) return value ? "TRUE" : "FALSE";
  if (type?.names) return formatValue(value, type); // an enumeration: its value's name
  return String(value);
}

export function traceCsv(
  paths: readonly string[],
  kinds: readonly Kind[],
  columns: SampleColumns,
  types: readonly (DisplayType | null)[] = [],
): string {
  const lines = [["time_ms", "scan", ...paths].map(csvField).join(",")];
  for (let i = 0; i < columns.scans.length; i++) {
    const row = [String(columns.times[i]), String(columns.scans[i])];
    columns.values.forEach((column, c) => row.push(formatSample(column[i]!, kinds[c] ?? "number", types[c])));
    lines.push(row.join(","));
  }
  return lines.join("\n") + "\n";
}
