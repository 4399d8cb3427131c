// Every editor action once: toolbar buttons, context menu items and keyboard shortcuts are all
// drawn from this table, so each action is reachable all three ways with the same rules.
import { locate, networksOf, type CoilMode, type ContactMode, type LdBody } from "../model";
import * as ops from "../ops";
import type { EditResult, ElementSpec } from "../ops";
import type { Selection } from "../view/types";

export interface CommandContext {
  body: LdBody;
  selection: Selection | null;
  readOnly: boolean;
  canUndo: boolean;
  canRedo: boolean;
  /** Records a successful edit and selects its result; "edit" then opens the new element's operand. */
  apply(result: EditResult, then?: "edit"): void;
  undo(): void;
  redo(): void;
  /** Opens the operand editor on the selected element's main operand. */
  editOperand(): void;
  openBoxPicker(): void;
  editNetwork(field: "label" | "comment"): void;
  copy(cut: boolean): void;
  paste(): void;
}

export type CommandGroup = "insert" | "edit" | "mode" | "network" | "clipboard" | "history";

export interface Command {
  id: string;
  label: string;
  group: CommandGroup;
  /** Shortcut as shown to the user, e.g. "Ctrl+Z"; also what the keyboard handler matches. */
  keys?: string;
  /** Edits the model (disabled while read-only). */
  edits: boolean;
  enabled(ctx: CommandContext): boolean;
  run(ctx: CommandContext): void;
}

type KeyPress = Pick<KeyboardEvent, "key" | "ctrlKey" | "metaKey" | "shiftKey" | "altKey">;

/** Whether a key press is the shortcut `keys` ("Ctrl+Shift+Z", "Alt+ArrowUp", "Delete / Backspace", "C", "Space"). */
export function matches(keys: string, event: KeyPress): boolean {
  return keys.split(" / ").some((alternative) => {
    const parts = alternative.split("+");
    const key = parts[parts.length - 1] === "Space" ? " " : parts[parts.length - 1]!;
    const mods = new Set(parts.slice(0, -1));
    return (
      event.key.toLowerCase() === key.toLowerCase() &&
      mods.has("Ctrl") === (event.ctrlKey || event.metaKey) &&
      mods.has("Alt") === event.altKey &&
      mods.has("Shift") === event.shiftKey
    );
  });
}

const selectedIds = (s: Selection | null): string[] => (s?.kind === "elements" ? s.ids : []);
const single = (ctx: CommandContext) => {
  const ids = selectedIds(ctx.selection);
  return ids.length === 1 ? locate(ctx.body, ids[0]!)?.element : undefined;
};
const hasTarget = (ctx: CommandContext) => ctx.selection !== null || networksOf(ctx.body).length === 0;

/** The network the selection is in (or is), for network commands. */
export function selectedNetwork(ctx: Pick<CommandContext, "body" | "selection">): string | undefined {
  const s = ctx.selection;
  if (!s) return undefined;
  if (s.kind === "network") return s.id;
  if (s.kind === "place") {
    const series = s.place.series;
    if (series.kind === "network") return series.network;
    return locate(ctx.body, series.kind === "branch" ? series.parallel : series.box)?.network;
  }
  const first = s.ids[0];
  return first ? locate(ctx.body, first)?.network : undefined;
}

/** Inserts next to the selection (a place, elements or a network); an empty POU gets a network first. */
export function insert(
  ctx: Pick<CommandContext, "body" | "selection">,
  spec: ElementSpec,
  side: "before" | "after",
): EditResult {
  const s = ctx.selection;
  if (!s && networksOf(ctx.body).length === 0) {
    const added = ops.addNetwork(ctx.body, 0);
    return added.ok ? ops.insertNear(added.body, { network: added.select[0]! }, spec) : added;
  }
  if (!s) return { ok: false, error: "select an element, a wire or a network first" };
  if (s.kind === "place") return ops.insertAt(ctx.body, s.place, spec);
  if (s.kind === "network") return ops.insertNear(ctx.body, { network: s.id }, spec);
  const anchor = side === "after" ? s.ids[s.ids.length - 1]! : s.ids[0]!;
  return ops.insertNear(ctx.body, { element: anchor, side }, spec);
}

const insertCommand = (
  id: string,
  label: string,
  keys: string,
  spec: () => ElementSpec,
  side: "before" | "after" = "after",
): Command => ({
  id,
  label,
  group: "insert",
  keys,
  edits: true,
  enabled: hasTarget,
  run: (ctx) => ctx.apply(insert(ctx, spec(), side), "edit"),
});

