// The FBD model as the editor sees it: the generated project types, the pins every node shows
// (typed from the library and the symbols), and lookups by id. Pin names follow the lowering
// (ir/fbd_order.py): simple nodes have one pin, IN or OUT; a function's result is OUT.
import type { LibraryEntry, SymbolInfo } from "../generated/api";
import type { Block, FbdBody, FbdNetwork, PinRef, Wire } from "../generated/api";
import { RESULT_PIN } from "../ld/pins";
import { blockEntry, symbolType, type Lookup } from "../store/calls";

export { blockEntry, instanceMethodEntries, methodEntry, symbolType, type Lookup } from "../store/calls";

export type {
  Block,
  Connector,
  Continuation,
  FbdBody,
  FbdComment,
  FbdJump,
  FbdLabel,
  FbdNetwork,
  FbdReturn,
  InputNode,
  OutputNode,
  PinRef,
  Position,
  Wire,
} from "../generated/api";

export type FbdNode = NonNullable<FbdNetwork["nodes"]>[number];
export type NodeKind = NonNullable<FbdNode["type"]>;
export type OutputMode = "normal" | "negated" | "set" | "reset" | "p" | "n";

export const SIMPLE_IN = "IN";
export const SIMPLE_OUT = RESULT_PIN;

export const networksOf = (body: FbdBody): FbdNetwork[] => body.networks ?? [];
export const nodesOf = (network: FbdNetwork): FbdNode[] => network.nodes ?? [];
export const wiresOf = (network: FbdNetwork): Wire[] => network.wires ?? [];
export const kindOf = (node: FbdNode): NodeKind => node.type ?? "block";

export function findNode(body: FbdBody, id: string): { network: FbdNetwork; node: FbdNode } | undefined {
  for (const network of networksOf(body)) {
    const node = nodesOf(network).find((n) => n.id === id);
    if (node) return { network, node };
  }
  return undefined;
}

export const samePin = (a: PinRef, b: PinRef): boolean =>
  a.node === b.node && a.pin.toUpperCase() === b.pin.toUpperCase();
export const wireKey = (w: Wire): string => `${w.from.node}.${w.from.pin}->${w.to.node}.${w.to.pin}`;

/** A pin as drawn: its name and declared type (a generic family such as ANY_NUM; undefined when unknown). */
export interface PinDef {
  name: string;
  type?: string;
}

export interface NodePins {
  inputs: PinDef[];
  outputs: PinDef[];
}

const EXTENSION = /^([A-Z_]+?)(\d+)$/;

/**
 * The inputs of an extensible block: the declared ones, then as many more like the last as the
 * model names (through a wire or pin flags): ADD with a wire into IN3 shows IN1..IN3.
 */
function extensionInputs(block: Block, entry: LibraryEntry, wires: readonly Wire[]): PinDef[] {
  const declared = entry.inputs;
  const last = declared[declared.length - 1];
  const match = last && EXTENSION.exec(last.name.toUpperCase());
  if (!last || !match) return declared;
  const [, stem, first] = match;
  const named = [...Object.keys(block.pins ?? {}), ...wires.filter((w) => w.to.node === block.id).map((w) => w.to.pin)];
  let highest = Number(first);
  for (const pin of named) {
    const m = EXTENSION.exec(pin.toUpperCase());
    if (m && m[1] === stem) highest = Math.max(highest, Number(m[2]));
  }
  const extra: PinDef[] = [];
  for (let n = Number(first) + 1; n <= highest; n += 1) extra.push({ name: `${stem}${n}`, type: last.type });
  return [...declared, ...extra];
}

/** The name the next "add input" creates on an extensible block (null when it is not one). */
export function nextInput(block: Block, entry: LibraryEntry | undefined, wires: readonly Wire[]): string | null {
  if (!entry?.extensible) return null;
  const inputs = extensionInputs(block, entry, wires);
  const match = EXTENSION.exec(inputs[inputs.length - 1]?.name.toUpperCase() ?? "");
  return match ? `${match[1]}${Number(match[2]) + 1}` : null;
}

/** The type of an input node's operand: a declared variable or a literal's family. */
export function operandType(text: string, symbols: readonly SymbolInfo[]): string | undefined {
  const t = text.trim().toUpperCase();
  if (t === "TRUE" || t === "FALSE") return "BOOL";
  const typed = /^([A-Z_]+)#/.exec(t);
  if (
    typed &&
    !["T", "TIME", "D", "DATE", "TOD", "TIME_OF_DAY", "DT", "DATE_AND_TIME", "LT", "LTIME"].includes(typed[1]!)
  )
    return typed[1];
  if (/^(T|TIME)#/.test(t)) return "TIME";
  if (/^[+-]?\d[\d_]*$/.test(t) || /^(2|8|16)#[0-9A-F_]+$/.test(t)) return "ANY_LITERAL_INT";
  if (/^[+-]?\d[\d_]*\.\d[\d_]*(E[+-]?\d+)?$/.test(t)) return "ANY_REAL";
  if (/^'.*'$/.test(t)) return "STRING";
  return symbolType(t, symbols);
}

/** The pins of `node`, in drawing order (EN first and ENO first when a block has them). */
export function nodePins(node: FbdNode, network: FbdNetwork, lookup: Lookup, symbols: readonly SymbolInfo[]): NodePins {
  switch (kindOf(node)) {
    case "block": {
      const block = node as Block;
      const entry = blockEntry(block.call, lookup, symbols);
      const en = block.en ? [{ name: "EN", type: "BOOL" }] : [];
      const eno = block.en ? [{ name: "ENO", type: "BOOL" }] : [];
      if (!entry) {
        // An unknown block keeps the pins its wires name, so nothing drawn disappears.
        const wires = wiresOf(network);
        const names = (side: "from" | "to") => [
          ...new Set(wires.filter((w) => w[side].node === block.id).map((w) => w[side].pin.toUpperCase())),
        ];
        return {
          inputs: [
            ...en,
            ...names("to")
              .filter((p) => p !== "EN")
              .map((name) => ({ name })),
          ],
          outputs: [
            ...eno,
            ...names("from")
              .filter((p) => p !== "ENO")
              .map((name) => ({ name })),
          ],
        };
      }
      const result =
        entry.kind === "function" && entry.return_type ? [{ name: RESULT_PIN, type: entry.return_type }] : [];
      return {
        inputs: [...en, ...extensionInputs(block, entry, wiresOf(network)), ...entry.in_outs],
        outputs: [...eno, ...result, ...entry.outputs],
      };
    }
    case "input":
      return {
        inputs: [],
        outputs: [{ name: SIMPLE_OUT, type: operandType((node as { expr: string }).expr, symbols) }],
      };
    case "output": {
      const out = node as { var: string; mode?: OutputMode };
      const type = (out.mode ?? "normal") === "normal" ? symbolType(out.var, symbols) : "BOOL";
      return { inputs: [{ name: SIMPLE_IN, type }], outputs: [] };
    }
    case "jump":
    case "return":
      return { inputs: [{ name: SIMPLE_IN, type: "BOOL" }], outputs: [] };
    case "connector":
      return { inputs: [{ name: SIMPLE_IN }], outputs: [] };
    case "label":
    case "continuation":
      return { inputs: [], outputs: [{ name: SIMPLE_OUT }] };
    case "comment":
      return { inputs: [], outputs: [] };
  }
}
