// Where the FBD canvases draw nodes, shared by the editor and the print view: each node's drawn height
// (from its pins) and, for networks with nodes that have no stored position (imported, hand-written),
// the places auto-arrange would give them.
import { useCallback, useMemo } from "react";
import type { SymbolInfo } from "../../generated/api";
import { arrange } from "../arrange";
import { nodePins, nodesOf, type FbdNetwork, type FbdNode, type Lookup, type Position } from "../model";
import { nodeHeight } from "./FbdNodeView";

export function useNodeLayout(networks: readonly FbdNetwork[], lookup: Lookup, symbols: readonly SymbolInfo[]) {
  const heightOf = useCallback(
    (network: FbdNetwork) => (node: FbdNode) => {
      const pins = nodePins(node, network, lookup, symbols);
      return nodeHeight(node, Math.max(pins.inputs.length, pins.outputs.length));
    },
    [lookup, symbols],
  );
  const fallbacks = useMemo(
    () =>
      new Map(
        networks.map((n) => [
          n.id,
          nodesOf(n).every((node) => node.pos) ? new Map<string, Position>() : arrange(n, heightOf(n)),
        ]),
      ),
    [networks, heightOf],
  );
  return { heightOf, fallbacks };
}
