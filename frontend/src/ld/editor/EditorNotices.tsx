// The notices above a diagram editor (LD and FBD alike): why it is read-only, with what to do about
// it; a dismissible message (a refused edit); the declare dialog for a variable typed but not declared.
import { lazy, Suspense, type ReactNode } from "react";
import type { VariableDeclaration } from "./declare";

const ProjectDeclareDialog = lazy(() => import("../../declarations/ProjectDeclareDialog"));

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
      {offer ? (
        <Suspense fallback={null}>
          <ProjectDeclareDialog key={offer.name} offer={offer} onDeclare={onDeclare} onCancel={onDismissOffer} />
        </Suspense>
      ) : null}
    </>
  );
}
