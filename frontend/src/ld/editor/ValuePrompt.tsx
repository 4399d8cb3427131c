// A small dialog asking for a value to write or force (online mode); the text goes to the server
// as typed (TRUE, 42, T#5s), which checks it against the variable's type.
import { useState } from "react";
import type { LdOnlineActions } from "./LdEditor";

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

/** A pending "write value…" / "force value…" request on an operand, as the context menus make it. */
export interface ValueRequest {
  operand: string;
  action: "write" | "force";
}

/** The prompt for `request`, sending the value through `commands`; `onDone` runs after OK or Cancel. */
export function OperandValuePrompt({
  request,
  commands,
  onDone,
}: {
  request: ValueRequest;
  commands: Pick<LdOnlineActions, "write" | "force">;
  onDone(): void;
}) {
  return (
    <ValuePrompt
      title={`${request.action === "write" ? "Write" : "Force"} ${request.operand}`}
      onSubmit={(text) => {
        onDone();
        if (request.action === "write") commands.write(request.operand, text);
        else commands.force(request.operand, text);
      }}
      onCancel={onDone}
    />
  );
}
