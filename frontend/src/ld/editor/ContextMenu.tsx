// Right-click menu: the commands available for what was clicked, grouped like the toolbar.
import { useEffect, useRef } from "react";
import { available, COMMANDS, type Command, type CommandContext, type CommandGroup } from "./commands";

const GROUP_ORDER: CommandGroup[] = ["insert", "mode", "edit", "clipboard", "network", "history"];

/** An item that is not an editor command (breakpoints; online: write, force, watch). */
export interface MenuItem {
  id: string;
  label: string;
  /** Its shortcut, shown like a command's. */
  keys?: string;
  run(): void;
}

export interface ContextMenuProps {
  x: number;
  y: number;
  /** The editor's commands are offered for this context; without one, only `extra` (the ST editor's online menu). */
  ctx?: CommandContext;
  /** Shown first, as their own group. */
  extra?: readonly MenuItem[];
  onClose(): void;
}

export function ContextMenu({ x, y, ctx, extra = [], onClose }: ContextMenuProps) {
  const menu = useRef<HTMLUListElement>(null);
  useEffect(() => {
    menu.current?.querySelector<HTMLButtonElement>("button")?.focus();
    const close = (e: MouseEvent) => {
      if (!menu.current?.contains(e.target as Node)) onClose();
    };
    window.addEventListener("mousedown", close);
    return () => window.removeEventListener("mousedown", close);
  }, [onClose]);
  const groups = ctx ? GROUP_ORDER.map((group) => COMMANDS.filter((c) => c.group === group && available(c, ctx))).filter((g) => g.length) : [];
  const run = (command: Pick<Command, "run">) => {
    onClose();
    command.run(ctx!);
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
        const items = [...(menu.current?.querySelectorAll<HTMLButtonElement>("button") ?? [])];
        const at = items.indexOf(document.activeElement as HTMLButtonElement);
        if (e.key === "ArrowDown") items[(at + 1) % items.length]?.focus();
        if (e.key === "ArrowUp") items[(at - 1 + items.length) % items.length]?.focus();
      }}
    >
      {extra.length ? (
        <li role="none">
          <ul role="none">
            {extra.map((item) => (
              <li key={item.id} role="none">
                <button type="button" role="menuitem" onClick={() => run({ run: item.run })}>
                  <span>{item.label}</span>
                  {item.keys ? <kbd>{item.keys}</kbd> : null}
                </button>
              </li>
            ))}
          </ul>
        </li>
      ) : null}
      {groups.map((group, i) => (
        <li key={group[0]!.group} role="none" className={i > 0 || extra.length ? "ld-menu-group" : undefined}>
          <ul role="none">
            {group.map((command) => (
              <li key={command.id} role="none">
                <button type="button" role="menuitem" onClick={() => run(command)}>
                  <span>{command.label}</span>
                  {command.keys ? <kbd>{command.keys}</kbd> : null}
                </button>
              </li>
            ))}
          </ul>
        </li>
      ))}
    </ul>
  );
}
