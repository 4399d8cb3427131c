// The dialogs of the project tree's menus (and of the Global variables and Types editors): rename everywhere
// with a preview, delete listing what refers to the item, duplicate, change the kind of an empty POU, convert
// FBD <-> CFC. Each applies one undoable step of the working copy (workspace store's applyOperation); nothing is
// saved until the user saves. Loaded when a menu entry is first chosen (lazyDialogs.tsx), not with the app.
import { useEffect, useState, type FormEvent } from "react";
import type { Pou, Reference } from "../generated/api";
import { cfcToFbd, fbdToCfc } from "../fbd/convert";
import { networksOf, nodesOf, type FbdBody, type FbdNetwork } from "../fbd/model";
import { fetchChartOrder, fetchOrder } from "../fbd/useOrder";
import { onlineStore } from "../online/store";
import { debugStore } from "../debug/store";
import { renamedPou } from "../breakpointPlaces/follow";
import { traceStore } from "../trace/store";
import {
  changedParts,
  describeReference,
  renamedPath,
  renameEverywhere,
  renameMemberEverywhere,
  renamedPous,
  type Use,
} from "./refactor";
import { emptyDeclarations, workspaceStore } from "../store/project";
import { FormError } from "../ui/FormError";
import { ConfirmButtons, NameField } from "../ui/NameField";
import { Dialog, DialogFooter } from "../ui/TreeActions";
import { KIND_HELP, KindPicker } from "./kinds";
import { sessionUsesOf, type DeleteOperations, type ItemOperations } from "./operations";

const message = (err: unknown) => (err instanceof Error ? err.message : String(err));

function ReferenceList({ references, empty }: { references: readonly Use[]; empty: string }) {
  if (!references.length) return <p className="tree-empty">{empty}</p>;
  return (
    <ul className="reference-list" aria-label="References">
      {references.map((r, i) => (
        <li key={i}>
          <span className="reference-where">{describeReference(r)}</span> <code>{r.text}</code>
        </li>
      ))}
    </ul>
  );
}

/**
 * Rename a project-level name (a POU, a user type, a global variable) everywhere, or a method or property of
 * function block `member` with its calls: the new name, a preview of every change the server's refactoring
 * makes, then one undoable step. A POU's open tab follows it; the session's watch and trace paths follow a
 * project-level name.
 */
