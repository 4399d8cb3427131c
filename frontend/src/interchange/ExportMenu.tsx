// Export of the saved project: as PLCopen XML, as one ST file, the active POU as ST, and a printable
// document (PDF, HTML, SVG) of the project or the active POU (src/print). The
// server exports the saved version, so unsaved changes are called out before the download.
import { Download } from "lucide-react";
import { useRef, useState } from "react";
import { interchangeApi, type InterchangeApi } from "./api";
import { printUrl } from "../print/data";
import { downloadText } from "../ui/download";
import { failure } from "./outcome";
import { Problems, type Outcome } from "./Problems";

export interface ExportMenuProps {
  project: string;
  /** The POU in the active tab, offered for a single-POU ST export. */
  pou: string | null;
  unsaved: boolean;
  api?: InterchangeApi;
  download?: typeof downloadText;
}

export function ExportMenu({ project, pou, unsaved, api = interchangeApi, download = downloadText }: ExportMenuProps) {
  const [busy, setBusy] = useState(false);
  const [outcome, setOutcome] = useState<Outcome | null>(null);
  const menu = useRef<HTMLDetailsElement>(null);
  const run = async (what: string, fileName: string, get: () => Promise<{ text: string; type: string }>) => {
    setBusy(true);
    setOutcome(null);
    menu.current?.removeAttribute("open");
    try {
      const { text, type } = await get();
      download(fileName, text, type);
    } catch (err) {
      setOutcome(failure(what, err));
    } finally {
      setBusy(false);
    }
  };
  const printing = (url: string) => {
    menu.current?.removeAttribute("open");
    window.open(url, "_blank");
  };
  const st = (p: Promise<{ text: string }>) => p.then((r) => ({ text: r.text, type: "text/plain;charset=utf-8" }));
  return (
    <div className="export-menu">
      <details className="menu" ref={menu}>
        <summary title={unsaved ? "Export the saved version (not the unsaved changes)" : "Export or print the project"}>
          <Download size={16} aria-hidden="true" /> Export
        </summary>
        <div className="menu-items" role="group" aria-label="Export">
          <span className="export-label">Export{unsaved ? " (saved version)" : ""}:</span>
          <button
            type="button"
            disabled={busy}
            onClick={() =>
              void run("PLCopen XML export", `${project}.xml`, () =>
                api.exportPlcopen(project).then((text) => ({ text, type: "application/xml" })),
              )
            }
          >
            PLCopen XML
          </button>
          <button
            type="button"
            disabled={busy}
            onClick={() => void run("ST export", `${project}.st`, () => st(api.exportProjectSt(project)))}
          >
            Project as ST
          </button>
          {pou ? (
            <button
              type="button"
              disabled={busy}
              onClick={() => void run(`ST export of ${pou}`, `${pou}.st`, () => st(api.exportPouSt(project, pou)))}
            >
              {pou} as ST
            </button>
          ) : null}
          <button type="button" onClick={() => printing(printUrl(project))}>
            Print project…
          </button>
          {pou ? (
            <button type="button" onClick={() => printing(printUrl(project, [pou]))}>
              Print {pou}…
            </button>
          ) : null}
        </div>
      </details>
      {outcome ? (
        <div className="export-outcome">
          <Problems outcome={outcome} />
          <button type="button" className="link" onClick={() => setOutcome(null)}>
            Dismiss
          </button>
        </div>
      ) : null}
    </div>
  );
}
