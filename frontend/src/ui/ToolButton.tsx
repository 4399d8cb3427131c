// One icon button of a compact toolbar (issue 22 item 7): the icon alone, its name as the accessible
// name and tooltip, with the shortcut in the tooltip.
import type { ButtonHTMLAttributes, Ref } from "react";
import type { Icon } from "./icons";

export interface ToolButtonProps extends Omit<ButtonHTMLAttributes<HTMLButtonElement>, "children" | "title"> {
  icon: Icon;
  /** What the button does, in the user's words: the accessible name and the tooltip. */
  label: string;
  /** The shortcut, as the tooltip shows it ("Ctrl+Z"). */
  keys?: string;
  /** What the tool does in more words, after its name in the tooltip. */
  hint?: string;
  ref?: Ref<HTMLButtonElement>;
}

/** The tooltip of a tool: its name, and its shortcut when it has one. */
export const toolTitle = (label: string, keys?: string) => (keys ? `${label} (${keys})` : label);

export function ToolButton({ icon: IconOf, label, keys, hint, className, ...button }: ToolButtonProps) {
  return (
    <button
      type="button"
      className={className ? `tool-button ${className}` : "tool-button"}
      aria-label={label}
      title={hint ? `${toolTitle(label, keys)}: ${hint}` : toolTitle(label, keys)}
      {...button}
    >
      <IconOf size={16} aria-hidden="true" />
    </button>
  );
}
