// Side and bottom panels the user may hide for room (the project list, the project tree, the bottom
// panels), and the sizes the user dragged them to, kept per browser in localStorage so the layout stays
// as the user left it.
import { useCallback, useState } from "react";

export type Collapsible = "projects" | "tree" | "panels";

const key = (panel: Collapsible) => `ladderlab:layout:${panel}-hidden`;

/** Whether `panel` is hidden, and the toggle. */
export function useHidden(panel: Collapsible, storage: Storage = localStorage): [boolean, () => void] {
  const [hidden, setHidden] = useState(() => storage.getItem(key(panel)) === "1");
  const toggle = useCallback(() => {
    setHidden((was) => {
      if (was) storage.removeItem(key(panel));
      else storage.setItem(key(panel), "1");
      return !was;
    });
  }, [panel, storage]);
  return [hidden, toggle];
}

export type Resizable = "projects" | "tree" | "panels";

const sizeKey = (panel: Resizable) => `ladderlab:layout:${panel}-size`;

/** The size (px) the user last gave `panel`, or null for the default. */
export function storedSize(panel: Resizable, storage: Storage = localStorage): number | null {
  const px = Number(storage.getItem(sizeKey(panel)));
  return Number.isFinite(px) && px > 0 ? px : null;
}

export function storeSize(panel: Resizable, px: number, storage: Storage = localStorage): void {
  storage.setItem(sizeKey(panel), String(px));
}

/** A side panel's width, kept between `min` and `max` px and across reloads, and its setter. */
export function useStoredSize(
  panel: Resizable,
  min: number,
  max: number,
  storage: Storage = localStorage,
): [number | null, (px: number) => void] {
  const [size, setSize] = useState(() => storedSize(panel, storage));
  const resize = useCallback(
    (px: number) => {
      const kept = Math.round(Math.max(min, Math.min(max, px)));
      storeSize(panel, kept, storage);
      setSize(kept);
    },
    [panel, min, max, storage],
  );
  return [size, resize];
}
