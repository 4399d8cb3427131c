// One row of a toolbar or tab row whatever its width (issue 22 item 7): the items that do not fit leave for a
// "More" menu at the end, where each keeps its name and shortcut, as in CODESYS and VS Code. The bar measures
// its real width and its items' widths (a ResizeObserver, no fixed breakpoint) and asks ui/overflow.ts which fit.
// Every toolbar (LD, FBD/CFC, SFC, the simulation bar) and the bottom panels' tab row use it.
import { useLayoutEffect, useRef, useState, type ReactNode } from "react";
import { createPortal } from "react-dom";
import { Ellipsis } from "lucide-react";
import { fitItems } from "./overflow";
import { MenuList, type MenuItem } from "./MenuList";
import { ToolButton } from "./ToolButton";
import { COMMAND_ICONS, type Icon } from "./icons";

/** One item of a bar: what the bar shows, and what More shows for it when it does not fit. */
export interface BarItem {
  key: string;
  node: ReactNode;
  /** Its entries in More; an item without any (a status figure, the active tab) never leaves the bar. */
  entries?: readonly MenuItem[];
  /** How long it stays as the bar narrows: the lowest leaves first; among equals, the last (default 0). */
  priority?: number;
  /** Starts a group: a separator before it in the bar and in More. */
  group?: boolean;
}

/** A toolbar command: one description for its button in the bar and its entry in More. */
export interface Tool {
  id: string;
  icon: Icon;
  label: string;
  keys?: string;
  hint?: string;
  disabled?: boolean;
  run(): void;
}

/** A command as a bar item: an icon button that keeps the editor's focus, and the same command in More. */
export function toolItem(tool: Tool, options: Pick<BarItem, "group" | "priority"> = {}): BarItem {
  return {
    key: tool.id,
    node: (
      <ToolButton
        icon={tool.icon}
        label={tool.label}
        keys={tool.keys}
        hint={tool.hint}
        disabled={tool.disabled}
        onMouseDown={(e) => e.preventDefault()}
        onClick={tool.run}
      />
    ),
    entries: [{ id: tool.id, label: tool.label, keys: tool.keys, disabled: tool.disabled, run: tool.run }],
    ...options,
  };
}

/** The More button's width and the gap the bar keeps before it (styles.css .overflow-more). */
const MORE_WIDTH = 28;

export interface OverflowBarProps {
  items: readonly BarItem[];
  /** The bar's accessible name. */
  label?: string;
  role?: "toolbar" | "tablist" | "group";
  className?: string;
  /** The More button's name ("More tools", "More panels"). */
  moreLabel?: string;
}

export function OverflowBar({ items, label, role = "toolbar", className, moreLabel = "More" }: OverflowBarProps) {
  const bar = useRef<HTMLDivElement>(null);
  const more = useRef<HTMLButtonElement>(null);
  const [shown, setShown] = useState<readonly boolean[]>(() => items.map(() => true));
  const [menu, setMenu] = useState<{ right: number; top: number } | null>(null);
  const keys = items.map((item) => item.key).join(" ");
  const pinned = items.map((item) => !item.entries?.length).join(" ");

  useLayoutEffect(() => {
    const element = bar.current;
    if (!element) return;
    const measure = () => {
      const style = getComputedStyle(element);
      const gap = parseFloat(style.columnGap) || 0;
      const available =
        element.clientWidth - (parseFloat(style.paddingLeft) || 0) - (parseFloat(style.paddingRight) || 0);
      if (element.clientWidth === 0) return; // not laid out (hidden, or jsdom): nothing to measure, all stay
      const cells = [...element.querySelectorAll<HTMLElement>(":scope > .overflow-item")];
      const next = fitItems({
        widths: cells.map((cell) => cell.getBoundingClientRect().width),
        pinned: pinned.split(" ").map((p) => p === "true"),
        priority: items.map((item) => item.priority ?? 0),
        gap,
        available,
        more: MORE_WIDTH,
      });
      setShown((before) => (before.length === next.length && before.every((s, i) => s === next[i]) ? before : next));
    };
    measure();
    if (typeof ResizeObserver === "undefined") return; // jsdom (Vitest): no layout, every item shows
    const observer = new ResizeObserver(measure);
    observer.observe(element);
    for (const cell of element.querySelectorAll(":scope > .overflow-item")) observer.observe(cell);
    return () => observer.disconnect();
    // eslint-disable-next-line react-hooks/exhaustive-deps -- measured again when the items themselves change
  }, [keys, pinned]);

  const hidden = items.filter((_, i) => shown[i] === false);
  const groups: MenuItem[][] = [];
  for (const item of hidden) {
    if (item.group || groups.length === 0) groups.push([]);
    groups[groups.length - 1]!.push(...(item.entries ?? []));
  }
  const openMenu = () => {
    const box = more.current!.getBoundingClientRect();
    setMenu({ right: Math.max(0, document.documentElement.clientWidth - box.right), top: box.bottom + 2 });
  };
  const close = () => {
    setMenu(null);
    more.current?.focus();
  };
  return (
    <div ref={bar} className={`overflow-bar${className ? ` ${className}` : ""}`} role={role} aria-label={label}>
      {items.map((item, i) => (
        <span
          key={item.key}
          className={`overflow-item${item.group ? " overflow-group" : ""}${shown[i] === false ? " overflow-hidden" : ""}`}
          aria-hidden={shown[i] === false || undefined}
        >
          {item.node}
        </span>
      ))}
      {hidden.length ? (
        <MoreButton button={more} label={moreLabel} open={!!menu} onToggle={() => (menu ? close() : openMenu())} />
      ) : null}
      {menu && hidden.length
        ? createPortal(
            // under the More button, its right edge on the button's (the bar ends at the window's right)
            <div className="overflow-menu" style={{ right: menu.right, top: menu.top }}>
              <MenuList x={0} y={0} groups={groups} onClose={close} />
            </div>,
            document.body,
          )
        : null}
    </div>
  );
}

function MoreButton({
  button,
  label,
  open,
  onToggle,
}: {
  button: React.RefObject<HTMLButtonElement | null>;
  label: string;
  open: boolean;
  onToggle(): void;
}) {
  return (
    <ToolButton
      ref={button}
      icon={Ellipsis as Icon}
      label={label}
      hint="the commands that do not fit in the bar"
      className="overflow-more"
      aria-haspopup="menu"
      aria-expanded={open}
      onMouseDown={(e) => {
        e.preventDefault(); // keeps the editor's focus, and the menu's own outside-click does not close it first
        e.stopPropagation();
      }}
      onClick={onToggle}
    />
  );
}

/** The editors' "Shortcuts" button (the list of keys), the last of their toolbars. */
export function helpItem(open: boolean, toggle: () => void): BarItem {
  return {
    key: "shortcuts",
    node: <ToolButton icon={COMMAND_ICONS.shortcuts!} label="Shortcuts" aria-expanded={open} onClick={toggle} />,
    entries: [{ id: "shortcuts", label: "Shortcuts", run: toggle }],
    priority: 1,
  };
}
