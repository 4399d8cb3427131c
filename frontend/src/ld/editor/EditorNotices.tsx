// The notices above a diagram editor (LD and FBD alike): why it is read-only, with what to do about
// it; a dismissible message (a refused edit); the offer to declare a variable typed but not declared.
import { useState, type ReactNode } from "react";
import type { VariableDeclaration } from "./declare";

export interface EditorNoticesProps {
  readOnly: string | null;
  readOnlyActions?: ReactNode;
  message: string | null;
  onDismissMessage(): void;
  offer: VariableDeclaration | null;
  onDeclare(declaration: VariableDeclaration): void;
  onDismissOffer(): void;
}

export function EditorNotices({
  readOnly,
  readOnlyActions,
  message,
  onDismissMessage,
  offer,
  onDeclare,
  onDismissOffer,
}: EditorNoticesProps) {
  return (
    <>
      {readOnly ? (
        <div className="ld-banner" role="status">
          {readOnly}
          {readOnlyActions}
        </div>
      ) : null}
      {message ? (
        <div className="ld-message" role="alert">
          {message}
          <button type="button" aria-label="Dismiss" onClick={onDismissMessage}>
            ×
          </button>
        </div>
      ) : null}
      {offer ? <DeclareOffer key={offer.name} offer={offer} onDeclare={onDeclare} onDismiss={onDismissOffer} /> : null}
    </>
  );
}

export function DeclareOffer({
  offer,
  onDeclare,
  onDismiss,
}: {
  offer: VariableDeclaration;
  onDeclare(d: VariableDeclaration): void;
  onDismiss(): void;
}) {
  const [type, setType] = useState(offer.type);
  return (
    <div className="ld-declare" role="status">
      <span>
        <code>{offer.name}</code> is not declared.
      </span>
      <label>
        Type{" "}
        <input
          aria-label="Type of the new variable"
          value={type}
          onChange={(e) => setType(e.target.value)}
          spellCheck={false}
        />
      </label>
      <button type="button" onClick={() => onDeclare({ name: offer.name, type: type.trim() || offer.type })}>
        Declare {offer.name}
      </button>
      <button type="button" onClick={onDismiss}>
        Not now
      </button>
    </div>
  );
}
