// The project's own parts besides POUs and test files: the global variables, the types, the tasks, the
// vendor libraries it uses and the exercise statement.
// Each opens in a tab keyed `part:<id>`: a POU name is an IEC identifier and never holds a ':', so a POU
// called Types or Tasks has a tab of its own (issue 22). The tree, the tabs and the unsaved-changes list show
// the part's label. A diagnostic of one (file "globals" or "types", or a JSON path into the tasks) reveals
// that tab.
import type { Diagnostic } from "../generated/api";
import { gvlNameOf, isGvlTab } from "./gvls";

export const PART_LABELS = {
  "part:globals": "Global variables",
  "part:types": "Types",
  "part:tasks": "Tasks",
  "part:libraries": "Library manager",
} as const;
export type ProjectPart = keyof typeof PART_LABELS;
export const PROJECT_PARTS = Object.keys(PART_LABELS) as ProjectPart[];

/** The exercise statement's tab and unsaved-changes key (a lab bench project's; hmi/shell.tsx shows it). */
export const EXERCISE_TAB = "part:exercise";

// Own keys only: `in` would also find "constructor" or "toString", which are POU names too.
export const isProjectPart = (tab: string): tab is ProjectPart => Object.hasOwn(PART_LABELS, tab);

/** What the user reads for a tab or unsaved-changes key: a part's label, else the key (a POU's name, a test
 * file's path). */
export const partLabel = (key: string): string =>
  isProjectPart(key)
    ? PART_LABELS[key]
    : key === EXERCISE_TAB
      ? "Exercise"
      : isGvlTab(key)
        ? `${gvlNameOf(key)} (GVL)`
        : key;

/** The keys of the parts before they had the `part:` prefix (their labels), as stored sessions and drafts
 * still hold them. */
const LEGACY_KEYS: Record<string, string> = {
  ...Object.fromEntries(PROJECT_PARTS.map((part) => [PART_LABELS[part], part])),
  exercise: EXERCISE_TAB,
};

/** A stored tab key as it is now: an old part key (its label) becomes the part's key. An old tab "Types" was
 * the Types editor even when a POU of that name existed (the collision this prefix ends). */
export const migratedTab = (key: string): string => (Object.hasOwn(LEGACY_KEYS, key) ? LEGACY_KEYS[key]! : key);

/** Stored unsaved-changes keys as they are now. An old "Types" may also have meant a POU of that name
 * (`isPou`), which then stays marked too: marking more as unsaved loses nothing. */
export function migratedChanged(keys: readonly string[], isPou: (name: string) => boolean): string[] {
  const out = keys.flatMap((k) => {
    const part = migratedTab(k);
    return part === k ? [k] : isPou(k) ? [part, k] : [part];
  });
  return [...new Set(out)];
}

/** The part a diagnostic is in, or null for a POU's or test file's. */
export function partOf(d: Diagnostic): ProjectPart | null {
  if (d.file === "globals") return "part:globals";
  if (d.file === "types") return "part:types";
  if (d.json_path?.startsWith("$.tasks")) return "part:tasks";
  if (d.json_path?.startsWith("$.libraries") || d.json_path?.startsWith("$.typing")) return "part:libraries";
  return null;
}

/** The index of the task a diagnostic's JSON path points into ($.tasks[2].interval -> 2), or null. */
export function taskIndexOf(d: Diagnostic): number | null {
  const m = /^\$\.tasks\[(\d+)\]/.exec(d.json_path ?? "");
  return m ? Number(m[1]) : null;
}
