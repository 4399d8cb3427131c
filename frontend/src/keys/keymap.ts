// Every keyboard shortcut of the app in one table: the app's own keys (CODESYS's for online mode and
// debugging), and those of the LD, FBD and ST editors. The key handlers look keys up here and the
// shortcut help lists this table, so the help cannot disagree with what the keys do (issue 17).
// A binding matches only its exact modifiers: a combination the table does not list does nothing.

export type KeyScope = "app" | "ld" | "fbd" | "st" | "sfc";

export interface KeyBinding {
  scope: KeyScope;
  /** What the key does, as the scope's handlers name it. */
  command: string;
  /** As shown and matched: "Ctrl+F7", "Delete / Backspace" (alternatives), "Space". */
  keys: string;
  /** What the help says it does. */
  label: string;
}

const APP = [
  { scope: "app", command: "save", keys: "Ctrl+S", label: "Save the project" },
  { scope: "app", command: "check", keys: "Ctrl+Shift+B", label: "Check the project (build)" },
  { scope: "app", command: "go-online", keys: "Alt+F8", label: "Compile & simulate (go online)" },
  { scope: "app", command: "go-offline", keys: "Ctrl+F8", label: "Go offline" },
  { scope: "app", command: "run", keys: "F5", label: "Run; continue a halted scan" },
  { scope: "app", command: "stop", keys: "Shift+F5", label: "Stop" },
  { scope: "app", command: "single-cycle", keys: "Ctrl+F5", label: "Single cycle: one scan, then stopped" },
  { scope: "app", command: "force-prepared", keys: "F7", label: "Force the prepared values" },
  { scope: "app", command: "write-prepared", keys: "Ctrl+F7", label: "Write the prepared values" },
  { scope: "app", command: "release-forces", keys: "Alt+F7", label: "Release all forces" },
  {
    scope: "app",
    command: "step-over",
    keys: "F10",
    label: "Step over: the next network or statement of this POU (or of its caller once it returns)",
  },
  { scope: "app", command: "step-into", keys: "F11", label: "Step into: the next statement, also in called POUs" },
  { scope: "app", command: "step-out", keys: "Shift+F11", label: "Step out: run until the caller goes on" },
  {
    scope: "app",
    command: "step-transition",
    keys: "Ctrl+F11",
    label: "Step to the next SFC transition that fires (scans run until one does)",
  },
] as const;

/**
 * Zoom to fit: CODESYS and TwinCAT offer it only in the zoom list of their toolbars, with no key; this is
 * draw.io's "Fit window" key (Ctrl+0 stays "100 %", as in browsers and the LD editor before).
 */
const FIT_KEYS = "Ctrl+Shift+H";

