// The error line under a form or dialog (new project, new POU, rename, delete, ...): announced to
// screen readers as an alert, nothing when there is no error.

export function FormError({ error, className = "new-pou-error" }: { error: string | null; className?: string }) {
  return error ? (
    <p className={className} role="alert">
      {error}
    </p>
  ) : null;
}
