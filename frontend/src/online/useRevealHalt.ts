// A halt point is revealed in its editor once, when the scan reaches it: not again for each message that repeats it
// (the status after a write while halted, the frames of a step through a past scan), so a call the user opened from
// the call stack stays in view until the scan moves on.
import { useEffect, useRef } from "react";
import type { At } from "./protocol";

/** The place `reveal` is given: the halt point without its instance and column. */
export interface HaltPlace {
  pou: string;
  network?: string | null;
  element?: string | null;
  line?: number | null;
  body?: string | null;
}

export function useRevealHalt(at: At | null, reveal: (place: HaltPlace) => void): void {
  const shown = useRef<string | null>(null);
  useEffect(() => {
    const key = at ? JSON.stringify([at.pou, at.instance, at.network, at.element, at.line, at.body]) : null;
    if (key === shown.current) return;
    shown.current = key;
    if (at) reveal({ pou: at.pou, network: at.network, element: at.element, line: at.line, body: at.body ?? null });
  }, [at, reveal]);
}