const LD = [
  { scope: "ld", command: "contact", keys: "C", label: "Insert a contact after the selection" },
  { scope: "ld", command: "contact-before", keys: "Shift+C", label: "Insert a contact before the selection" },
  { scope: "ld", command: "contact-nc", keys: "N", label: "Insert a normally closed contact" },
  { scope: "ld", command: "coil", keys: "O", label: "Insert a coil" },
  { scope: "ld", command: "compare", keys: "M", label: "Insert a compare contact" },
  { scope: "ld", command: "box", keys: "B", label: "Insert a box (function or function block)" },
  { scope: "ld", command: "jump", keys: "J", label: "Insert a jump" },
  { scope: "ld", command: "return", keys: "R", label: "Insert a return" },
  { scope: "ld", command: "parallel", keys: "P", label: "Put the selection in a parallel branch" },
  { scope: "ld", command: "add-branch", keys: "Shift+P", label: "Add a branch to the selected parallel" },
  { scope: "ld", command: "edit-operand", keys: "Enter / F2", label: "Edit the operand" },
  { scope: "ld", command: "cycle-mode", keys: "Space", label: "Next mode of the contact, coil or compare" },
  { scope: "ld", command: "toggle-en", keys: "E", label: "EN/ENO on the box" },
  { scope: "ld", command: "delete", keys: "Delete / Backspace", label: "Delete" },
  { scope: "ld", command: "contact-mode-no", keys: "1", label: "Contact: normally open" },
  { scope: "ld", command: "contact-mode-nc", keys: "2", label: "Contact: normally closed" },
  { scope: "ld", command: "contact-mode-p", keys: "3", label: "Contact: rising edge (P)" },
  { scope: "ld", command: "contact-mode-n", keys: "4", label: "Contact: falling edge (N)" },
  { scope: "ld", command: "coil-mode-normal", keys: "1", label: "Coil: normal" },
  { scope: "ld", command: "coil-mode-negated", keys: "2", label: "Coil: negated" },
  { scope: "ld", command: "coil-mode-set", keys: "3", label: "Coil: set (S)" },
  { scope: "ld", command: "coil-mode-reset", keys: "4", label: "Coil: reset (R)" },
  { scope: "ld", command: "coil-mode-p", keys: "5", label: "Coil: rising edge (P)" },
  { scope: "ld", command: "coil-mode-n", keys: "6", label: "Coil: falling edge (N)" },
  { scope: "ld", command: "network-add", keys: "Ctrl+Enter", label: "New network below" },
  { scope: "ld", command: "network-add-above", keys: "Ctrl+Shift+Enter", label: "New network above" },
  { scope: "ld", command: "network-duplicate", keys: "Ctrl+D", label: "Duplicate the network" },
  { scope: "ld", command: "network-up", keys: "Alt+ArrowUp", label: "Move the network up" },
  { scope: "ld", command: "network-down", keys: "Alt+ArrowDown", label: "Move the network down" },
  { scope: "ld", command: "network-label", keys: "L", label: "Edit the network label" },
  { scope: "ld", command: "network-comment", keys: "K", label: "Edit the network comment" },
  { scope: "ld", command: "network-delete", keys: "Ctrl+Delete", label: "Delete the network" },
  { scope: "ld", command: "copy", keys: "Ctrl+C", label: "Copy" },
  { scope: "ld", command: "cut", keys: "Ctrl+X", label: "Cut" },
  { scope: "ld", command: "paste", keys: "Ctrl+V", label: "Paste" },
  { scope: "ld", command: "undo", keys: "Ctrl+Z", label: "Undo" },
  { scope: "ld", command: "redo", keys: "Ctrl+Y / Ctrl+Shift+Z", label: "Redo" },
  {
    scope: "ld",
    command: "move-selection",
    keys: "ArrowLeft / ArrowRight / ArrowUp / ArrowDown",
    label: "Move the selection through the rung and between networks",
  },
  {
    scope: "ld",
    command: "extend-selection",
    keys: "Shift+ArrowLeft / Shift+ArrowRight",
    label: "Extend the selection along a branch",
  },
  { scope: "ld", command: "clear-selection", keys: "Escape", label: "Clear the selection" },
  { scope: "ld", command: "zoom-in", keys: "Ctrl+= / Ctrl++", label: "Zoom in (also Ctrl+wheel)" },
  { scope: "ld", command: "zoom-out", keys: "Ctrl+-", label: "Zoom out (also Ctrl+wheel)" },
  { scope: "ld", command: "zoom-reset", keys: "Ctrl+0", label: "Zoom to 100 %" },
  { scope: "ld", command: "zoom-fit", keys: FIT_KEYS, label: "Zoom to fit the whole diagram in the view" },
  {
    scope: "ld",
    command: "toggle-breakpoint",
    keys: "F9",
    label: "Toggle a breakpoint on the selected element or network",
  },
] as const;

const FBD = [
  { scope: "fbd", command: "delete", keys: "Delete / Backspace", label: "Delete the selection" },
  { scope: "fbd", command: "copy", keys: "Ctrl+C", label: "Copy" },
  { scope: "fbd", command: "cut", keys: "Ctrl+X", label: "Cut" },
  { scope: "fbd", command: "paste", keys: "Ctrl+V", label: "Paste" },
  { scope: "fbd", command: "undo", keys: "Ctrl+Z", label: "Undo" },
  { scope: "fbd", command: "redo", keys: "Ctrl+Y / Ctrl+Shift+Z", label: "Redo" },
  { scope: "fbd", command: "run-earlier", keys: "Alt+ArrowUp", label: "Run the selected block earlier" },
  { scope: "fbd", command: "run-later", keys: "Alt+ArrowDown", label: "Run the selected block later" },
  { scope: "fbd", command: "clear-selection", keys: "Escape", label: "Clear the selection" },
  { scope: "fbd", command: "zoom-fit", keys: FIT_KEYS, label: "Zoom every network to fit its canvas" },
  {
    scope: "fbd",
    command: "toggle-breakpoint",
    keys: "F9",
    label: "Toggle a breakpoint on the selected node or network",
  },
] as const;

