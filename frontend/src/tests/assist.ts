// What the ST editor of a test file needs: live diagnostics of the file with the working copy
// (POST /api/tests/check after the user pauses typing) and completions - the test verbs, the
// configuration's programs (their variables as members: tests may read and write any of them), the
// globals, functions and function blocks.
import { useEffect, useMemo, useState } from "react";
import type { Completion } from "@codemirror/autocomplete";
import type { Diagnostic, LibraryEntry, SymbolInfo } from "../generated/api";
import type { Project } from "../generated/api";
import { memberCompletions, stCompletions, type StCompletions } from "../st/completion";
import { tokenize } from "../st/language";
import { projectScope } from "../st/qualifiers";
import { declaredSymbols, workingLibrary } from "../st/scope";
import { CHECK_DELAY_MS } from "../store/useLiveCheck";
import { useWorkspace } from "../store/project";
import { testsApi, type TestsApi } from "./api";
import { IEC } from "../generated/iec";

/** The verbs and MOCK statements of test files (docs/testing.md), from the backend's checker. */
const verbCompletions: Completion[] = IEC.test_verbs.map(({ name, signature }) => ({
  label: name,
  type: "keyword",
  detail: signature,
  info: `test verb ${name}${signature}`,
}));

/** Each PROGRAM of the working copy as a library entry whose members are all its variables. */
function programEntries(project: Project): LibraryEntry[] {
  return (project.pous ?? [])
    .filter((p) => p.kind === "program")
    .map((p) => ({
      name: p.name,
      kind: "function_block",
      source: "user",
      inputs: [],
      outputs: (declaredSymbols(p.declarations ?? "") ?? []).map((s) => ({ name: s.name, type: s.type })),
      in_outs: [],
      extensible: false,
      return_type: null,
      comment: `PROGRAM ${p.name}`,
    }));
}

/** The variables the TESTs and the SETUP of a test file declare in their VAR blocks (comments skipped). */
export function testLocals(text: string): SymbolInfo[] {
  const code = tokenize(text)
    .filter((t) => t.style !== "comment" && t.style !== "lineComment")
    .map((t) => t.text)
    .join(" ");
  const blocks = code.match(/\bVAR(?:_[A-Z]+)?\b[\s\S]*?\bEND_VAR\b/gi) ?? [];
  return blocks.flatMap((block) => declaredSymbols(block) ?? []);
}

export function useTestCompletions(project: Project | null, text = ""): StCompletions {
  const saved = useWorkspace((s) => s.library);
  const tables = useWorkspace((s) => s.symbols);
  return useMemo(() => {
    if (!project) return { options: verbCompletions, members: () => null };
    const library = [...workingLibrary(saved, project.pous ?? []), ...programEntries(project)];
    const globals = Object.values(tables)[0]?.globals ?? [];
    const programs: SymbolInfo[] = (project.pous ?? [])
      .filter((p) => p.kind === "program")
      .map((p) => ({
        name: p.name,
        type: p.name,
        var_class: "VAR",
        initial: null,
        address: null,
        comment: "program instance",
        retain: false,
        constant: false,
      }));
    const symbols = [...testLocals(text), ...programs, ...globals];
    const types = project.types ?? "";
    // the programs are variables here (all their variables as members); the enumerations qualify their values
    const scope = { symbols, library, ...projectScope([], types) };
    return {
      options: [...verbCompletions, ...stCompletions([...scope.symbols], library, scope)],
      members: (chain: readonly string[], separator: "." | "#") => memberCompletions(chain, scope, separator),
    };
  }, [project, text, saved, tables]);
}

/** The diagnostics of one test file of the working copy, checked after the user pauses typing. */
export function useTestCheck(project: Project | null, file: string, api: TestsApi = testsApi): Diagnostic[] {
  const [diagnostics, setDiagnostics] = useState<Diagnostic[]>([]);
  useEffect(() => {
    if (!project) return;
    let current = true;
    const timer = setTimeout(() => {
      api.checkTestFile(project, file).then(
        (info) => current && setDiagnostics(info.diagnostics ?? []),
        () => current && setDiagnostics([]),
      );
    }, CHECK_DELAY_MS);
    return () => {
      current = false;
      clearTimeout(timer);
    };
  }, [project, file, api]);
  return diagnostics;
}
