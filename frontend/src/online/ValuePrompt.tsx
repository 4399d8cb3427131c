// A small dialog asking for a value to write or force (online mode); the text goes to the server
// as typed (TRUE, 42, T#5s), which checks it against the variable's type.
import { useState } from "react";
import type { LdOnlineActions } from "./operandCommands";

export interface ValuePromptProps {
  title: string;
  onSubmit(text: string): void;
  onCancel(): void;
}

export function ValuePrompt({ title, onSubmit, onCancel }: ValuePromptProps) {
  const [text, setText] = useState("");
  return (
    <div className="ld-dialog-backdrop">
      <form
        className="ld-dialog value-prompt"
        role="dialog"
        aria-label={title}
        onSubmit={(e) => {
          e.preventDefault();
          if (text.trim()) onSubmit(text.trim());
        }}
        onKeyDown={(e) => {
          e.stopPropagation();
          if (e.key === "Escape") onCancel();
        }}
      >
        <h2>{title}</h2>
        <label>
          Value{" "}
          <input
            aria-label="Value"
            autoFocus
            value={text}
            onChange={(e) => setText(e.target.value)}
            spellCheck={false}
            placeholder="TRUE, 42, T#5s"
          />
        </label>
        <div className="dialog-buttons">
          <button type="submit" disabled={!text.trim()}>
            OK
          </button>
          <button type="button" onClick={onCancel}>
            Cancel
          </button>
        </div>
      </form>
    </div>
  );
}

/** A pending "write value…" / "force value…" request (context menus) or a value to prepare (double-click). */
export interface ValueRequest {
  operand: string;
  action: "write" | "force" | "prepare";
}

const TITLES: Record<ValueRequest["action"], string> = {
  write: "Write",
  force: "Force",
  prepare: "Prepare a value for",
};

/** The prompt for `request`, sending the value through `commands`; `onDone` runs after OK or Cancel. */
export function OperandValuePrompt({
  request,
  commands,
  onDone,
}: {
  request: ValueRequest;
  commands: Pick<LdOnlineActions, "write" | "force" | "prepare">;
  onDone(): void;
}) {
  return (
    <ValuePrompt
      title={`${TITLES[request.action]} ${request.operand}`}
      onSubmit={(text) => {
        onDone();
        if (request.action === "write") commands.write(request.operand, text);
        else if (request.action === "force") commands.force(request.operand, text);
        else commands.prepare(request.operand, text);
      }}
      onCancel={onDone}
    />
  );
}
