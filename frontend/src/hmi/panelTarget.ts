// The address of a panel window (`/?panel=<project>/<panel>&simulation=<id>`), read before the app
// decides what to load: the panel window's code (hmi/PanelWindow.tsx) is loaded only for such an address.

/** The panel a window was opened for, from its address; null when it is the app's address. */
export function panelTarget(search: string): { project: string; panel: string; simulation: string | null } | null {
  const params = new URLSearchParams(search);
  const target = params.get("panel");
  if (!target || !target.includes("/")) return null;
  const [project, panel] = [target.slice(0, target.lastIndexOf("/")), target.slice(target.lastIndexOf("/") + 1)];
  return { project, panel, simulation: params.get("simulation") || null };
}
