// One FBD node on the canvas: blocks with typed pins (negation bubbles, edge markers, EN/ENO),
// input/output variables, jumps, returns, connectors and continuations; each with its execution
// order badge, diagnostics, breakpoint mark and online value.
import { Handle, Position, type Node, type NodeProps } from "@xyflow/react";
import type { Block, FbdComment, FbdNetwork, FbdNode, OutputMode, PinDef } from "../model";
import { kindOf } from "../model";
import { OperandEditor } from "../../ui/OperandEditor";
import { pinKey } from "../../online/pinValues";
import { shownOf, type ValueShown } from "../../online/shown";
import { ValueTag } from "../../online/ValueTag";
import { executed, operandOf } from "../online";
import { useFbdEditor, type NodeView } from "./context";

export type FbdFlowNode = Node<{ network: FbdNetwork; node: FbdNode }, "fbd">;

/** Handle ids: the side and the pin name (`in:IN1`, `out:OUT`). */
export const handleId = (side: "in" | "out", pin: string): string => `${side}:${pin}`;
export const pinOfHandle = (handle: string | null | undefined): string => (handle ?? "").replace(/^(in|out):/, "");

export const PIN_ROW = 22;
const HEADER = 24;
/** The drawn height of a node (auto-arrange stacks nodes by it). */
export const nodeHeight = (node: FbdNode, rows: number): number =>
  kindOf(node) === "block" ? HEADER + Math.max(1, rows) * PIN_ROW + 8 : 34;

const MODE_MARK: Record<OutputMode, string> = { normal: "", negated: "/", set: "S", reset: "R", p: "P", n: "N" };

const titleOf = (view: NodeView, pin?: string) =>
  view.diagnostics
    .filter((d) => (pin ? d.pin?.toUpperCase() === pin.toUpperCase() : true))
    .map((d) => `${d.code}: ${d.message}`)
    .join("\n") || undefined;

function PinRow({ node, input, output, view }: { node: FbdNode; input?: PinDef; output?: PinDef; view: NodeView }) {
  const api = useFbdEditor();
  const flags = kindOf(node) === "block" ? ((node as Block).pins ?? {}) : {};
  const side = (pin: PinDef | undefined, dir: "in" | "out") => {
    if (!pin) return <span className={`fbd-pin fbd-pin-${dir} fbd-pin-empty`} />;
    const f = flags[pin.name] ?? {};
    const error = view.diagnostics.some((d) => d.pin?.toUpperCase() === pin.name.toUpperCase());
    return (
      <span
        className={`fbd-pin fbd-pin-${dir}${f.negated ? " fbd-negated" : ""}${error ? " fbd-pin-error" : ""}`}
        data-pin={pin.name}
        title={titleOf(view, pin.name) ?? `${pin.name}${pin.type ? ` : ${pin.type}` : ""}`}
        onContextMenu={(e) => api.pinMenu(node, pin.name, dir, e)}
      >
        <Handle
          type={dir === "in" ? "target" : "source"}
          position={dir === "in" ? Position.Left : Position.Right}
          id={handleId(dir, pin.name)}
          className="fbd-handle"
        />
        {f.negated ? <span className="fbd-bubble" aria-label="negated" /> : null}
        {f.edge ? (
          <span className="fbd-edge-mark" aria-label={`${f.edge} edge`}>
            {f.edge === "rising" ? ">" : "<"}
          </span>
        ) : null}
        <span className="fbd-pin-name">{pin.name}</span>
        {pinValue(pin, dir)}
      </span>
    );
  };
  const pinValue = (pin: PinDef, dir: "in" | "out") => {
    const shown = api.online?.pins[node.id]?.[pinKey(dir, pin.name)];
    return shown ? (
      <span
        className="fbd-pin-value nodrag"
        data-pin-value={pinKey(dir, pin.name)}
        onDoubleClick={() => api.pinDoubleClick(node, dir, pin.name)}
      >
        <ValueTag shown={shown} />
      </span>
    ) : null;
  };
  return (
    <div className="fbd-pin-row" style={{ height: PIN_ROW }}>
      {side(input, "in")}
      {side(output, "out")}
    </div>
  );
}

function Badges({ view }: { view: NodeView }) {
  return (
    <>
      {view.order !== undefined ? (
        <span className="fbd-order" title="Execution order" aria-label={`runs ${view.order}.`}>
          {view.order}
        </span>
      ) : null}
      {view.breakpoint ? <span className="fbd-breakpoint" aria-label="breakpoint" /> : null}
    </>
  );
}

/** Node kinds whose text names a variable (the others name labels and connectors: no variable suggestions). */
const NAMES_VARIABLE = new Set(["input", "output", "block"]);

function TextField({
  node,
  text,
  placeholder,
  label,
}: {
  node: FbdNode;
  text: string;
  placeholder: string;
  label: string;
}) {
  const api = useFbdEditor();
  if (api.editing === node.id) {
    return (
      <div className="nodrag nopan nowheel fbd-text-editor">
        <OperandEditor
          label={label}
          initial={text}
          suggestions={NAMES_VARIABLE.has(kindOf(node)) ? api.symbols : []}
          members={NAMES_VARIABLE.has(kindOf(node)) ? api.members : undefined}
          onCommit={(t) => api.commitEdit(node.id, t)}
          onCancel={api.cancelEdit}
        />
      </div>
    );
  }
  return (
    <span
      className={`fbd-text${text ? "" : " fbd-placeholder"}`}
      onDoubleClick={() => (api.online ? api.valueDoubleClick(node) : !api.readOnly && api.startEdit(node.id))}
    >
      {text || placeholder}
    </span>
  );
}

