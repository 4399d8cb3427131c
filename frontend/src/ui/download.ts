// Saves text as a file through a temporary object URL (no server round trip for the download),
// and reads the diagnostics a refused export or import carries.
import type { Diagnostic, ErrorDetail } from "../generated/api";

/** Offers `text` as a download named `fileName`. */
export function downloadText(fileName: string, text: string, type = "text/plain;charset=utf-8"): void {
  const url = URL.createObjectURL(new Blob([text], { type }));
  const a = document.createElement("a");
  a.href = url;
  a.download = fileName;
  a.click();
  URL.revokeObjectURL(url);
}

/** The diagnostics an ApiError's detail (an ErrorDetail from a 422) carries, or none. */
export function diagnosticsOf(detail: unknown): Diagnostic[] {
  const list = detail && typeof detail === "object" ? (detail as ErrorDetail).diagnostics : undefined;
  return Array.isArray(list) ? list : [];
}
