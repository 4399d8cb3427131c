// An LD body as the editor draws it (src/ld: the same layout and network SVGs), one network per block
// that a page break never cuts.
import { useMemo } from "react";
import type { LibraryEntry } from "../generated/api";
import { layoutBody } from "../ld/layout";
import type { LdBody } from "../ld/model";
import { NetworkView } from "../ld/view/NetworkView";
import "../ld/ld.css";

const NONE: never[] = [];

export function LdPrint({ body, library }: { body: LdBody; library: (call: string) => LibraryEntry | undefined }) {
  const layout = useMemo(() => layoutBody(body, { library }), [body, library]);
  return (
    <div className="print-diagram print-ld ld-palette" data-width={layout.width}>
      {layout.networks.map((n) => (
        <div key={n.network.id} className="print-network" data-network={n.network.id} style={{ height: n.height }}>
          <NetworkView
            layout={n}
            width={layout.width}
            selection={null}
            diagnostics={NONE}
            dropping={false}
            handlers={{}}
          />
        </div>
      ))}
    </div>
  );
}
