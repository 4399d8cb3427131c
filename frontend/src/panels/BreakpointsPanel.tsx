// Every breakpoint of the project (LD/FBD networks and elements, ST lines, wherever they were set):
// enable/disable, remove, remove all, and a click shows the place in its editor. The row where the
// scan is halted is marked.
import type { Pou } from "../generated/api";
import { breakpointKey, type Breakpoint } from "../debug/breakpoints";
import { revealPlace } from "../debug/reveal";
import { debugStore, isEnabled, useDebug } from "../debug/store";
import { breakpointBody, describePlace } from "../breakpointPlaces/place";
import type { At } from "../online/protocol";
import { useOnline } from "../online/store";
import { useWorkspace } from "../store/project";

/** Whether the scan halted at this breakpoint. */
function hitBy(bp: Breakpoint, at: At | null): boolean {
  if (!at || at.pou.toUpperCase() !== bp.pou.toUpperCase() || (at.body ?? null) !== (bp.body ?? null)) return false;
  if ("network" in bp) return at.network === bp.network && !at.element;
  return "element" in bp ? at.element === bp.element : at.line === bp.line;
}

function BreakpointRow({
  bp,
  enabled,
  pou,
  hit,
}: {
  bp: Breakpoint;
  enabled: boolean;
  pou: Pou | undefined;
  hit: boolean;
}) {
  const name = pou?.name ?? bp.pou;
  const { body, language } = breakpointBody(bp, pou);
  const place = describePlace(bp, pou, body, language);
  const label = `${name}, ${place}`;
  const debug = debugStore.getState();
  return (
    <tr
      className={`breakpoint-row${enabled ? "" : " breakpoint-disabled"}${hit ? " breakpoint-hit" : ""}`}
      data-breakpoint={breakpointKey(bp)}
    >
      <td>
        <input
          type="checkbox"
          aria-label={`Enable breakpoint ${label}`}
          checked={enabled}
          onChange={(e) => debug.setEnabled(bp, e.target.checked)}
        />
      </td>
      <td>
        <button
          type="button"
          className="link"
          title="Show in the editor"
          onClick={() =>
            revealPlace({
              pou: name,
              network: "network" in bp ? bp.network : null,
              element: "element" in bp ? bp.element : null,
              line: "line" in bp ? bp.line : null,
              body: bp.body ?? null,
            })
          }
        >
          <span className="breakpoint-pou">{name}</span> {place}
        </button>
        {hit ? <span className="breakpoint-hit-mark"> ← halted here</span> : null}
      </td>
      <td>
        <button type="button" aria-label={`Remove breakpoint ${label}`} onClick={() => debug.remove(bp)}>
          ×
        </button>
      </td>
    </tr>
  );
}

export function BreakpointsPanel() {
  const breakpoints = useDebug((s) => s.breakpoints);
  const disabled = useDebug((s) => s.disabled);
  const project = useWorkspace((s) => s.project);
  const at = useOnline((s) => (s.monitor.state === "halted" ? s.monitor.at : null));
  const notice = useDebug((s) => s.notice);
  const noticed = notice ? (
    <p className="breakpoints-notice" role="status">
      {notice}{" "}
      <button type="button" aria-label="Dismiss" onClick={() => debugStore.getState().dismissNotice()}>
        ×
      </button>
    </p>
  ) : null;
  if (!breakpoints.length) {
    return (
      <>
        {noticed}
        <p className="panel-empty">
          No breakpoints. Click a network number in a diagram, Alt+click an element (or select it and press F9), or
          click the gutter of an ST line.
        </p>
      </>
    );
  }
  return (
    <div className="breakpoints-panel">
      {noticed}
      <button type="button" onClick={() => debugStore.getState().clearAll()}>
        Remove all breakpoints
      </button>
      <table className="breakpoints-table" aria-label="Breakpoints">
        <tbody>
          {breakpoints.map((bp) => {
            const pou = project?.pous?.find((p) => p.name.toUpperCase() === bp.pou.toUpperCase());
            return (
              <BreakpointRow
                key={breakpointKey(bp)}
                bp={bp}
                enabled={isEnabled({ disabled }, bp)}
                pou={pou}
                hit={hitBy(bp, at)}
              />
            );
          })}
        </tbody>
      </table>
    </div>
  );
}
