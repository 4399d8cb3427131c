// @vitest-environment node
// The layer rule of eslint.config.js bites (issue 19): ESLint lints deliberate wrong-way imports as if
// they sat in a layer's folder and must report import-x/no-restricted-paths; the right-way imports
// beside them must pass. The imported files are real ones, so the resolver finds them as in the app.
import { ESLint } from "eslint";
import { describe, expect, it } from "vitest";
import { cyclicImports, folderGraph, type FolderGraph } from "./test/folderGraph";

const eslint = new ESLint({ cwd: new URL("..", import.meta.url).pathname });

/** The layer-rule messages ESLint gives for `code` placed at `file` (relative to frontend/). */
async function layerErrors(file: string, code: string): Promise<string[]> {
  const [result] = await eslint.lintText(`${code}\nexport const used = imported;\n`, { filePath: file });
  return result!.messages.filter((m) => m.ruleId === "import-x/no-restricted-paths").map((m) => m.message);
}

const WRONG_WAY: [string, string, string, string][] = [
  ["the store imports a feature", "src/store/bad.ts", 'import { imported } from "../online/store";', "store"],
  ["the store imports the shell", "src/store/bad.ts", 'import imported from "../app/App";', "store"],
  ["a feature imports the shell", "src/ld/editor/bad.ts", 'import imported from "../../app/App";', "feature"],
  [
    "a feature at the top of its folder imports the shell",
    "src/trace/bad.ts",
    'import { imported } from "../app/session";',
    "feature",
  ],
  ["a bottom module imports the store", "src/ui/bad.ts", 'import { imported } from "../store/project";', "bottom"],
  ["a bottom module imports a feature", "src/iec/bad.ts", 'import { imported } from "../ld/model";', "bottom"],
  ["a bottom module imports the shell", "src/api/bad.ts", 'import imported from "../app/App";', "bottom"],
];

const RIGHT_WAY: [string, string, string][] = [
  ["the shell imports a feature", "src/app/ok.ts", 'import { imported } from "../online/store";'],
  ["a feature imports another feature", "src/fbd/ok.ts", 'import { imported } from "../ld/model";'],
  ["a feature imports the store", "src/ld/editor/ok.ts", 'import { imported } from "../../store/project";'],
  ["the store imports a bottom module", "src/store/ok.ts", 'import { imported } from "../api/client";'],
  ["a test imports across layers", "src/iec/ok.test.ts", 'import { imported } from "../ld/model";'],
];

describe("frontend layers (eslint.config.js)", () => {
  it.each(WRONG_WAY)(
    "fails when %s",
    async (_what, file, code, layer) => {
      const errors = await layerErrors(file, code);
      expect(errors).toHaveLength(1);
      expect(errors[0]).toContain(
        {
          store: "The store imports no feature",
          feature: "A feature never imports the app shell",
          bottom: "A bottom module imports no",
        }[layer],
      );
    },
    60_000,
  );

  it.each(RIGHT_WAY)(
    "passes when %s",
    async (_what, file, code) => {
      expect(await layerErrors(file, code)).toEqual([]);
    },
    60_000,
  );
});

// No import cycles among the folders (issue 19): the layer rule above keeps the store, the bottom
// modules and the shell apart; among the features, a folder that imports another is never imported back,
// directly or through other folders. `make test` fails on a new cycle and names its imports.
describe("no import cycles among the frontend's folders (src/test/folderGraph.ts)", () => {
  const graph = folderGraph(new URL(".", import.meta.url).pathname);
  const withImport = (from: string, to: string): FolderGraph =>
    new Map([...graph, [from, new Set([...(graph.get(from) ?? []), to])]]);

  it("finds the app's folder imports", () => {
    // Real imports of today's app, one feature on another and on the bottom layers.
    expect([...(graph.get("fbd") ?? [])]).toEqual(expect.arrayContaining(["ld", "online", "ui", "store"]));
    expect([...(graph.get("ld") ?? [])]).toEqual(expect.arrayContaining(["online", "ui", "keys"]));
  });

  it("has none", () => {
    expect(cyclicImports(graph)).toEqual([]);
  });

  it("fails on a cycle: online importing ld again (ld imports online)", () => {
    expect(cyclicImports(withImport("online", "ld"))).toEqual(expect.arrayContaining(["ld -> online", "online -> ld"]));
  });

  it("names every import on a longer cycle, and only those", () => {
    const chain: FolderGraph = new Map([
      ["a", new Set(["b"])],
      ["b", new Set(["c"])],
      ["c", new Set(["a", "d"])],
      ["d", new Set<string>()],
    ]);
    expect(cyclicImports(chain)).toEqual(["a -> b", "b -> c", "c -> a"]);
    chain.get("c")!.delete("a");
    expect(cyclicImports(chain)).toEqual([]);
  });
});
