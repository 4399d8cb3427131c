// Which items of a bar fit its width (issue 22 item 7: one compact row per toolbar, the rest in "More", as
// CODESYS and VS Code do it). Pure: the bar measures its items and its width (ui/OverflowBar.tsx) and asks.

export interface FitRequest {
  /** Each item's width in px, in the bar's order. */
  widths: readonly number[];
  /** The items that stay whatever the width (a status figure, the active tab): they have no menu entry. */
  pinned: readonly boolean[];
  /** How long each item stays as the bar narrows: the lowest goes first; among equals, the last one. */
  priority?: readonly number[];
  /** The space between two items (the bar's CSS gap). */
  gap: number;
  /** The bar's inner width. */
  available: number;
  /** The width of the "More" button that replaces what does not fit. */
  more: number;
}

/** The width of a row of items of these widths, `gap` apart. */
export function rowWidth(widths: readonly number[], gap: number): number {
  return widths.length ? widths.reduce((sum, w) => sum + w, 0) + gap * (widths.length - 1) : 0;
}

/**
 * Which items the bar shows (true) and which go into its More menu (false): all when they fit; else the More
 * button takes its place at the end and items leave, the lowest priority first (among equals the last),
 * until the rest fits. Pinned items never leave, even when they alone are too wide.
 */
export function fitItems({ widths, pinned, priority, gap, available, more }: FitRequest): boolean[] {
  const shown = widths.map(() => true);
  if (rowWidth(widths, gap) <= available) return shown;
  const leaving = widths
    .map((_, i) => i)
    .filter((i) => !pinned[i])
    .sort((a, b) => (priority?.[a] ?? 0) - (priority?.[b] ?? 0) || b - a);
  const width = () =>
    rowWidth(
      widths.filter((_, i) => shown[i]),
      gap,
    ) +
    gap +
    more;
  for (const i of leaving) {
    if (width() <= available) break;
    shown[i] = false;
  }
  return shown;
}
