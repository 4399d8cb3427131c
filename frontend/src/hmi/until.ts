// "Run until" as typed: a duration (5s, T#1m30s, 500ms) runs that much more virtual time; anything else
// is a condition the server reads (Motor, NOT Alarm, Tank.Level >= 80) and checks after every scan.

const DURATION = /^(?:T#|TIME#)?((?:\d+(?:\.\d+)?(?:ms|d|h|m|s)_?)+)$/i;
const UNIT_MS: Record<string, number> = { d: 86_400_000, h: 3_600_000, m: 60_000, s: 1000, ms: 1 };

/** Milliseconds of a duration literal (T#1m30s, 2s, 500ms), or null when the text is none. */
export function durationMs(text: string): number | null {
  const match = DURATION.exec(text.trim().replace(/\s+/g, ""));
  if (!match) return null;
  let total = 0;
  for (const [, amount, unit] of match[1]!.matchAll(/(\d+(?:\.\d+)?)(ms|d|h|m|s)/gi))
    total += Number(amount) * UNIT_MS[unit!.toLowerCase()]!;
  return total;
}

/** The run_until request for the text, from virtual time `nowMs`; or why it cannot be one. */
export function parseUntil(
  text: string,
  nowMs: number,
): { condition: string } | { time_ms: number } | { error: string } {
  const t = text.trim();
  if (!t) return { error: "type a condition (Level >= 80) or a time (5s)" };
  const ms = durationMs(t);
  if (ms === null) return { condition: t };
  if (ms <= 0) return { error: "run for more than 0 s" };
  return { time_ms: nowMs + ms };
}
