// The types a declarations table offers, shared by the POU and global variable editors.
import { useMemo } from "react";
import { userTypeNames } from "../iec/declarations";
import { DECLARABLE_TYPES } from "../iec/vocabulary";
import { useWorkspace } from "../store/project";

/** The types a declaration may use: elementary, the project's own, and the function blocks. */
export function useDeclarableTypes(): string[] {
  const library = useWorkspace((s) => s.library);
  const userTypes = useWorkspace((s) => s.project?.types ?? "");
  const pous = useWorkspace((s) => s.project?.pous);
  return useMemo(
    () => [
      ...new Set([
        ...DECLARABLE_TYPES,
        ...userTypeNames(userTypes),
        ...library.filter((e) => e.kind === "function_block").map((e) => e.name),
        ...(pous ?? []).filter((p) => p.kind === "function_block").map((p) => p.name),
      ]),
    ],
    [userTypes, library, pous],
  );
}
