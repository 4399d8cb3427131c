// The name field and the confirm / Cancel buttons every dialog of the project tree shows (rename a POU, member,
// task or test file; duplicate; delete): one component each, so they look, focus and read alike everywhere.

/** A name being typed in a dialog: focused when the dialog opens, no spelling marks (IEC names are not words). */
export function NameField({
  label,
  value,
  onChange,
}: {
  /** The accessible name (the browser tests and screen readers find the field by it). */
  label: string;
  value: string;
  onChange(value: string): void;
}) {
  return (
    <input aria-label={label} autoFocus value={value} onChange={(e) => onChange(e.target.value)} spellCheck={false} />
  );
}

/** A dialog's confirming button and Cancel: with `onConfirm` a button of its own, focused so Enter confirms (a
 * dialog without a field); without, its form's submit button (the name field has the focus). */
export function ConfirmButtons({
  confirm,
  onConfirm,
  onClose,
  disabled = false,
}: {
  confirm: string;
  onConfirm?: () => void;
  onClose(): void;
  disabled?: boolean;
}) {
  return (
    <div className="dialog-buttons">
      {onConfirm ? (
        <button type="button" onClick={onConfirm} disabled={disabled} autoFocus>
          {confirm}
        </button>
      ) : (
        <button type="submit" disabled={disabled}>
          {confirm}
        </button>
      )}
      <button type="button" onClick={onClose}>
        Cancel
      </button>
    </div>
  );
}
