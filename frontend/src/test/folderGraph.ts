// The import graph between the folders of src/ (issue 19: no import cycles among the feature folders),
// read from the sources: every relative import, export-from, side-effect and dynamic import of the app's
// files (tests excluded: they may import across layers). src/layers.test.ts checks it.
import { readdirSync, readFileSync } from "node:fs";
import { dirname, join, relative, resolve } from "node:path";

/** folder -> the folders it imports from (its own folder left out). */
export type FolderGraph = Map<string, Set<string>>;

const SPECIFIER = /(?:\bfrom|\bimport)\s*\(?\s*["'](\.{1,2}\/[^"']+)["']/g;

function sources(dir: string): string[] {
  return readdirSync(dir, { withFileTypes: true }).flatMap((entry) => {
    const path = join(dir, entry.name);
    if (entry.isDirectory()) return sources(path);
    return /\.tsx?$/.test(entry.name) && !/\.test\.tsx?$/.test(entry.name) ? [path] : [];
  });
}

/** The folder graph of the app under `src` (files at the top of src/, like main.tsx, are not a folder). */
export function folderGraph(src: string): FolderGraph {
  const graph: FolderGraph = new Map();
  const folderOf = (path: string) => {
    const parts = relative(src, path).split("/");
    return parts.length > 1 ? parts[0]! : null;
  };
  for (const file of sources(src)) {
    const from = folderOf(file);
    if (!from) continue;
    for (const [, specifier] of readFileSync(file, "utf8").matchAll(SPECIFIER)) {
      const to = folderOf(resolve(dirname(file), specifier!));
      if (!to || to === from) continue;
      if (!graph.has(from)) graph.set(from, new Set());
      graph.get(from)!.add(to);
    }
  }
  return graph;
}

function reaches(graph: FolderGraph, start: string, goal: string): boolean {
  const seen = new Set([start]);
  const queue = [start];
  while (queue.length) {
    const folder = queue.shift()!;
    if (folder === goal) return true;
    for (const next of graph.get(folder) ?? [])
      if (!seen.has(next)) {
        seen.add(next);
        queue.push(next);
      }
  }
  return false;
}

/** The imports ("a -> b") that lie on a cycle: b imports back to a, directly or through other folders. */
export function cyclicImports(graph: FolderGraph): string[] {
  return [...graph]
    .flatMap(([from, tos]) => [...tos].filter((to) => reaches(graph, to, from)).map((to) => `${from} -> ${to}`))
    .sort();
}
