// The LD right-click menu: the commands available for what was clicked, grouped like the toolbar (ui/MenuList).
import { MenuList, type MenuItem } from "../../ui/MenuList";
import { available, commandKeys, COMMANDS, type CommandContext, type CommandGroup } from "./commands";

const GROUP_ORDER: CommandGroup[] = ["insert", "mode", "edit", "clipboard", "network", "history"];

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
  const groups = ctx
    ? GROUP_ORDER.map((group) => COMMANDS.filter((c) => c.group === group && available(c, ctx))).filter((g) => g.length)
    : [];
  const items = groups.map((group) =>
    group.map((c): MenuItem => ({ id: c.id, label: c.label, keys: commandKeys(c), run: () => c.run(ctx!) })),
  );
  return <MenuList x={x} y={y} groups={extra.length ? [[...extra], ...items] : items} onClose={onClose} />;
}
