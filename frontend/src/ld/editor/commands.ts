// Every editor action once: toolbar buttons, context menu items and keyboard shortcuts are all
// drawn from this table, so each action is reachable all three ways with the same rules. The keys
// are the keymap's (src/keys/keymap.ts, scope "ld"), by command id.
import { locate, networksOf, type CoilMode, type ContactMode, type LdBody } from "../model";
import * as ops from "../ops";
import type { EditResult, ElementSpec } from "../ops";
import type { Selection } from "../view/types";
import { commandsFor, keysOf, type KeyPress } from "../../keys/keymap";

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
  /** Edits the model (disabled while read-only). */
  edits: boolean;
  enabled(ctx: CommandContext): boolean;
  run(ctx: CommandContext): void;
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
  spec: () => ElementSpec,
  side: "before" | "after" = "after",
): Command => ({
  id,
  label,
  group: "insert",
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
  ...(Object.keys(CONTACT_LABELS) as ContactMode[]).map((mode): Command => ({
    id: `contact-mode-${mode}`,
    label: CONTACT_LABELS[mode],
    group: "mode",
    edits: true,
    enabled: (ctx) => single(ctx)?.type === "contact",
    run: (ctx) => ctx.apply(ops.setMode(ctx.body, selectedIds(ctx.selection)[0]!, mode)),
  })),
  ...(Object.keys(COIL_LABELS) as CoilMode[]).map((mode): Command => ({
    id: `coil-mode-${mode}`,
    label: COIL_LABELS[mode],
    group: "mode",
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
  insertCommand("contact", "Contact", () => ops.contact("no")),
  insertCommand("contact-before", "Contact before", () => ops.contact("no"), "before"),
  insertCommand("contact-nc", "NC contact", () => ops.contact("nc")),
  insertCommand("coil", "Coil", () => ops.coil("normal")),
  insertCommand("compare", "Compare", () => ops.compare("GT")),
  {
    id: "box",
    label: "Box…",
    group: "insert",
    edits: true,
    enabled: hasTarget,
    run: (ctx) => ctx.openBoxPicker(),
  },
  insertCommand("jump", "Jump", () => ops.jump("")),
  insertCommand("return", "Return", () => ops.ret()),
  {
    id: "parallel",
    label: "Parallel branch",
    group: "insert",
    edits: true,
    enabled: (ctx) => selectedIds(ctx.selection).length > 0,
    run: (ctx) => ctx.apply(ops.wrapInParallel(ctx.body, selectedIds(ctx.selection))),
  },
  {
    id: "add-branch",
    label: "Add branch",
    group: "insert",
    edits: true,
    enabled: (ctx) => single(ctx)?.type === "parallel",
    run: (ctx) => ctx.apply(ops.addBranch(ctx.body, selectedIds(ctx.selection)[0]!)),
  },
  {
    id: "edit-operand",
    label: "Edit operand",
    group: "edit",
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
    edits: true,
    enabled: (ctx) => ["contact", "coil", "compare"].includes(single(ctx)?.type ?? ""),
    run: (ctx) => ctx.apply(ops.cycleMode(ctx.body, selectedIds(ctx.selection)[0]!)),
  },
  {
    id: "toggle-en",
    label: "EN/ENO",
    group: "edit",
    edits: true,
    enabled: (ctx) => single(ctx)?.type === "box",
    run: (ctx) => ctx.apply(ops.toggleEn(ctx.body, selectedIds(ctx.selection)[0]!)),
  },
  {
    id: "delete",
    label: "Delete",
    group: "edit",
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
    edits: true,
    enabled: () => true,
    run: (ctx) => ctx.apply(ops.addNetwork(ctx.body, Math.max(0, networkIndex(ctx)))),
  },
  {
    id: "network-duplicate",
    label: "Duplicate network",
    group: "network",
    edits: true,
    enabled: (ctx) => selectedNetwork(ctx) !== undefined,
    run: (ctx) => ctx.apply(ops.duplicateNetwork(ctx.body, selectedNetwork(ctx)!)),
  },
  {
    id: "network-up",
    label: "Move network up",
    group: "network",
    edits: true,
    enabled: (ctx) => networkIndex(ctx) > 0,
    run: (ctx) => ctx.apply(ops.moveNetwork(ctx.body, selectedNetwork(ctx)!, networkIndex(ctx) - 1)),
  },
  {
    id: "network-down",
    label: "Move network down",
    group: "network",
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
    edits: true,
    enabled: (ctx) => selectedNetwork(ctx) !== undefined,
    run: (ctx) => ctx.editNetwork("label"),
  },
  {
    id: "network-comment",
    label: "Network comment…",
    group: "network",
    edits: true,
    enabled: (ctx) => selectedNetwork(ctx) !== undefined,
    run: (ctx) => ctx.editNetwork("comment"),
  },
  {
    id: "network-delete",
    label: "Delete network",
    group: "network",
    edits: true,
    enabled: (ctx) => selectedNetwork(ctx) !== undefined,
    run: (ctx) => ctx.apply(ops.deleteNetworks(ctx.body, [selectedNetwork(ctx)!])),
  },
  {
    id: "copy",
    label: "Copy",
    group: "clipboard",
    edits: false,
    enabled: (ctx) => ctx.selection?.kind === "elements" || ctx.selection?.kind === "network",
    run: (ctx) => ctx.copy(false),
  },
  {
    id: "cut",
    label: "Cut",
    group: "clipboard",
    edits: true,
    enabled: (ctx) => ctx.selection?.kind === "elements" || ctx.selection?.kind === "network",
    run: (ctx) => ctx.copy(true),
  },
  {
    id: "paste",
    label: "Paste",
    group: "clipboard",
    edits: true,
    enabled: () => true,
    run: (ctx) => ctx.paste(),
  },
  {
    id: "undo",
    label: "Undo",
    group: "history",
    edits: true,
    enabled: (ctx) => ctx.canUndo,
    run: (ctx) => ctx.undo(),
  },
  {
    id: "redo",
    label: "Redo",
    group: "history",
    edits: true,
    enabled: (ctx) => ctx.canRedo,
    run: (ctx) => ctx.redo(),
  },
];

/** Whether a command may run now (edits are off while read-only). */
export const available = (command: Command, ctx: CommandContext): boolean =>
  (!command.edits || !ctx.readOnly) && command.enabled(ctx);

/** The command a key press means in this context, if any (of those the keymap binds to it, the first available). */
export function commandForKey(event: KeyPress, ctx: CommandContext): Command | undefined {
  return commandsFor("ld", event)
    .map((id) => COMMANDS.find((c) => c.id === id))
    .find((c) => c !== undefined && available(c, ctx));
}

/** A command's keys as tooltips and menus show them ("" without). */
export const commandKeys = (command: Pick<Command, "id">): string => keysOf("ld", command.id);
