// The online commands on a variable, shared by the LD and FBD diagrams and the ST editor: prepare
// (CODESYS's double-click: a BOOL toggles its prepared value, other types ask for one), write,
// force and release go to the online store as simulation paths, and one list of context menu items
// (the editors render it with the LD context menu and ask for values with ValuePrompt).
import type { MenuItem } from "../ui/MenuList";
import { pathKey } from "./monitor";
import { parseValue } from "./values";
import type { Value } from "./protocol";

/** What a diagram or the ST editor can ask of a running simulation, by operand text (the caller maps it to a path). */
export interface LdOnlineActions {
  /**
   * Prepares a value (double-click, CODESYS): `text` when given, else a BOOL's prepared value toggles;
   * false when the variable is not a BOOL and a value must be asked for. `type`: what the diagram
   * knows of it (a contact's variable is a BOOL), for before its first value arrives.
   */
  prepare(operand: string, text?: string, type?: string): boolean;
  write(operand: string, text: string): void;
  force(operand: string, value: boolean | string): void;
  unforce(operand: string): void;
  watch(operand: string): void;
}

const isBool = (value: Value | undefined, type: string | undefined) =>
  typeof value === "boolean" || type?.toUpperCase() === "BOOL";
import { onlineStore } from "./store";

/**
 * Commands by operand text; `pathOf` names its simulation path (null: nothing to do), `declared` its
 * declared type when known (so a BOOL toggles its prepared value before its first value arrives).
 */
export function operandCommands(
  pathOf: (operand: string) => string | null,
  declared: (operand: string) => string | undefined = () => undefined,
): LdOnlineActions {
  const store = () => onlineStore.getState();
  const on = (operand: string, run: (path: string) => void) => {
    const p = pathOf(operand);
    if (p) run(p);
  };
  return {
    prepare(operand, text, type) {
      const p = pathOf(operand);
      if (!p) return true; // nothing to prepare (a literal): done
      const key = pathKey(p);
      const { monitor, prepared } = store();
      if (text !== undefined) store().prepare(p, parseValue(text));
      else if (isBool(monitor.values[key], monitor.types[key]?.name ?? type ?? declared(operand)))
        store().prepare(p, !(prepared[key] ?? monitor.values[key]));
      else return false;
      return true;
    },
    write: (operand, text) => on(operand, (p) => store().write(p, parseValue(text))),
    force: (operand, value) =>
      on(operand, (p) => store().force(p, typeof value === "boolean" ? value : parseValue(value))),
    unforce: (operand) => on(operand, (p) => store().unforce(p)),
    watch: (operand) => on(operand, (p) => store().addWatch(p)),
  };
}

/**
 * The context menu items for `operand`; `prompt` asks for the value to write or force. `bool` false
 * (the type is known and not BOOL) leaves out Force TRUE/FALSE.
 */
export function onlineOperandItems(
  operand: string,
  commands: LdOnlineActions,
  prompt: (action: "write" | "force") => void,
  bool = true,
): MenuItem[] {
  return [
    { id: "online-write", label: `Write value of ${operand}…`, run: () => prompt("write") },
    ...(bool
      ? [
          { id: "online-force-true", label: "Force TRUE", run: () => commands.force(operand, true) },
          { id: "online-force-false", label: "Force FALSE", run: () => commands.force(operand, false) },
        ]
      : []),
    { id: "online-force-value", label: "Force value…", run: () => prompt("force") },
    { id: "online-release", label: "Release force", run: () => commands.unforce(operand) },
    { id: "online-watch", label: "Add to watch list", run: () => commands.watch(operand) },
  ];
}
