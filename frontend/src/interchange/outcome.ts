// Turns a failed interchange call into an Outcome the UI lists (message plus diagnostics).
import { ApiError } from "../api/client";
import { diagnosticsOf } from "../ui/download";
import type { Outcome } from "./Problems";

export function failure(what: string, err: unknown): Outcome {
  const message = err instanceof Error ? err.message : String(err);
  return {
    message: `${what} failed: ${message}`,
    diagnostics: err instanceof ApiError ? diagnosticsOf(err.detail) : [],
    failed: true,
  };
}
