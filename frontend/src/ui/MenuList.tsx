// A right-click menu of grouped items (the LD, FBD and SFC diagrams, the ST editor's online menu):
// keyboard-driven (arrows, Escape), closed by a click outside or after running an item.
import { useEffect, useRef } from "react";

/** One item: an editor command, a breakpoint, an online command (write, force, watch)... */
export interface MenuItem {
  id: string;
  label: string;
  /** Its shortcut, shown like a command's. */
  keys?: string;
  /** Shown but not runnable now (a toolbar command moved into a More menu keeps its state). */
  disabled?: boolean;
  run(): void;
}

/** A menu of grouped items at (x, y); closes on a click outside, Escape, or after running an item. */
export function MenuList({
  x,
  y,
  groups,
  onClose,
}: {
  x: number;
  y: number;
  groups: readonly (readonly MenuItem[])[];
  onClose(): void;
}) {
  const menu = useRef<HTMLUListElement>(null);
  useEffect(() => {
    menu.current?.querySelector<HTMLButtonElement>("button:not(:disabled)")?.focus();
    const close = (e: MouseEvent) => {
      if (!menu.current?.contains(e.target as Node)) onClose();
    };
    window.addEventListener("mousedown", close);
    return () => window.removeEventListener("mousedown", close);
  }, [onClose]);
  const run = (item: MenuItem) => {
    onClose();
    item.run();
  };
  return (
    <ul
      ref={menu}
      className="ld-context-menu"
      role="menu"
      style={{ left: x, top: y }}
      onKeyDown={(e) => {
        e.stopPropagation();
        if (e.key === "Escape") onClose();
        const items = [...(menu.current?.querySelectorAll<HTMLButtonElement>("button:not(:disabled)") ?? [])];
        const at = items.indexOf(document.activeElement as HTMLButtonElement);
        if (e.key === "ArrowDown") items[(at + 1) % items.length]?.focus();
        if (e.key === "ArrowUp") items[(at - 1 + items.length) % items.length]?.focus();
      }}
    >
      {groups.map((group, i) => (
        <li key={group[0]?.id ?? i} role="none" className={i > 0 ? "ld-menu-group" : undefined}>
          <ul role="none">
            {group.map((item) => (
              <li key={item.id} role="none">
                <button type="button" role="menuitem" disabled={item.disabled} onClick={() => run(item)}>
                  <span>{item.label}</span>
                  {item.keys ? <kbd>{item.keys}</kbd> : null}
                </button>
              </li>
            ))}
          </ul>
        </li>
      ))}
    </ul>
  );
}
