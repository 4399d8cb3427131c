// The call stack of the halted scan (issue 25 item 6; CODESYS's Call Stack view): each POU call it stands in,
// outermost first, where it stands (the call it makes, the halt point in the last); choosing one opens its POU
// there (a method in its FB's Methods tab), where a FUNCTION's or METHOD's own variables show inline.
import { useOnline } from "../online/store";
import type { At } from "../online/protocol";
import { describeHalt } from "./breakpoints";
import type { Place } from "./reveal";

export interface CallStackProps {
  networksOf(pou: string, part?: string | null): string[];
  elementText?(pou: string, id: string): string | null;
  reveal(target: Place): void;
}

export function CallStack({ networksOf, elementText, reveal }: CallStackProps) {
  const stack = useOnline((s) => s.monitor.stack);
  if (stack.length === 0) return null;
  const text = (at: At) =>
    describeHalt(at, networksOf(at.pou, at.body), at.element && !at.body ? elementText?.(at.pou, at.element) : null);
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
              {text(frame.at)}
            </button>
          </li>
        ))}
      </ol>
    </nav>
  );
}
