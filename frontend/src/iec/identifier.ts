// An IEC 61131-3 identifier (letters, digits and _, not starting with a digit), and what to say when a name is none.

const IDENTIFIER = /^[A-Za-z_][A-Za-z0-9_]*$/;

/** The first of `name`_copy, `name`_copy2, ... that is none of `taken` (IEC names: in any case). */
export function copyName(taken: Iterable<string>, name: string): string {
  const used = new Set([...taken].map((t) => t.toUpperCase()));
  for (let i = 1; ; i++) {
    const candidate = `${name}_copy${i === 1 ? "" : i}`;
    if (!used.has(candidate.toUpperCase())) return candidate;
  }
}

/** Why `name` (trimmed) is no IEC identifier, in the user's words; null when it is one. */
export function identifierProblem(name: string): string | null {
  const wanted = name.trim();
  return IDENTIFIER.test(wanted)
    ? null
    : `${wanted || "An empty name"} is not an IEC identifier (letters, digits and _, not starting with a digit).`;
}