const SFC = [
  { scope: "sfc", command: "insert-step", keys: "S", label: "Insert a step and a transition below the selection" },
  { scope: "sfc", command: "alternative", keys: "A", label: "Alternative branch: divide the transition" },
  { scope: "sfc", command: "parallel", keys: "P", label: "Simultaneous branch: divide the step" },
  { scope: "sfc", command: "jump", keys: "J", label: "Jump at the end of the sequence" },
  { scope: "sfc", command: "associate", keys: "Q", label: "Associate an action with the step (qualifier picker)" },
  { scope: "sfc", command: "edit", keys: "Enter / F2", label: "Edit the step name, the condition or the jump target" },
  { scope: "sfc", command: "open", keys: "Ctrl+Enter", label: "Open the action of the selected association" },
  { scope: "sfc", command: "delete", keys: "Delete / Backspace", label: "Delete the selection with its partner" },
  { scope: "sfc", command: "delete-branch", keys: "Shift+Delete", label: "Delete the branch of the selection" },
  { scope: "sfc", command: "copy", keys: "Ctrl+C", label: "Copy" },
  { scope: "sfc", command: "cut", keys: "Ctrl+X", label: "Cut" },
  { scope: "sfc", command: "paste", keys: "Ctrl+V", label: "Paste below the selection" },
  { scope: "sfc", command: "undo", keys: "Ctrl+Z", label: "Undo" },
  { scope: "sfc", command: "redo", keys: "Ctrl+Y / Ctrl+Shift+Z", label: "Redo" },
  { scope: "sfc", command: "zoom-in", keys: "=", label: "Zoom in" },
  { scope: "sfc", command: "zoom-out", keys: "-", label: "Zoom out" },
  { scope: "sfc", command: "zoom-reset", keys: "0", label: "Zoom to 100 %" },
  { scope: "sfc", command: "zoom-fit", keys: FIT_KEYS, label: "Zoom to fit the whole chart in the view" },
  {
    scope: "sfc",
    command: "move-selection",
    keys: "ArrowLeft / ArrowRight / ArrowUp / ArrowDown",
    label: "Move the selection along the chart and across branches",
  },
  { scope: "sfc", command: "clear-selection", keys: "Escape", label: "Clear the selection" },
  {
    scope: "sfc",
    command: "toggle-breakpoint",
    keys: "F9",
    label: "Toggle a breakpoint on the selected step or transition",
  },
] as const;

const ST = [
  { scope: "st", command: "toggle-breakpoint", keys: "F9", label: "Toggle a breakpoint on the cursor's line" },
  { scope: "st", command: "complete", keys: "Ctrl+Space", label: "Complete: variables, functions, FB pins" },
  { scope: "st", command: "undo", keys: "Ctrl+Z", label: "Undo" },
  { scope: "st", command: "redo", keys: "Ctrl+Y / Ctrl+Shift+Z", label: "Redo" },
  { scope: "st", command: "fold", keys: "Ctrl+Shift+[", label: "Fold the block at the cursor" },
  { scope: "st", command: "unfold", keys: "Ctrl+Shift+]", label: "Unfold the block at the cursor" },
  { scope: "st", command: "indent", keys: "Tab", label: "Indent the selected lines" },
  { scope: "st", command: "unindent", keys: "Shift+Tab", label: "Unindent the selected lines" },
  {
    scope: "st",
    command: "find-references",
    keys: "Shift+F12",
    label: "Find all references of the variable at the cursor",
  },
  {
    scope: "st",
    command: "declare",
    keys: "Shift+F2",
    label: "Declare the undeclared variable at the cursor (the declare dialog)",
  },
] as const;

export const KEYMAP = [...APP, ...LD, ...FBD, ...SFC, ...ST] as const satisfies readonly KeyBinding[];

/** The commands of one scope, as the table names them: a scope's handler table must cover them all. */
export type CommandOf<S extends KeyScope> = Extract<(typeof KEYMAP)[number], { scope: S }>["command"];

