// The project's vendor compatibility libraries (Tc2_Math, Tc2_Utilities), as TwinCAT's library manager adds
// them: a checkbox per library and its functions' signatures. The list and the signatures come from the
// backend's library sources through the vocabulary (src/generated/iec.ts), so they cannot disagree with
// what the checker accepts; docs/st.md "Vendor libraries" says what each function does.
import { IEC } from "../generated/iec";
import type { Project } from "../generated/api";
import { useOnline } from "../online/store";
import { useWorkspace } from "../store/project";

type LibraryName = NonNullable<Project["libraries"]>[number];
type Typing = NonNullable<Project["typing"]>;
const NONE: readonly LibraryName[] = [];

/** The ST type rules a project may use (Project.typing, docs/st.md "CODESYS typing"). */
const TYPINGS: readonly { value: Typing; label: string; note: string }[] = [
  { value: "iec", label: "IEC 61131-3", note: "operands of one type; explicit conversions (the default)" },
  {
    value: "codesys",
    label: "CODESYS V3",
    note: "arithmetic on BYTE/WORD/DWORD, SHL/SHR on integers, implicit conversions, 32-bit intermediate results",
  },
];

/** ``libraries`` with ``name`` added or removed, in the catalogue's order (project.json diffs stay small). */
export function toggled(libraries: readonly LibraryName[], name: LibraryName, on: boolean): LibraryName[] {
  return IEC.libraries.map((l) => l.name as LibraryName).filter((l) => (l === name ? on : libraries.includes(l)));
}

export function LibrariesView() {
  const libraries = useWorkspace((s) => s.project?.libraries ?? NONE);
  const typing = useWorkspace((s) => s.project?.typing ?? "iec");
  const setProjectPart = useWorkspace((s) => s.setProjectPart);
  const online = useOnline((s) => s.phase) !== "offline";
  const use = (name: LibraryName, on: boolean) =>
    setProjectPart("part:libraries", (project) => ({ ...project, libraries: toggled(libraries, name, on) }));
  const setTyping = (value: Typing) => setProjectPart("part:libraries", (project) => ({ ...project, typing: value }));
  return (
    <div className="pou-view part-view" role="region" aria-label="Library manager">
      <fieldset aria-label="Type rules">
        <legend>Type rules of the project&apos;s ST</legend>
        {TYPINGS.map((t) => (
          <label key={t.value}>
            <input
              type="radio"
              name="typing"
              checked={typing === t.value}
              disabled={online}
              onChange={() => setTyping(t.value)}
            />{" "}
            <strong>{t.label}</strong> - {t.note}
          </label>
        ))}
      </fieldset>
      <p className="tree-empty">
        Vendor compatibility libraries for code brought from TwinCAT. A POU of the project with the same name as a
        library function is used instead of it.
      </p>
      {IEC.libraries.map((library) => {
        const name = library.name as LibraryName;
        return (
          <section key={name} aria-label={name}>
            <label>
              <input
                type="checkbox"
                checked={libraries.includes(name)}
                disabled={online}
                onChange={(e) => use(name, e.target.checked)}
              />{" "}
              <strong>{name}</strong>
            </label>
            <ul>
              {library.functions.map((f) => (
                <li key={f.name}>
                  <code>{f.signature}</code> - {f.description}
                </li>
              ))}
            </ul>
          </section>
        );
      })}
    </div>
  );
}