const CONTACT_LABELS: Record<ContactMode, string> = {
  no: "Normally open",
  nc: "Normally closed",
  p: "Rising edge (P)",
  n: "Falling edge (N)",
};
const COIL_LABELS: Record<CoilMode, string> = {
  normal: "Coil",
  negated: "Negated coil",
  set: "Set coil (S)",
  reset: "Reset coil (R)",
  p: "Rising edge coil (P)",
  n: "Falling edge coil (N)",
};

const modeCommands: Command[] = [
  ...(Object.keys(CONTACT_LABELS) as ContactMode[]).map((mode, i): Command => ({
    id: `contact-mode-${mode}`,
    label: CONTACT_LABELS[mode],
    group: "mode",
    keys: String(i + 1),
    edits: true,
    enabled: (ctx) => single(ctx)?.type === "contact",
    run: (ctx) => ctx.apply(ops.setMode(ctx.body, selectedIds(ctx.selection)[0]!, mode)),
  })),
  ...(Object.keys(COIL_LABELS) as CoilMode[]).map((mode, i): Command => ({
    id: `coil-mode-${mode}`,
    label: COIL_LABELS[mode],
    group: "mode",
    keys: String(i + 1),
    edits: true,
    enabled: (ctx) => single(ctx)?.type === "coil",
    run: (ctx) => ctx.apply(ops.setMode(ctx.body, selectedIds(ctx.selection)[0]!, mode)),
  })),
];

function networkIndex(ctx: CommandContext): number {
  const id = selectedNetwork(ctx);
  return networksOf(ctx.body).findIndex((n) => n.id === id);
}