/** Mouse gestures, listed in the help with the keys (they are not keys, so nothing dispatches them here). */
export const GESTURES: readonly { scope: KeyScope; gesture: string; label: string }[] = [
  { scope: "app", gesture: "Double-click a value", label: "Prepare a value (a BOOL toggles; others ask)" },
  { scope: "ld", gesture: "Shift+click", label: "Select a run of elements" },
  { scope: "ld", gesture: "Alt+click", label: "Toggle a breakpoint on an element" },
  { scope: "ld", gesture: "Click a network number", label: "Toggle a breakpoint on the network" },
  { scope: "fbd", gesture: "Alt+click", label: "Toggle a breakpoint on a node" },
  { scope: "fbd", gesture: "Click a network number", label: "Toggle a breakpoint on the network" },
  { scope: "sfc", gesture: "Alt+click", label: "Toggle a breakpoint on a step or transition" },
  { scope: "sfc", gesture: "Double-click", label: "Edit a step's name, a condition, a jump's target; open an action" },
  { scope: "st", gesture: "Click the breakpoint gutter", label: "Toggle a breakpoint on the line" },
  { scope: "st", gesture: "Arrows, Home, End, Shift+…", label: "Move and select as in any text editor" },
];

export const SCOPE_TITLES: Record<KeyScope, string> = {
  app: "Everywhere",
  ld: "LD editor",
  fbd: "FBD editor",
  sfc: "SFC editor",
  st: "ST editor",
};

export type KeyPress = Pick<KeyboardEvent, "key" | "ctrlKey" | "metaKey" | "shiftKey" | "altKey">;

/** The alternatives of `keys` ("Delete / Backspace", "Ctrl++") as the key and its exact modifiers. */
function parse(keys: string): { key: string; ctrl: boolean; alt: boolean; shift: boolean }[] {
  return keys.split(" / ").map((alternative) => {
    const parts = alternative.endsWith("++") ? [...alternative.slice(0, -2).split("+"), "+"] : alternative.split("+");
    const last = parts[parts.length - 1]!;
    const mods = new Set(parts.slice(0, -1));
    return {
      key: last === "Space" ? " " : last,
      ctrl: mods.has("Ctrl"),
      alt: mods.has("Alt"),
      shift: mods.has("Shift"),
    };
  });
}

/**
 * Whether a key press is one of `keys`' alternatives with exactly its modifiers (Cmd counts as Ctrl;
 * "+" is typed with Shift on most layouts, so Shift does not count for it).
 */
export function matches(keys: string, event: KeyPress): boolean {
  return parse(keys).some(
    (k) =>
      event.key.toLowerCase() === k.key.toLowerCase() &&
      k.ctrl === (event.ctrlKey || event.metaKey) &&
      k.alt === event.altKey &&
      (k.shift === event.shiftKey || k.key === "+"),
  );
}

/** Every command of `scope` bound to this key press, in table order (one key may serve several, e.g. 1). */
export function commandsFor<S extends KeyScope>(scope: S, event: KeyPress): CommandOf<S>[] {
  return KEYMAP.filter((b) => b.scope === scope && matches(b.keys, event)).map((b) => b.command as CommandOf<S>);
}

/** The keys of a command as the help and tooltips show them ("" when it has none). */
export function keysOf<S extends KeyScope>(scope: S, command: CommandOf<S> | string): string {
  return KEYMAP.find((b) => b.scope === scope && b.command === command)?.keys ?? "";
}

/**
 * Function keys the app binds: with any modifiers their browser meaning never applies (F5 and Ctrl+F5
 * would reload the page and lose the session, F7 turns on caret browsing, F11 goes full screen).
 */
export const RESERVED_KEYS: ReadonlySet<string> = new Set(
  KEYMAP.flatMap((b) => parse(b.keys).map((k) => k.key)).filter((key) => /^F\d+$/.test(key)),
);

/** The CodeMirror spelling of `keys` ("Ctrl+Shift+Z" -> "Mod-Shift-z"; letters in lower case), one per alternative. */
export function codeMirrorKeys(keys: string): string[] {
  return parse(keys).map((k) => {
    const key = k.key === " " ? "Space" : k.key.length === 1 ? k.key.toLowerCase() : k.key;
    return `${k.ctrl ? "Mod-" : ""}${k.alt ? "Alt-" : ""}${k.shift ? "Shift-" : ""}${key}`;
  });
}
