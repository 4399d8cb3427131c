// The print page (print.html): renders the document embedded by `ladderlab doc`, or the one of the
// project and POUs in the query (fetched from the server), with the screen tools of the browser.
import { StrictMode, useEffect, useState } from "react";
import { createRoot } from "react-dom/client";
import { flushSync } from "react-dom";
import type { PrintDocument as Doc } from "../generated/api";
import { downloadText } from "../ui/download";
import { embeddedDocument, fetchDocument, printUrl, requestOf, type PrintRequest } from "./data";
import { PrintDocument } from "./PrintDocument";
import { staticHtml } from "./html";

function Fetched({ request }: { request: PrintRequest }) {
  const [doc, setDoc] = useState<Doc | null>(null);
  const [error, setError] = useState<string | null>(null);
  const [all, setAll] = useState<string[] | null>(null);
  useEffect(() => {
    fetchDocument(request).then(
      (d) => {
        setDoc(d);
        setAll((known) => known ?? (d.project.pous ?? []).map((p) => p.name));
        document.title = `${d.project.name} - LadderLab`;
      },
      (e: unknown) => setError(e instanceof Error ? e.message : String(e)),
    );
  }, [request]);
  if (error) return <p role="alert">The document could not be made: {error}</p>;
  if (!doc) return <p>Preparing the document…</p>;
  return (
    <PrintDocument
      doc={doc}
      tools={{
        all: all ?? doc.pous,
        onSelect: (pous) => window.location.assign(printUrl(request.project, pous)),
        onSaveHtml: () => downloadText(`${doc.project.name}.html`, staticHtml(document), "text/html;charset=utf-8"),
      }}
    />
  );
}

const root = document.getElementById("root");
if (!root) throw new Error("print.html has no #root element");
const embedded = embeddedDocument(document);
const request = requestOf(window.location.search);
const app = createRoot(root);
if (embedded) {
  // Rendered at once, so Chromium's --print-to-pdf (ladderlab doc) prints the whole document.
  flushSync(() => app.render(<PrintDocument doc={embedded} />));
  document.title = `${embedded.project.name} - LadderLab`;
} else if (request) {
  app.render(
    <StrictMode>
      <Fetched request={request} />
    </StrictMode>,
  );
} else {
  app.render(<p role="alert">No project to print: open this page from a project (Export: Print…).</p>);
}