export const COMMANDS: Command[] = [
  insertCommand("contact", "Contact", "C", () => ops.contact("no")),
  insertCommand("contact-before", "Contact before", "Shift+C", () => ops.contact("no"), "before"),
  insertCommand("contact-nc", "NC contact", "N", () => ops.contact("nc")),
  insertCommand("coil", "Coil", "O", () => ops.coil("normal")),
  insertCommand("compare", "Compare", "M", () => ops.compare("GT")),
  {
    id: "box",
    label: "Box…",
    group: "insert",
    keys: "B",
    edits: true,
    enabled: hasTarget,
    run: (ctx) => ctx.openBoxPicker(),
  },
  insertCommand("jump", "Jump", "J", () => ops.jump("")),
  insertCommand("return", "Return", "R", () => ops.ret()),
  {
    id: "parallel",
    label: "Parallel branch",
    group: "insert",
    keys: "P",
    edits: true,
    enabled: (ctx) => selectedIds(ctx.selection).length > 0,
    run: (ctx) => ctx.apply(ops.wrapInParallel(ctx.body, selectedIds(ctx.selection))),
  },
  {
    id: "add-branch",
    label: "Add branch",
    group: "insert",
    keys: "Shift+P",
    edits: true,
    enabled: (ctx) => single(ctx)?.type === "parallel",
    run: (ctx) => ctx.apply(ops.addBranch(ctx.body, selectedIds(ctx.selection)[0]!)),
  },
  {
    id: "edit-operand",
    label: "Edit operand",
    group: "edit",
    keys: "Enter / F2",
    edits: true,
    enabled: (ctx) => {
      const e = single(ctx);
      return e !== undefined && e.type !== "parallel" && e.type !== "return";
    },
    run: (ctx) => ctx.editOperand(),
  },
  {
    id: "cycle-mode",
    label: "Next mode",
    group: "edit",
    keys: "Space",
    edits: true,
    enabled: (ctx) => ["contact", "coil", "compare"].includes(single(ctx)?.type ?? ""),
    run: (ctx) => ctx.apply(ops.cycleMode(ctx.body, selectedIds(ctx.selection)[0]!)),
  },
  {
    id: "toggle-en",
    label: "EN/ENO",
    group: "edit",
    keys: "E",
    edits: true,
    enabled: (ctx) => single(ctx)?.type === "box",
    run: (ctx) => ctx.apply(ops.toggleEn(ctx.body, selectedIds(ctx.selection)[0]!)),
  },
  {
    id: "delete",
    label: "Delete",
    group: "edit",
    keys: "Delete / Backspace",
    edits: true,
    enabled: (ctx) => ctx.selection?.kind === "elements" || ctx.selection?.kind === "network",
    run: (ctx) => {
      const s = ctx.selection!;
      ctx.apply(
        s.kind === "network" ? ops.deleteNetworks(ctx.body, [s.id]) : ops.deleteElements(ctx.body, selectedIds(s)),
      );
    },
  },
  ...modeCommands,
  {
    id: "network-add",
    label: "New network below",
    group: "network",
    keys: "Ctrl+Enter",
    edits: true,
    enabled: () => true,
    run: (ctx) => {
      const index = networkIndex(ctx);
      ctx.apply(ops.addNetwork(ctx.body, index < 0 ? networksOf(ctx.body).length : index + 1));
    },
  },
  {
    id: "network-add-above",
    label: "New network above",
    group: "network",
    keys: "Ctrl+Shift+Enter",
    edits: true,
    enabled: () => true,
    run: (ctx) => ctx.apply(ops.addNetwork(ctx.body, Math.max(0, networkIndex(ctx)))),
  },
  {
    id: "network-duplicate",
    label: "Duplicate network",
    group: "network",
    keys: "Ctrl+D",
    edits: true,
    enabled: (ctx) => selectedNetwork(ctx) !== undefined,
    run: (ctx) => ctx.apply(ops.duplicateNetwork(ctx.body, selectedNetwork(ctx)!)),
  },
  {
    id: "network-up",
    label: "Move network up",
    group: "network",
    keys: "Alt+ArrowUp",
    edits: true,
    enabled: (ctx) => networkIndex(ctx) > 0,
    run: (ctx) => ctx.apply(ops.moveNetwork(ctx.body, selectedNetwork(ctx)!, networkIndex(ctx) - 1)),
  },
  {
    id: "network-down",
    label: "Move network down",
    group: "network",
    keys: "Alt+ArrowDown",
    edits: true,
    enabled: (ctx) => {
      const i = networkIndex(ctx);
      return i >= 0 && i < networksOf(ctx.body).length - 1;
    },
    run: (ctx) => ctx.apply(ops.moveNetwork(ctx.body, selectedNetwork(ctx)!, networkIndex(ctx) + 1)),
  },
  {
    id: "network-label",
    label: "Network label…",
    group: "network",
    keys: "L",
    edits: true,
    enabled: (ctx) => selectedNetwork(ctx) !== undefined,
    run: (ctx) => ctx.editNetwork("label"),
  },
  {
    id: "network-comment",
    label: "Network comment…",
    group: "network",
    keys: "K",
    edits: true,
    enabled: (ctx) => selectedNetwork(ctx) !== undefined,
    run: (ctx) => ctx.editNetwork("comment"),
  },
  {
    id: "network-delete",
    label: "Delete network",
    group: "network",
    keys: "Ctrl+Delete",
    edits: true,
    enabled: (ctx) => selectedNetwork(ctx) !== undefined,
    run: (ctx) => ctx.apply(ops.deleteNetworks(ctx.body, [selectedNetwork(ctx)!])),
  },
  {
    id: "copy",
    label: "Copy",
    group: "clipboard",
    keys: "Ctrl+C",
    edits: false,
    enabled: (ctx) => ctx.selection?.kind === "elements" || ctx.selection?.kind === "network",
    run: (ctx) => ctx.copy(false),
  },
  {
    id: "cut",
    label: "Cut",
    group: "clipboard",
    keys: "Ctrl+X",
    edits: true,
    enabled: (ctx) => ctx.selection?.kind === "elements" || ctx.selection?.kind === "network",
    run: (ctx) => ctx.copy(true),
  },
  {
    id: "paste",
    label: "Paste",
    group: "clipboard",
    keys: "Ctrl+V",
    edits: true,
    enabled: () => true,
    run: (ctx) => ctx.paste(),
  },
  {
    id: "undo",
    label: "Undo",
    group: "history",
    keys: "Ctrl+Z",
    edits: true,
    enabled: (ctx) => ctx.canUndo,
    run: (ctx) => ctx.undo(),
  },
  {
    id: "redo",
    label: "Redo",
    group: "history",
    keys: "Ctrl+Y / Ctrl+Shift+Z",
    edits: true,
    enabled: (ctx) => ctx.canRedo,
    run: (ctx) => ctx.redo(),
  },
];

/** Whether a command may run now (edits are off while read-only). */
export const available = (command: Command, ctx: CommandContext): boolean =>
  (!command.edits || !ctx.readOnly) && command.enabled(ctx);

/** The command a key press means in this context, if any. */
export function commandForKey(event: KeyPress, ctx: CommandContext): Command | undefined {
  return COMMANDS.find((c) => c.keys !== undefined && matches(c.keys, event) && available(c, ctx));
}