export function FbdNodeView({ data, selected }: NodeProps<FbdFlowNode>) {
  const api = useFbdEditor();
  /** A variable node's value: its variable's (forced, prepared), else the probe's (a literal, an expression). */
  const nodeValue = (id: string, operand: string | null): ValueShown | null => {
    const variable = operand ? api.online?.operands[operand.toUpperCase()] : undefined;
    if (variable) return variable;
    const probe = api.online?.probes[id];
    if (probe === undefined || probe === null) return null;
    const pins = api.view(data.network, data.node).pins;
    return { ...shownOf(probe, (pins.outputs[0] ?? pins.inputs[0])?.type), forced: false, prepared: null };
  };
  const { network, node } = data;
  const view = api.view(network, node);
  const kind = kindOf(node);
  const online = api.online;
  const skipped = online ? !executed(online, node.id) : false;
  const operand = operandOf(node);
  // a jump shows its condition (its probe), as CODESYS shows the value at a CFC jump's input
  const shown =
    online && (kind === "input" || kind === "output" || kind === "jump") ? nodeValue(node.id, operand) : null;
  const forced = shown?.forced ?? false;
  const classes = [
    "fbd-node",
    `fbd-${kind}`,
    selected ? "fbd-selected" : "",
    skipped ? "fbd-skipped" : "",
    view.diagnostics.length ? "fbd-error" : "",
    view.halted ? "fbd-halted" : "",
    forced ? "fbd-forced" : "",
    view.coverage ? `fbd-coverage-${view.coverage}` : "",
  ].filter(Boolean);
  const common = { className: classes.join(" "), "data-node": node.id, title: titleOf(view) };

  if (kind === "block") {
    const block = node as Block;
    const rows = Math.max(view.pins.inputs.length, view.pins.outputs.length);
    return (
      <div {...common}>
        <Badges view={view} />
        {view.fb || block.instance ? (
          <div className="fbd-instance">
            <TextField node={node} text={block.instance ?? ""} placeholder="instance" label="Instance" />
          </div>
        ) : null}
        <div className="fbd-block-title">{block.call}</div>
        {Array.from({ length: rows }, (_, i) => (
          <PinRow key={i} node={node} input={view.pins.inputs[i]} output={view.pins.outputs[i]} view={view} />
        ))}
      </div>
    );
  }

  if (kind === "comment") {
    // A free comment box (issue 28): its text where it was drawn, as large as it was drawn; no pins.
    const note = node as FbdComment;
    return (
      <div {...common} style={{ width: note.width ?? undefined, height: note.height ?? undefined }}>
        <TextField node={node} text={note.text ?? ""} placeholder="comment" label="Comment" />
      </div>
    );
  }

  const input = view.pins.inputs[0];
  const output = view.pins.outputs[0];
  const text = (() => {
    switch (kind) {
      case "input":
        return (
          <TextField
            node={node}
            text={(node as { expr: string }).expr}
            placeholder="variable or constant"
            label="Input operand"
          />
        );
      case "output":
        return (
          <TextField node={node} text={(node as { var: string }).var} placeholder="variable" label="Output variable" />
        );
      case "jump":
        return (
          <>
            <span className="fbd-keyword">JMP</span>{" "}
            <TextField node={node} text={(node as { target: string }).target} placeholder="label" label="Jump target" />
          </>
        );
      case "return":
        return <span className="fbd-keyword">RETURN</span>;
      case "label":
        return (
          <>
            <TextField node={node} text={(node as { name: string }).name} placeholder="label" label="Label name" />
            <span className="fbd-keyword">:</span>
          </>
        );
      default:
        return (
          <TextField
            node={node}
            text={(node as { name: string }).name}
            placeholder="name"
            label={kind === "connector" ? "Connector name" : "Continuation name"}
          />
        );
    }
  })();
  const mode = kind === "output" ? MODE_MARK[(node as { mode?: OutputMode }).mode ?? "normal"] : "";
  return (
    <div {...common}>
      <Badges view={view} />
      {input ? (
        <Handle type="target" position={Position.Left} id={handleId("in", input.name)} className="fbd-handle" />
      ) : null}
      {mode ? (
        <span className="fbd-mode" aria-label={`mode ${(node as { mode?: OutputMode }).mode}`}>
          {mode}
        </span>
      ) : null}
      {text}
      {shown ? (
        <span
          className="fbd-value nodrag"
          data-testid={`value-${node.id}`}
          onDoubleClick={() => api.valueDoubleClick(node)}
        >
          <ValueTag shown={shown} />
        </span>
      ) : null}
      {output ? (
        <Handle type="source" position={Position.Right} id={handleId("out", output.name)} className="fbd-handle" />
      ) : null}
    </div>
  );
}
