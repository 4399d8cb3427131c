// Zooming a diagram (LD, FBD, SFC): the steps of Ctrl+wheel and the zoom keys, and "fit", the zoom at
// which the whole diagram fits the view. Pure geometry, tested without a browser (zoom.test.ts).

/** What a zoom key or button asks for; "fit" is measured by the editor and arrives as a zoom value. */
export type ZoomStep = "in" | "out" | "reset";

export interface Size {
  width: number;
  height: number;
}

/** The zoom range of the keys and the wheel: 50 % to 200 %. */
export const ZOOM_MIN = 0.5;
export const ZOOM_MAX = 2;
/** Fit goes further down, so a long POU still fits (TwinCAT's zoom list starts at 25 % too). */
export const FIT_MIN = 0.25;

const clamp = (zoom: number, min: number, max: number) => Math.min(max, Math.max(min, zoom));

/**
 * The largest zoom at which `content` (at zoom 1) fits inside `view`, within [min, max], rounded down
 * to whole percent so rounding never lets the diagram overflow. A diagram too large even at `min` stays
 * at `min` (the view scrolls); an empty diagram or view keeps 100 %.
 */
export function fitZoom(content: Size, view: Size, min = FIT_MIN, max = ZOOM_MAX): number {
  if (content.width <= 0 || content.height <= 0 || view.width <= 0 || view.height <= 0) return 1;
  const zoom = Math.min(view.width / content.width, view.height / content.height);
  return clamp(Math.floor(zoom * 100) / 100, min, max);
}

/**
 * The next zoom in 10 % steps from 50 % to 200 % (LD); reset is 100 %. Below 50 % (a fit) zooming out
 * stays and zooming in steps up from there.
 */
export function zoomed(zoom: number, step: ZoomStep): number {
  if (step === "reset") return 1;
  const next = Math.round((zoom + (step === "in" ? 0.1 : -0.1)) * 10) / 10;
  return clamp(next, Math.min(zoom, ZOOM_MIN), ZOOM_MAX);
}

/** The next of `levels` (ascending) above or below `zoom` (SFC's preset levels); reset is 100 %. */
export function zoomedTo(levels: readonly number[], zoom: number, step: ZoomStep): number {
  if (step === "reset") return 1;
  const next = step === "in" ? levels.find((l) => l > zoom + 1e-9) : [...levels].reverse().find((l) => l < zoom - 1e-9);
  return next ?? zoom;
}
