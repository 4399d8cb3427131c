// The call stack of the halted scan, or of a step through a past scan (issue 25 item 6; CODESYS's Call Stack view):
// each POU call it stands in, outermost first, where it stands (the call it makes, the halt point in the last);
// choosing one opens its POU there (a method in its FB's Methods tab), where a FUNCTION's or METHOD's own variables
// show inline.
import type { CallFrame } from "../generated/monitor";
import type { At } from "./protocol";
import type { HaltPlace } from "./useRevealHalt";

export interface CallStackProps {
  /** The calls, outermost first: the halted live scan's, or those of a step through a past scan. */
  stack: readonly CallFrame[];
  /** Where a call stands in words ("MAIN, line 3"), as the halt is described. */
  describe(at: At): string;
  /** Shows a place in its editor (debug/reveal.ts's revealPlace: a method's call opens its FB's Methods tab). */
  reveal(target: HaltPlace): void;
}

export function CallStack({ stack, describe, reveal }: CallStackProps) {
  if (stack.length === 0) return null;
  return (
    <nav className="call-stack" aria-label="Call stack">
      <span>Call stack:</span>
      <ol>
        {stack.map((frame, i) => (
          <li key={i} aria-current={i === stack.length - 1 ? "step" : undefined}>
            <button
              type="button"
              className="link"
              title={`Open ${frame.at.pou} where this call stands`}
              onClick={() =>
                reveal({
                  pou: frame.at.pou,
                  network: frame.at.network,
                  element: frame.at.element,
                  line: frame.at.line,
                  body: frame.at.body ?? null,
                })
              }
            >
              {describe(frame.at)}
            </button>
          </li>
        ))}
      </ol>
    </nav>
  );
}
