// Side and bottom panels the user may hide for room (the project list, the project tree, the bottom
// panels), kept per browser in localStorage so the layout stays as the user left it.
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
