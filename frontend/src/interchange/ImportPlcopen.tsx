// "Import PLCopen XML": pick a file, optionally name the new project, POST it, then show what the
// import reported (warnings about what it converted or dropped) and offer to open the project.
import { FileUp } from "lucide-react";
import { useState, type FormEvent } from "react";
import { ToolButton } from "../ui/ToolButton";
import type { ImportReport } from "../generated/api";
import { interchangeApi, type InterchangeApi } from "./api";
import { failure } from "./outcome";
import { Problems, type Outcome } from "./Problems";

export interface ImportPlcopenProps {
  /** The new project is stored: refresh the project list. "Open" is offered only once this settles, since the
   * app can open only a project its list holds (a click before the list caught up would do nothing). */
  onStored(name: string): void | Promise<void>;
  /** The user asks to open the new project. */
  onOpen(name: string): void;
  api?: InterchangeApi;
}

/** The file's text, through FileReader (which every browser and jsdom have; Blob.text is newer). */
function readText(file: Blob): Promise<string> {
  return new Promise((resolve, reject) => {
    const reader = new FileReader();
    reader.onload = () => resolve(String(reader.result));
    reader.onerror = () => reject(reader.error ?? new Error("the file cannot be read"));
    reader.readAsText(file);
  });
}

/** The summary line of a successful import. */
export function importSummary(report: ImportReport): string {
  const { name, pou_count } = report.project;
  const warnings = report.diagnostics?.length ?? 0;
  return `Imported ${name}: ${pou_count} POU${pou_count === 1 ? "" : "s"}, ${warnings ? `${warnings} warning${warnings === 1 ? "" : "s"}` : "no warnings"}.`;
}

export function ImportPlcopen({ onStored, onOpen, api = interchangeApi }: ImportPlcopenProps) {
  const [open, setOpen] = useState(false);
  const [file, setFile] = useState<File | null>(null);
  const [name, setName] = useState("");
  const [busy, setBusy] = useState(false);
  const [outcome, setOutcome] = useState<Outcome | null>(null);
  const [imported, setImported] = useState<string | null>(null);
  if (!open) {
    return (
      <ToolButton icon={FileUp} label="Import PLCopen XML…" className="import-button" onClick={() => setOpen(true)} />
    );
  }
  const submit = async (e: FormEvent) => {
    e.preventDefault();
    if (!file) return;
    setBusy(true);
    setOutcome(null);
    setImported(null);
    try {
      const report = await api.importPlcopen(await readText(file), name);
      setOutcome({ message: importSummary(report), diagnostics: report.diagnostics ?? [], failed: false });
      await onStored(report.project.name);
      setImported(report.project.name);
    } catch (err) {
      setOutcome(failure("The import", err));
    } finally {
      setBusy(false);
    }
  };
  return (
    <form className="import-plcopen" aria-label="Import PLCopen XML" onSubmit={(e) => void submit(e)}>
      <input
        type="file"
        aria-label="PLCopen XML file"
        accept=".xml,application/xml,text/xml"
        onChange={(e) => setFile(e.target.files?.[0] ?? null)}
      />
      <input
        aria-label="New project name"
        value={name}
        onChange={(e) => setName(e.target.value)}
        placeholder="name (default: the document's)"
        spellCheck={false}
      />
      <button type="submit" disabled={busy || !file}>
        {busy ? "Importing…" : "Import"}
      </button>
      <button type="button" onClick={() => setOpen(false)}>
        Close
      </button>
      {outcome ? <Problems outcome={outcome} /> : null}
      {imported ? (
        <button type="button" onClick={() => onOpen(imported)}>
          Open {imported}
        </button>
      ) : null}
    </form>
  );
}
