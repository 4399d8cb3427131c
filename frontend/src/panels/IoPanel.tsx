// The I/O view: every direct address the running program uses (%I inputs, %Q outputs, %M memory),
// with the variables declared at it and its live value; each row writes, forces, releases and
// prepares the address itself (a variable row of the watch list's tree), so an input can be driven
// whether or not a variable names it.
import { useEffect, useMemo } from "react";
import type { IoPoint } from "../generated/api";
import { onlineStore, useOnline } from "../online/store";
import { VariableRow, type Expansion } from "./VariableTree";

export const AREA_NAMES: Record<IoPoint["area"], string> = {
  I: "Input",
  Q: "Output",
  M: "Memory",
  S: "System",
};

/** The subscription key of the I/O view. */
export const IO_VIEW = "io";

/** Addresses are elementary: nothing expands. */
const FLAT: Expansion = { isOpen: () => false, toggle: () => undefined };

function IoRow({ point }: { point: IoPoint }) {
  const names = point.names ?? [];
  return (
    <VariableRow
      node={{ name: names.length ? names.join(", ") : "—", path: point.address, type: point.type, expandable: false }}
      depth={0}
      expansion={FLAT}
      lead={
        <>
          <td>{AREA_NAMES[point.area]}</td>
          <td className="watch-path">{point.address}</td>
        </>
      }
      actions={
        <button
          type="button"
          aria-label={`Watch ${point.address}`}
          onClick={() => onlineStore.getState().addWatch(point.address)}
        >
          Watch
        </button>
      }
    />
  );
}

export function IoPanel() {
  const io = useOnline((s) => s.io);
  const live = useOnline((s) => s.phase !== "offline");
  const paths = useMemo(() => io.map((p) => p.address), [io]);
  useEffect(() => {
    onlineStore.getState().subscribe(IO_VIEW, live && paths.length ? { paths, elements: [] } : null);
  }, [live, paths]);
  useEffect(() => () => onlineStore.getState().subscribe(IO_VIEW, null), []);
  if (!live) {
    return <p className="panel-empty">Go online to see the program's inputs, outputs and memory by address.</p>;
  }
  if (!io.length) {
    return <p className="panel-empty">The program uses no direct addresses (%I, %Q, %M).</p>;
  }
  return (
    <table className="watch-table" aria-label="Process image">
      <thead>
        <tr>
          <th>Area</th>
          <th>Address</th>
          <th>Declared as</th>
          <th>Value</th>
          <th>Type</th>
          <th>Write / force</th>
        </tr>
      </thead>
      <tbody>
        {io.map((p) => (
          <IoRow key={p.address} point={p} />
        ))}
      </tbody>
    </table>
  );
}
