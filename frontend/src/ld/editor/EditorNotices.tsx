// The notices above a diagram editor (LD and FBD alike): why it is read-only, with what to do about
// it; a dismissible message (a refused edit); the declare dialog for a variable typed but not declared.
import type { ReactNode } from "react";
import { DeclareDialog } from "../../declarations/DeclareDialog";
import type { VariableDeclaration } from "./declare";

export interface EditorNoticesProps {
  readOnly: string | null;
  readOnlyActions?: ReactNode;
  message: string | null;
  onDismissMessage(): void;
  offer: VariableDeclaration | null;
  /** The types the declare dialog completes from (the IEC vocabulary's and the project's). */
  declarableTypes?: readonly string[];
  onDeclare(declaration: VariableDeclaration): void;
  onDismissOffer(): void;
}

export function EditorNotices({
  readOnly,
  readOnlyActions,
  message,
  onDismissMessage,
  offer,
  declarableTypes = [],
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
      {offer ? (
        <DeclareDialog
          key={offer.name}
          offer={offer}
          types={declarableTypes}
          onDeclare={onDeclare}
          onCancel={onDismissOffer}
        />
      ) : null}
    </>
  );
}
