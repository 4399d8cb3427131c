// Diagram clipboard texts: JSON with a format tag, so copy and paste go through the system
// clipboard between tabs, windows and POUs, and one editor never pastes another's contents.
// Shared by the LD and FBD clipboards.

export const serializeTagged = (format: string, clip: object): string => JSON.stringify({ format, ...clip });

/** The fields of a clip tagged `format` in `text`; null for any other text or tag. */
export function parseTagged(format: string, text: string): Record<string, unknown> | null {
  let data: unknown;
  try {
    data = JSON.parse(text);
  } catch {
    return null;
  }
  if (!data || typeof data !== "object") return null;
  const d = data as Record<string, unknown>;
  return d.format === format ? d : null;
}
