// A value as the HTML views show it (FBD nodes and pins, the watch list, the Variables view; the ST
// editor's inline values use the same classes): TRUE blue, FALSE plain, other values framed,
// forced on an orange ground with a red F, a prepared value after it as <value>.
import type { ValueShown } from "./shown";

/** The classes of a value's tag (the ST editor builds its widget DOM with them too). */
export function valueTagClass(shown: Pick<ValueShown, "bool" | "forced">): string {
  const kind = shown.bool === null ? "value-tag-value" : shown.bool ? "value-tag-true" : "value-tag-false";
  return `value-tag ${kind}${shown.forced ? " value-tag-forced" : ""}`;
}

export function ValueTag({ shown, label }: { shown: ValueShown; label?: string }) {
  return (
    <>
      <span
        className={valueTagClass(shown)}
        aria-label={label}
        title={`${shown.text}${shown.forced ? " (forced)" : ""}`}
        data-value={shown.text}
      >
        {shown.text}
        {shown.forced ? (
          <span className="forced-mark" aria-label="forced">
            F
          </span>
        ) : null}
      </span>
      {shown.prepared !== null ? (
        <span className="prepared-tag" title="prepared: F7 forces, Ctrl+F7 writes">{`<${shown.prepared}>`}</span>
      ) : null}
    </>
  );
}
