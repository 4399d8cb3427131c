// The Methods tab of a function block or a program (issue 25, CODESYS's objects under an FB or a PROGRAM): its methods
// and properties listed, their access (PUBLIC/PRIVATE/PROTECTED/INTERNAL), FINAL and ABSTRACT set (an FB's only:
// nothing extends a program),
// added, renamed (with every call, previewed: the tree's rename dialog) and deleted; a method's result type, declarations and body, and a property's type and GET / SET
// texts, edited in the ST editor with the live check's diagnostics; breakpoints in a method's or accessor's body;
// online, the FB instance's variables a body names inline, live (writable as in the FB body), and a method's or
// accessor's own variables' values while the scan is halted in a call of it (read only).
import { useState, type FormEvent, type ReactNode } from "react";
import type { Accessor, Method, Pou, Property } from "../generated/api";
import { useTextDebug } from "../breakpointPlaces/useTextDebug";
import { useOnline } from "../online/store";
import type { Focus } from "../store/panels";
import { StEditor } from "../st/StEditor";
import { StOnlineBar } from "../st/StOnlineBar";
import { useStAssist } from "../st/useStAssist";
import { useStOnline, type StMember } from "../st/useStOnline";
import type { Scope } from "../st/members";
import { workspaceStore } from "../store/project";
import { FormError } from "../ui/FormError";
import { RenameDialog } from "../tree/lazyDialogs";
import {
  addMember,
  changeMember,
  deleteMember,
  memberFile,
  memberOf,
  renameMember,
  ACCESS_MEANING,
  withModifier,
  type Edited,
  type MemberKind,
} from "./members";
import type { Access } from "../tree/modifiers";

/** What ABSTRACT and FINAL mean for the function block itself, as its checkboxes' tooltips say. */
const FB_MODIFIER_MEANING = {
  abstract: "ABSTRACT: no instance of it can be declared; it may have ABSTRACT methods for derived FBs to implement",
  final: "FINAL: no function block can extend it",
};

/** What FINAL and ABSTRACT mean, as the checkboxes' tooltips say. */
const MODIFIER_MEANING = {
  final: "FINAL: a function block derived from this one cannot override it",
  abstract: "ABSTRACT: no body here; the function block is ABSTRACT and a derived one implements it",
};

/** `instancePicker`: the shell's choice of the FB instance the bodies show online (the FB body's too). */
export function MethodsView({
  pou,
  focus,
  instancePicker,
}: {
  pou: Pou;
  focus: Focus | null;
  instancePicker?: ReactNode;
}) {
  const [selected, setSelected] = useState<string | null>(
    focus?.member ?? pou.methods?.[0]?.name ?? pou.properties?.[0]?.name ?? null,
  );
  // A member chosen in the tree, or a diagnostic or halt in its text, selects it (as the request arrives).
  const [focusSeen, setFocusSeen] = useState(focus);
  if (focus !== focusSeen) {
    setFocusSeen(focus);
    if (focus?.member) setSelected(memberOf(pou, focus.member)?.member.name ?? focus.member);
  }
  const [name, setName] = useState("");
  const [error, setError] = useState<string | null>(null);
  /** The new name of the selected member while the rename's preview shows. */
  const [renaming, setRenaming] = useState<string | null>(null);
  const online = useOnline((s) => s.phase !== "offline");
  const found = selected ? memberOf(pou, selected) : null;
  /** A function block may be extended: it and its methods may be ABSTRACT or FINAL (a program's may not). */
  const extendable = pou.kind === "function_block";
  /** An edit of the FB as one undoable step (add, rename, delete); a refusal is shown instead. */
  const operate = (label: string, edited: Edited, select: string | null) => {
    if (!edited.ok) return setError(edited.error);
    setError(null);
    const project = workspaceStore.getState().project;
    if (!project) return;
    const next = { ...project, pous: (project.pous ?? []).map((p) => (p.name === pou.name ? edited.pou : p)) };
    workspaceStore.getState().applyOperation(label, next, [pou.name]);
    setSelected(select);
  };
  const add = (kind: MemberKind) => (e: FormEvent) => {
    e.preventDefault();
    operate(`Add ${kind} ${name.trim()}`, addMember(pou, kind, name), name.trim());
    setName("");
  };
  return (
    <div className="methods-view" style={{ display: "flex", gap: "0.75rem", height: "100%", minHeight: 0 }}>
      <div style={{ flex: "0 0 14rem", display: "flex", flexDirection: "column", gap: "0.5rem" }}>
        <div className="methods-fb" style={{ display: "flex", gap: "0.5rem" }}>
          {(extendable ? (["abstract", "final"] as const) : []).map((which) => (
            <label key={which} title={FB_MODIFIER_MEANING[which]}>
              <input
                type="checkbox"
                aria-label={`${which.toUpperCase()} ${pou.name}`}
                checked={Boolean(pou[which])}
                disabled={online}
                onChange={(e) =>
                  operate(
                    `make ${pou.name} ${e.target.checked ? "" : "not "}${which.toUpperCase()}`,
                    { ok: true, pou: withModifier(pou, which, e.target.checked) },
                    selected,
                  )
                }
              />{" "}
              {which.toUpperCase()}
            </label>
          ))}
        </div>
        <ul className="tree-members" aria-label={`Methods and properties of ${pou.name}`}>
          {(pou.methods ?? []).map((m) => (
            <MemberRow key={`m-${m.name}`} kind="M" name={m.name} selected={selected} onSelect={setSelected} />
          ))}
          {(pou.properties ?? []).map((p) => (
            <MemberRow key={`p-${p.name}`} kind="P" name={p.name} selected={selected} onSelect={setSelected} />
          ))}
        </ul>
        {online ? null : (
          <form onSubmit={add("method")}>
            <input
              aria-label="New method or property name"
              value={name}
              onChange={(e) => setName(e.target.value)}
              spellCheck={false}
            />
            <button type="submit">Add method</button>
            <button type="button" onClick={add("property")}>
              Add property
            </button>
          </form>
        )}
        <FormError error={error} />
      </div>
      <div style={{ flex: "1 1 auto", minWidth: 0, display: "flex", flexDirection: "column", gap: "0.25rem" }}>
        {found ? (
          <MemberEditor
            key={found.member.name}
            focus={focus?.member?.toUpperCase() === found.member.name.toUpperCase() ? focus : null}
            pou={pou}
            kind={found.kind}
            member={found.member}
            readOnly={online ? "Online: go offline to edit." : null}
            instancePicker={instancePicker}
            onRename={(text) => {
              // refused here at once (a taken name); else the preview of every call it changes
              const edited = renameMember(pou, found.member.name, text);
              setError(edited.ok ? null : edited.error);
              if (edited.ok) setRenaming(text.trim());
            }}
            onDelete={() =>
              operate(`Delete ${found.member.name}`, { ok: true, pou: deleteMember(pou, found.member.name) }, null)
            }
          />
        ) : (
          <p className="panel-empty">{pou.name} has no methods or properties yet: name one and add it.</p>
        )}
        {found && renaming !== null ? (
          <RenameDialog
            current={found.member.name}
            isPou={false}
            member={pou.name}
            initial={renaming}
            onRenamed={setSelected}
            onClose={() => setRenaming(null)}
          />
        ) : null}
      </div>
    </div>
  );
}

