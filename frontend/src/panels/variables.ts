// The instance tree (ON-10) as the watch list and the Variables view expand it: what a program, FB
// instance, structure or array holds, asked of the server (GET /api/projects/{name}/variables) once
// per path and saved revision, and subscribed only while it is shown.
import { useEffect, useState } from "react";
import { getVariables } from "../api/client";
import type { VariableChildren } from "../generated/api";
import { useWorkspace } from "../store/project";
import { pathKey } from "../online/monitor";
import { onlineStore } from "../online/store";

const cache = new Map<string, Promise<VariableChildren>>();

/** The members of `path` in `project` at `revision` (the saved project the simulation runs), fetched once. */
export function childrenOf(
  project: string,
  revision: string,
  path: string,
  fetch: typeof getVariables = getVariables,
): Promise<VariableChildren> {
  const key = `${project}\u0000${revision}\u0000${pathKey(path)}`;
  let found = cache.get(key);
  if (!found) {
    found = fetch(project, path);
    found.catch(() => cache.delete(key)); // a failure is asked again next time
    cache.set(key, found);
  }
  return found;
}

export type Loaded =
  { state: "loading" } | { state: "error"; message: string } | ({ state: "ready" } & VariableChildren);

/** The members of `path` while `open` (null when closed), for the open project's saved revision. */
export function useChildren(path: string, open: boolean): Loaded | null {
  const project = useWorkspace((s) => s.name);
  const revision = useWorkspace((s) => s.revision);
  const [loaded, setLoaded] = useState<{ key: string; value: Loaded } | null>(null);
  const key = `${project}:${revision}:${pathKey(path)}`;
  useEffect(() => {
    if (!open || !project || !revision) return;
    let current = true;
    childrenOf(project, revision, path).then(
      (children) => current && setLoaded({ key, value: { state: "ready", ...children } }),
      (err: unknown) =>
        current &&
        setLoaded({ key, value: { state: "error", message: err instanceof Error ? err.message : String(err) } }),
    );
    return () => {
      current = false;
    };
  }, [open, project, revision, path, key]);
  if (!open) return null;
  return loaded?.key === key ? loaded.value : { state: "loading" };
}

/** Keeps `paths` subscribed under `view` while the calling component shows them. */
export function useSubscribedPaths(view: string, paths: readonly string[]): void {
  const joined = paths.join("\n");
  useEffect(() => {
    const list = joined ? joined.split("\n") : [];
    onlineStore.getState().subscribe(view, list.length ? { paths: list, elements: [] } : null);
  }, [view, joined]);
  useEffect(() => () => onlineStore.getState().subscribe(view, null), [view]);
}

/** A row with a value of its own: an elementary variable, or a pointer (its ADR()/REF() text, ON-11). */
export function hasValue(node: { expandable: boolean; pointer?: boolean }): boolean {
  return !node.expandable || !!node.pointer;
}
