// The coverage of a test run as marks for the editors: LD elements and FBD nodes never executed or
// never energised (a pin's probe "ton.Q" marks its box), ST body lines never executed.
import type { CoverageInfo } from "../generated/api";

export type CoverageMark = "never-executed" | "never-energised";

/** Element or node id -> its mark; nothing for what the tests executed and energised. */
export function coverageMarks(info: CoverageInfo | undefined | null): ReadonlyMap<string, CoverageMark> {
  const marks = new Map<string, CoverageMark>();
  if (!info) return marks;
  const owner = (probe: string) => probe.split(".")[0]!;
  for (const probe of info.never_energised ?? []) marks.set(owner(probe), "never-energised");
  for (const probe of info.never_executed ?? []) marks.set(owner(probe), "never-executed");
  return marks;
}

/** The body lines of an ST POU that no test executed. */
export function coverageLines(info: CoverageInfo | undefined | null): readonly number[] {
  return info?.never_executed_lines ?? [];
}

/** A POU's coverage by name in any case (the report names POUs as the project spells them). */
export function coverageOf(coverage: Record<string, CoverageInfo> | null, pou: string): CoverageInfo | undefined {
  if (!coverage) return undefined;
  return coverage[pou] ?? Object.entries(coverage).find(([name]) => name.toUpperCase() === pou.toUpperCase())?.[1];
}
