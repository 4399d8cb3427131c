// An FBD body as the editor draws it: the editor's own network canvases (src/fbd/editor), read-only,
// every node shown, each network a block that a page break never cuts.
import "@xyflow/react/dist/style.css";
import type { LibraryEntry, SymbolInfo } from "../generated/api";
import "../ld/ld.css";
import { FbdEditorContext, type FbdEditorApi } from "../fbd/editor/context";
import { NetworkCanvas } from "../fbd/editor/NetworkCanvas";
import { useNodeLayout } from "../fbd/editor/useNodeLayout";
import "../fbd/editor/fbd.css";
import { kindOf, networksOf, nodePins, type Block, type FbdBody } from "../fbd/model";

const NONE: never[] = [];
const nothing = () => {};

export function FbdPrint({
  body,
  library,
  symbols,
}: {
  body: FbdBody;
  library: (call: string) => LibraryEntry | undefined;
  symbols: readonly SymbolInfo[];
}) {
  const networks = networksOf(body);
  const { heightOf, fallbacks } = useNodeLayout(networks, library, symbols);
  const api: FbdEditorApi = {
    readOnly: true,
    symbols,
    editing: null,
    view: (network, node) => ({
      pins: nodePins(node, network, library, symbols),
      diagnostics: NONE,
      breakpoint: false,
      halted: false,
      fb: kindOf(node) === "block" && library((node as Block).call)?.kind === "function_block",
    }),
    startEdit: nothing,
    commitEdit: nothing,
    cancelEdit: nothing,
    pinMenu: nothing,
    valueDoubleClick: nothing,
    pinDoubleClick: nothing,
  };
  return (
    <FbdEditorContext.Provider value={api}>
      <div className="print-diagram print-fbd ld-palette">
        {networks.map((network, index) => (
          <div key={network.id} className="print-network" data-network={network.id}>
            <NetworkCanvas
              network={network}
              index={index}
              readOnly
              print
              selected={null}
              networkSelected={false}
              problems={NONE}
              breakpoint={false}
              halted={false}
              fallback={fallbacks.get(network.id)!}
              height={heightOf(network)}
              onSelectChanges={nothing}
              onSelectNetwork={nothing}
              onToggleBreakpoint={nothing}
              onEditText={nothing}
              onMove={nothing}
              onConnect={nothing}
              refusal={() => "read-only"}
              onRefused={nothing}
              onDropNew={nothing}
              onNodeContextMenu={nothing}
              onNodeClick={nothing}
              onNear={nothing}
            />
          </div>
        ))}
      </div>
    </FbdEditorContext.Provider>
  );
}
