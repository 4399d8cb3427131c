// The outcome of an export or import: a message and the located diagnostics behind it.
import type { Diagnostic } from "../generated/api";
import { placeOf } from "../panels/DiagnosticsPanel";

export interface Outcome {
  message: string;
  diagnostics: Diagnostic[];
  /** An error (the request was refused) rather than a report with warnings. */
  failed: boolean;
}

export function Problems({ outcome }: { outcome: Outcome }) {
  return (
    <div
      className={outcome.failed ? "interchange-error" : "interchange-report"}
      role={outcome.failed ? "alert" : "status"}
    >
      <p>{outcome.message}</p>
      {outcome.diagnostics.length ? (
        <ul>
          {outcome.diagnostics.map((d, i) => (
            <li key={i} className={`severity-${d.severity ?? "error"}`}>
              {d.severity ?? "error"} · {placeOf(d)}: {d.message}
            </li>
          ))}
        </ul>
      ) : null}
    </div>
  );
}
