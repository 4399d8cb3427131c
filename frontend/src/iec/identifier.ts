// An IEC 61131-3 identifier (letters, digits and _, not starting with a digit), and what to say when a name is none.

const IDENTIFIER = /^[A-Za-z_][A-Za-z0-9_]*$/;

/** Why `name` (trimmed) is no IEC identifier, in the user's words; null when it is one. */
export function identifierProblem(name: string): string | null {
  const wanted = name.trim();
  return IDENTIFIER.test(wanted)
    ? null
    : `${wanted || "An empty name"} is not an IEC identifier (letters, digits and _, not starting with a digit).`;
}