export function RenameDialog({
  current,
  isPou,
  member,
  initial,
  onClose,
  onRenamed,
  tabOf,
}: {
  current: string;
  isPou: boolean;
  /** The tab (and unsaved-changes) key of a renamed item that has one and is no POU (a global variable list). */
  tabOf?(name: string): string;
  /** The function block whose method or property `current` is. */
  member?: string;
  /** The new name to start from (else `current`). */
  initial?: string;
  onClose(): void;
  onRenamed?(name: string): void;
}) {
  const [name, setName] = useState(initial ?? current);
  const [preview, setPreview] = useState<{ name: string; changes: Reference[]; session: Use[] } | null>(null);
  const [error, setError] = useState<string | null>(null);
  const [result, setResult] = useState<Awaited<ReturnType<typeof renameEverywhere>> | null>(null);
  const submit = async (e: FormEvent) => {
    e.preventDefault();
    const project = workspaceStore.getState().project;
    if (!project) return;
    if (preview && result && preview.name === name.trim()) {
      const renamed: Record<string, string> = isPou
        ? { [current]: preview.name }
        : tabOf
          ? { [tabOf(current)]: tabOf(preview.name) }
          : {};
      const changedPous = new Set(preview.changes.map((c) => c.pou).filter((p): p is string => !!p));
      // Breakpoints on the POU (or on the method and its overrides) take the new name before the project changes
      // (else they would be dropped as gone).
      const pous = renamedPous(current, preview.name, isPou, preview.changes);
      if (pous.length)
        debugStore.getState().follow(
          (bp) => pous.reduce((moved, [from, to]) => renamedPou(moved, from, to), bp),
          () => "",
        );
      workspaceStore
        .getState()
        .applyOperation(
          `rename ${current} to ${preview.name}`,
          result.project,
          [
            ...(isPou ? [preview.name] : []),
            ...[...changedPous].map((p) => renamed[p] ?? p),
            ...changedParts(preview.changes),
          ],
          { renamed },
        );
      if (!member) {
        // The session's paths follow (the watch list, the trace): the preview listed them.
        const renamedIn = (paths: readonly string[]) => paths.map((p) => renamedPath(p, current, preview.name));
        const online = onlineStore.getState();
        online.restoreWatch(renamedIn(online.watch), renamedIn(online.watchExpanded));
        const trace = traceStore.getState();
        const trigger = { ...trace.trigger, path: renamedPath(trace.trigger.path, current, preview.name) };
        traceStore.setState({ paths: renamedIn(trace.paths), trigger });
      }
      onRenamed?.(preview.name);
      onClose();
      return;
    }
    try {
      const answer = member
        ? await renameMemberEverywhere(project, member, current, name.trim())
        : await renameEverywhere(project, current, name.trim());
      setResult(answer);
      setPreview({ name: name.trim(), changes: answer.changes, session: member ? [] : sessionUsesOf(current) });
      setError(null);
    } catch (err) {
      setError(message(err));
      setPreview(null);
    }
  };
  const ready = preview !== null && preview.name === name.trim();
  const places = preview ? preview.changes.length + preview.session.length : 0;
  return (
    <Dialog title={`Rename ${member ? `${member}.` : ""}${current}`} onClose={onClose}>
      <form onSubmit={(e) => void submit(e)}>
        <NameField label="New name" value={name} onChange={setName} />
        {ready ? (
          <>
            <p>
              {places} place{places === 1 ? "" : "s"} will change:
            </p>
            <ReferenceList references={[...preview.changes, ...preview.session]} empty="Nothing else uses this name." />
          </>
        ) : null}
        <DialogFooter error={error} submit={ready ? "Rename" : "Preview"} onClose={onClose} />
      </form>
    </Dialog>
  );
}

/** Delete: what still refers to the item (those places will no longer compile), then one undoable step. */
export function DeleteDialog({ name, item, onClose }: { name: string; item: DeleteOperations; onClose(): void }) {
  const [references, setReferences] = useState<Use[] | null>(null);
  const [error, setError] = useState<string | null>(null);
  const [consequence] = useState(() => {
    const project = workspaceStore.getState().project;
    return project ? (item.consequence?.(project) ?? null) : null;
  });
  useEffect(() => {
    const project = workspaceStore.getState().project;
    if (project) item.references(project).then(setReferences, (err) => setError(message(err)));
  }, [item]);
  const remove = () => {
    const ws = workspaceStore.getState();
    if (!ws.project) return;
    ws.applyOperation(`delete ${name}`, item.remove(ws.project), item.changed, { closed: item.closed ?? [] });
    onClose();
  };
  return (
    <Dialog title={`Delete ${name}`} onClose={onClose}>
      {consequence ? <p>{consequence}</p> : null}
      {references === null && !error ? <p>Looking for uses of {name}…</p> : null}
      {references?.length ? <p>These places use {name} and will no longer compile:</p> : null}
      {references ? <ReferenceList references={references} empty={`Nothing refers to ${name}.`} /> : null}
      <FormError error={error} />
      <ConfirmButtons
        confirm={`Delete ${name}`}
        onConfirm={remove}
        onClose={onClose}
        disabled={references === null && !error}
      />
    </Dialog>
  );
}

/** Duplicate: the copy's name (a free one offered), then one undoable step. */
export function DuplicateDialog({ name, item, onClose }: { name: string; item: ItemOperations; onClose(): void }) {
  const [copy, setCopy] = useState(() => item.copyName(workspaceStore.getState().project ?? { name: "" }));
  const [error, setError] = useState<string | null>(null);
  const submit = async (e: FormEvent) => {
    e.preventDefault();
    const ws = workspaceStore.getState();
    if (!ws.project) return;
    try {
      const next = await item.copy(ws.project, copy.trim());
      if (typeof next === "string") return setError(next);
      ws.applyOperation(`duplicate ${name}`, next, item.copyChanged(copy.trim()));
      item.open?.(copy.trim());
      onClose();
    } catch (err) {
      setError(message(err));
    }
  };
  return (
    <Dialog title={`Duplicate ${name}`} onClose={onClose}>
      <form onSubmit={(e) => void submit(e)}>
        <NameField label="Name of the copy" value={copy} onChange={setCopy} />
        <DialogFooter error={error} submit="Duplicate" onClose={onClose} />
      </form>
    </Dialog>
  );
}