function MemberRow({
  kind,
  name,
  selected,
  onSelect,
}: {
  kind: "M" | "P";
  name: string;
  selected: string | null;
  onSelect(name: string): void;
}) {
  return (
    <li>
      <button
        type="button"
        className="tree-item tree-member"
        aria-pressed={selected === name}
        onClick={() => onSelect(name)}
      >
        <span className="tree-kind">{kind}</span>
        <span className="tree-name">{name}</span>
      </button>
    </li>
  );
}

function MemberEditor({
  pou,
  kind,
  member,
  readOnly,
  onRename,
  onDelete,
  focus,
  instancePicker,
}: {
  focus: Focus | null;
  instancePicker?: ReactNode;
  pou: Pou;
  kind: MemberKind;
  member: Method | Property;
  readOnly: string | null;
  onRename(name: string): void;
  onDelete(): void;
}) {
  const [rename, setRename] = useState(member.name);
  const { diagnostics, completions, scope } = useStAssist(pou);
  /** A text or field of the member changed: the FB is unsaved (a draft is kept), as any edit of a POU's text. */
  const change = <T extends Method | Property>(update: (m: T) => T) => {
    const edited = changeMember<T>(pou, member.name, update);
    if (edited.ok)
      workspaceStore.getState().setProjectPart(pou.name, (project) => ({
        ...project,
        pous: (project.pous ?? []).map((p) => (p.name === pou.name ? edited.pou : p)),
      }));
  };
  const typeField = kind === "method" ? ((member as Method).return_type ?? "") : (member as Property).type;
  /** The line to show in `file` (a member's text), when the focus is in it: its part, and its accessor if any. */
  const focusLine = (file: string) =>
    focus?.line != null &&
    file.toUpperCase().endsWith(`${focus.accessor ? `.${focus.accessor}` : ""}/${focus.part ?? "body"}`.toUpperCase())
      ? { line: focus.line, seq: focus.seq }
      : null;
  /** A declarations text, or a body (`of`: the member whose own declarations it sees) with its values online. */
  const text = (
    label: string,
    value: string,
    file: string,
    onChange: (text: string) => void,
    of?: Omit<StMember, "file">,
  ) => {
    const editor = { text: value, onChange, file, diagnostics, completions, readOnly, label };
    return of ? (
      <MemberBody
        key={file}
        pou={pou}
        scope={scope}
        member={{ ...of, file }}
        editor={editor}
        instancePicker={instancePicker}
        focusLine={focusLine(file)}
      />
    ) : (
      <div key={file} style={{ flex: "1 1 0", minHeight: "6rem", overflow: "hidden", borderBottom: "1px solid #ccc" }}>
        <StEditor {...editor} focusLine={focusLine(file)} />
      </div>
    );
  };
  return (
    <>
      <div className="methods-header" style={{ display: "flex", gap: "0.5rem", alignItems: "center" }}>
        <strong>
          {kind === "method" ? "METHOD" : "PROPERTY"} {pou.name}.{member.name}
        </strong>
        <label>
          {kind === "method" ? "Result type" : "Type"}{" "}
          <input
            aria-label={`${kind === "method" ? "Result type" : "Type"} of ${member.name}`}
            value={typeField}
            disabled={readOnly !== null}
            spellCheck={false}
            onChange={(e) =>
              kind === "method"
                ? change<Method>((m) => ({ ...m, return_type: e.target.value.trim() ? e.target.value : null }))
                : change<Property>((p) => ({ ...p, type: e.target.value }))
            }
          />
        </label>
        <label title={ACCESS_MEANING[member.access ?? "PUBLIC"]}>
          Access{" "}
          <select
            aria-label={`Access of ${member.name}`}
            value={member.access ?? "PUBLIC"}
            disabled={readOnly !== null}
            onChange={(e) => change<Method | Property>((m) => ({ ...m, access: e.target.value as Access }))}
          >
            {(Object.keys(ACCESS_MEANING) as Access[]).map((access) => (
              <option key={access} value={access}>
                {access}
              </option>
            ))}
          </select>
        </label>
        {kind === "method" && pou.kind === "function_block"
          ? (["final", "abstract"] as const).map((which) => (
              <label key={which} title={MODIFIER_MEANING[which]}>
                <input
                  type="checkbox"
                  aria-label={`${which.toUpperCase()} ${member.name}`}
                  checked={Boolean((member as Method)[which])}
                  disabled={readOnly !== null}
                  onChange={(e) => change<Method>((m) => withModifier(m, which, e.target.checked))}
                />{" "}
                {which.toUpperCase()}
              </label>
            ))
          : null}
        {readOnly === null ? (
          <>
            <input
              aria-label={`New name of ${member.name}`}
              value={rename}
              onChange={(e) => setRename(e.target.value)}
              spellCheck={false}
            />
            <button type="button" onClick={() => onRename(rename)} disabled={rename.trim() === member.name}>
              Rename
            </button>
            <button type="button" onClick={onDelete}>
              Delete {member.name}
            </button>
          </>
        ) : null}
      </div>
      {kind === "method"
        ? [
            text(
              `${pou.name}.${member.name} declarations`,
              (member as Method).declarations ?? "",
              memberFile(pou.name, member.name, "declarations"),
              (t) => change<Method>((m) => ({ ...m, declarations: t })),
            ),
            text(
              `${pou.name}.${member.name} body`,
              (member as Method).body ?? "",
              memberFile(pou.name, member.name, "body"),
              (t) => change<Method>((m) => ({ ...m, body: t })),
              {
                name: member.name,
                declarations: (member as Method).declarations ?? "",
                call: `${pou.name}.${member.name}`,
              },
            ),
          ]
        : (["get", "set"] as const).flatMap((which) => {
            const accessor = (member as Property)[which];
            const update = (part: keyof Accessor) => (t: string) =>
              change<Property>((p) => ({
                ...p,
                [which]: { ...(p[which] ?? { declarations: "", body: "" }), [part]: t },
              }));
            return accessor
              ? [
                  text(
                    `${pou.name}.${member.name}.${which.toUpperCase()} declarations`,
                    accessor.declarations ?? "",
                    memberFile(pou.name, member.name, "declarations", which),
                    update("declarations"),
                  ),
                  text(
                    `${pou.name}.${member.name}.${which.toUpperCase()} body`,
                    accessor.body ?? "",
                    memberFile(pou.name, member.name, "body", which),
                    update("body"),
                    {
                      name: member.name,
                      declarations: accessor.declarations ?? "",
                      call: `${pou.name}.${member.name}.${which.toUpperCase()}`,
                    },
                  ),
                ]
              : [];
          })}
    </>
  );
}

/**
 * A method's or accessor's body: online, its FB instance's variables inline (the instance chosen as for the FB body,
 * or the halted call's), and its own while halted in it (st/useStOnline.tsx, the FB body's function).
 */
function MemberBody({
  pou,
  scope,
  member,
  editor,
  focusLine,
  instancePicker,
}: {
  pou: Pou;
  scope: Scope;
  member: StMember;
  editor: Omit<Parameters<typeof StEditor>[0], "online" | "debug" | "focusLine">;
  focusLine: { line: number; seq: number } | null;
  instancePicker?: ReactNode;
}) {
  const online = useStOnline(pou, editor.text, scope, member);
  const debug = useTextDebug(member.call);
  return (
    <div
      style={{
        flex: "1 1 0",
        minHeight: "6rem",
        display: "flex",
        flexDirection: "column",
        borderBottom: "1px solid #ccc",
      }}
    >
      <StOnlineBar online={online} instancePicker={instancePicker} />
      <div style={{ flex: "1 1 auto", minHeight: 0, overflow: "hidden" }}>
        <StEditor {...editor} debug={debug} online={online.view} focusLine={focusLine} />
      </div>
      {online.overlay}
    </div>
  );
}
