// ESLint (flat config): TypeScript's recommended rules and React's hooks rules; formatting is Prettier's job.
import { readdirSync } from "node:fs";
import js from "@eslint/js";
import { createNodeResolver, importX } from "eslint-plugin-import-x";
import reactHooks from "eslint-plugin-react-hooks";
import globals from "globals";
import tseslint from "typescript-eslint";

// The frontend's layers (docs/architecture.md, "Frontend layers"), bottom to top: the bottom modules,
// the store, the features, the app shell. A folder imports only from its own layer or the ones below:
// import-x/no-restricted-paths resolves each import to its file and fails `make lint` on a wrong-way one
// (src/layers.test.ts lints deliberate violations to prove it). Every other folder of src/ is a
// feature, so a new folder gets the feature rules without an edit here. Tests may import any layer
// (a test checks that layers agree, e.g. iec/vocabulary.test.ts); they are not part of the app.
const BOTTOM = ["api", "generated", "iec", "keys", "ui", "test"];
const STORE = "store";
const SHELL = "app";
const FEATURES = readdirSync(new URL("./src", import.meta.url), { withFileTypes: true })
  .filter((entry) => entry.isDirectory() && ![...BOTTOM, STORE, SHELL].includes(entry.name))
  .map((entry) => entry.name);
const dirs = (names) => names.map((name) => `./src/${name}`);
const zone = (targets, from, message) => ({ target: dirs(targets), from: dirs(from), message });
const LAYER_ZONES = [
  zone([...BOTTOM], [STORE, ...FEATURES, SHELL], "A bottom module imports no store, feature or shell."),
  zone([STORE], [...FEATURES, SHELL], "The store imports no feature and no shell: move the shared part down."),
  zone(FEATURES, [SHELL], "A feature never imports the app shell: the shell composes features."),
];

export default tseslint.config(
  { ignores: ["src/generated/**", "node_modules/**"] },
  js.configs.recommended,
  ...tseslint.configs.recommended,
  {
    files: ["src/**/*.{ts,tsx}"],
    languageOptions: { globals: { ...globals.browser } },
    plugins: { "react-hooks": reactHooks },
    rules: {
      ...reactHooks.configs.recommended.rules,
      "@typescript-eslint/no-unused-vars": ["error", { argsIgnorePattern: "^_", varsIgnorePattern: "^_" }],
      // React calls whatever an effect returns as its cleanup: an arrow with an expression body returns
      // the expression's value (scrollIntoView returns a Promise in Chromium 156: a blank page, issue 17).
      "no-restricted-syntax": [
        "error",
        {
          selector:
            "CallExpression[callee.name=/^use(Layout|Insertion)?Effect$/] > ArrowFunctionExpression[body.type!='BlockStatement'][body.type!='ArrowFunctionExpression']",
          message:
            "Give an effect a block body (or return a cleanup arrow): an expression body's value becomes its cleanup.",
        },
      ],
    },
  },
  {
    files: ["src/**/*.{ts,tsx}"],
    ignores: ["src/**/*.test.{ts,tsx}"],
    plugins: { "import-x": importX },
    settings: { "import-x/resolver-next": [createNodeResolver({ extensions: [".ts", ".tsx", ".js", ".json"] })] },
    rules: { "import-x/no-restricted-paths": ["error", { zones: LAYER_ZONES }] },
  },
);