export function KindDialog({ pou, onClose }: { pou: Pou; onClose(): void }) {
  const [kind, setKind] = useState<Pou["kind"]>(pou.kind);
  const change = (e: FormEvent) => {
    e.preventDefault();
    const ws = workspaceStore.getState();
    if (!ws.project) return;
    const { return_type: _unused, ...rest } = pou;
    const next: Pou = {
      ...rest,
      kind,
      declarations: emptyDeclarations(kind),
      ...(kind === "function" ? { return_type: pou.return_type ?? "BOOL" } : {}),
    };
    const pous = (ws.project.pous ?? []).map((p) => (p.name === pou.name ? next : p));
    ws.applyOperation(`make ${pou.name} a ${KIND_HELP[kind].label}`, { ...ws.project, pous }, [pou.name]);
    onClose();
  };
  return (
    <Dialog title={`Kind of ${pou.name}`} onClose={onClose}>
      <form onSubmit={change}>
        <KindPicker kind={kind} onChange={setKind} />
        <DialogFooter error={null} submit="Change kind" onClose={onClose} />
      </form>
    </Dialog>
  );
}

/** A stacked network's height on the chart: below its lowest node (positions are layout hints, px). */
const heightOf = (network: FbdNetwork) => Math.max(0, ...nodesOf(network).map((n) => n.pos?.y ?? 0)) + 120;

/** FBD <-> CFC (fbd/convert.ts), with the execution orders the backend reports for the body. */
async function converted(pou: Pou) {
  const body = pou.body as FbdBody;
  if (pou.language === "fbd") {
    const pairs = await Promise.all(
      networksOf(body).map(async (n): Promise<[string, readonly string[]]> => [n.id, (await fetchOrder(n)).order]),
    );
    return fbdToCfc(body, new Map(pairs), heightOf);
  }
  const chart = networksOf(body)[0] ?? { id: "chart" };
  const [numbers, flow] = await Promise.all([fetchChartOrder(chart), fetchOrder(chart)]);
  return cfcToFbd(body, numbers.order, flow.order);
}

export function ConvertDialog({ pou, onClose }: { pou: Pou; onClose(): void }) {
  const target = pou.language === "fbd" ? "CFC" : "FBD";
  const [error, setError] = useState<string | null>(null);
  const submit = async (e: FormEvent) => {
    e.preventDefault();
    try {
      const result = await converted(pou);
      if (!result.ok) return setError(result.error);
      const ws = workspaceStore.getState();
      if (!ws.project) return;
      const next: Pou = { ...pou, language: pou.language === "fbd" ? "cfc" : "fbd", body: result.body };
      const pous = (ws.project.pous ?? []).map((p) => (p.name === pou.name ? next : p));
      ws.applyOperation(`convert ${pou.name} to ${target}`, { ...ws.project, pous }, [pou.name]);
      onClose();
    } catch (err) {
      setError(message(err));
    }
  };
  return (
    <Dialog title={`Convert ${pou.name} to ${target}`} onClose={onClose}>
      <form onSubmit={(e) => void submit(e)}>
        <p className="kind-help">
          {target === "CFC"
            ? "The networks go onto one chart, top to bottom; each element's number is the place FBD ran it in, so the chart computes the same."
            : "The chart becomes one network. This works only when its numbers are the data-flow order (FBD cannot run an element before the block feeding it)."}
        </p>
        <DialogFooter error={error} submit={`Convert to ${target}`} onClose={onClose} />
      </form>
    </Dialog>
  );
}
