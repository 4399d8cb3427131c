// A printable project document (issue 28): a title page (project, revision, date), then each POU with its
// declarations as a table and its body drawn exactly as the editors draw it (LD and FBD through their own
// layout and drawing; ST as numbered lines), network numbers, labels and comments included, and the
// cross-reference list at the end. The print stylesheet starts every POU on a new page and never cuts a
// network. On screen a toolbar chooses the POUs, prints, and saves the page as HTML or a diagram as SVG.
import { useMemo, useRef } from "react";
import type { LibraryEntry, PrintDocument as Doc, SymbolInfo, XrefEntry } from "../generated/api";
import type { Pou } from "../generated/api";
import { downloadText } from "../ui/download";
import type { FbdBody } from "../fbd/model";
import type { LdBody } from "../ld/model";
import { highlightLines, Tokens } from "../stview/highlight";
import { placeOf, XREF_COLUMNS } from "../xref/model";
import { FbdPrint } from "./FbdPrint";
import { LdPrint } from "./LdPrint";
import { SfcPrint } from "./SfcPrint";
import type { SfcBody } from "../sfc/model";
import { diagramSvg, pageStyles } from "./svg";
import "./print.css";

export interface PrintDocumentProps {
  doc: Doc;
  /** Screen tools (selection, print, save); absent in a document saved as HTML or printed by the CLI. */
  tools?: { all: readonly string[]; onSelect(pous: string[]): void; onSaveHtml(): void } | null;
}

const LANGUAGE = {
  st: "Structured Text",
  ld: "Ladder Diagram",
  fbd: "Function Block Diagram",
  cfc: "Continuous Function Chart",
  sfc: "Sequential Function Chart",
  il: "Instruction List",
} as const;
// A plant is a PROGRAM in IEC text (.plant.st); the print names its role.
const KIND = {
  program: "PROGRAM",
  function_block: "FUNCTION_BLOCK",
  function: "FUNCTION",
  plant: "PROGRAM (plant)",
} as const;

export function PrintDocument({ doc, tools }: PrintDocumentProps) {
  const byName = useMemo(() => new Map(doc.library.map((e) => [e.name.toUpperCase(), e])), [doc.library]);
  const library = useMemo(
    () =>
      (call: string): LibraryEntry | undefined =>
        byName.get(call.toUpperCase()),
    [byName],
  );
  const pous = doc.pous
    .map((name) => (doc.project.pous ?? []).find((p) => p.name === name))
    .filter((p): p is Pou => p !== undefined);
  const printed = new Set(doc.pous.map((p) => p.toUpperCase()));
  const xref = doc.xref.entries.filter((e) =>
    e.pou ? printed.has(e.pou.toUpperCase()) : e.accesses.some((a) => a.pou && printed.has(a.pou.toUpperCase())),
  );
  return (
    <article className="print-document">
      {tools ? <Toolbar doc={doc} tools={tools} /> : null}
      <section className="print-title-page" aria-label="Title page">
        <h1>{doc.project.name}</h1>
        <dl>
          <dt>Revision</dt>
          <dd data-testid="revision">{doc.revision}</dd>
          <dt>Date</dt>
          <dd>{doc.date.replace("T", " ").replace("+00:00", " UTC")}</dd>
          <dt>Contents</dt>
          <dd>
            <ol>
              {pous.map((p) => (
                <li key={p.name}>
                  {KIND[p.kind]} {p.name} ({LANGUAGE[p.language]})
                </li>
              ))}
              <li>Cross-reference list</li>
            </ol>
          </dd>
        </dl>
      </section>
      {pous.map((pou) => (
        <PouSection
          key={pou.name}
          pou={pou}
          symbols={doc.symbols[pou.name] ?? []}
          globals={doc.globals}
          library={library}
        />
      ))}
      <section className="print-pou print-xref" aria-label="Cross-reference list">
        <h2>Cross-reference list</h2>
        <XrefTable entries={xref} />
      </section>
    </article>
  );
}

function Toolbar({ doc, tools }: { doc: Doc; tools: NonNullable<PrintDocumentProps["tools"]> }) {
  const chosen = new Set(doc.pous);
  return (
    <nav className="print-toolbar" aria-label="Print tools">
      <button type="button" onClick={() => window.print()}>
        Print…
      </button>
      <button type="button" onClick={tools.onSaveHtml}>
        Save as HTML
      </button>
      <fieldset>
        <legend>POUs</legend>
        {tools.all.map((name) => (
          <label key={name}>
            <input
              type="checkbox"
              checked={chosen.has(name)}
              onChange={(e) => tools.onSelect(tools.all.filter((n) => (n === name ? e.target.checked : chosen.has(n))))}
            />
            {name}
          </label>
        ))}
      </fieldset>
    </nav>
  );
}

function PouSection({
  pou,
  symbols,
  globals,
  library,
}: {
  pou: Pou;
  symbols: readonly SymbolInfo[];
  globals: readonly SymbolInfo[];
  library: (call: string) => LibraryEntry | undefined;
}) {
  const diagram = useRef<HTMLDivElement>(null);
  const title = `${KIND[pou.kind]} ${pou.name}${pou.return_type ? ` : ${pou.return_type}` : ""}`;
  const saveSvg = () => {
    const drawn = diagram.current?.firstElementChild;
    if (drawn instanceof HTMLElement)
      downloadText(`${pou.name}.svg`, diagramSvg(drawn, pageStyles(document)), "image/svg+xml");
  };
  return (
    <section className="print-pou" aria-label={title} data-pou={pou.name}>
      <h2>
        {title} <small>{LANGUAGE[pou.language]}</small>
        {pou.language === "ld" || pou.language === "fbd" || pou.language === "cfc" ? (
          <button type="button" className="print-screen-only" onClick={saveSvg}>
            Save diagram as SVG
          </button>
        ) : null}
      </h2>
      <h3>Declarations</h3>
      <DeclarationTable symbols={symbols} />
      <h3>
        {pou.language === "st" || pou.language === "il"
          ? "Body"
          : pou.language === "sfc" || pou.language === "cfc"
            ? "Chart"
            : "Networks"}
      </h3>
      <div ref={diagram}>
        {pou.language === "ld" ? (
          <LdPrint body={pou.body as LdBody} library={library} />
        ) : pou.language === "fbd" || pou.language === "cfc" ? (
          <FbdPrint body={pou.body as FbdBody} library={library} symbols={[...symbols, ...globals]} />
        ) : pou.language === "sfc" ? (
          <SfcPrint
            body={pou.body as SfcBody}
            library={library}
            symbols={[...symbols, ...globals]}
            text={(text) => <StBody text={text} />}
          />
        ) : (
          <StBody text={typeof pou.body === "string" ? pou.body : ""} />
        )}
      </div>
    </section>
  );
}

function DeclarationTable({ symbols }: { symbols: readonly SymbolInfo[] }) {
  if (!symbols.length) return <p className="print-empty">No declarations.</p>;
  return (
    <table className="print-table print-declarations">
      <thead>
        <tr>
          <th>Name</th>
          <th>Class</th>
          <th>Type</th>
          <th>Initial value</th>
          <th>Address</th>
          <th>Comment</th>
        </tr>
      </thead>
      <tbody>
        {symbols.map((s) => (
          <tr key={s.name}>
            <td>{s.name}</td>
            <td>
              {s.var_class}
              {s.constant ? " CONSTANT" : ""}
              {s.retain ? " RETAIN" : ""}
            </td>
            <td>{s.type}</td>
            <td>{s.initial ?? ""}</td>
            <td>{s.address ?? ""}</td>
            <td>{s.comment ?? ""}</td>
          </tr>
        ))}
      </tbody>
    </table>
  );
}

function StBody({ text }: { text: string }) {
  return (
    <pre className="print-st">
      {highlightLines(text).map((tokens, i) => (
        <div key={i} className="print-st-line">
          <span className="print-st-number">{i + 1}</span>
          <Tokens tokens={tokens} />
        </div>
      ))}
    </pre>
  );
}

function XrefTable({ entries }: { entries: readonly XrefEntry[] }) {
  return (
    <table className="print-table print-xref-table">
      <thead>
        <tr>
          {XREF_COLUMNS.map((c) => (
            <th key={c}>{c}</th>
          ))}
        </tr>
      </thead>
      {entries.map((e) => (
        <tbody key={`${e.pou ?? ""}/${e.name}`} className="print-xref-entry">
          {e.accesses.map((a, i) => (
            <tr key={i}>
              <td>{i === 0 ? e.name : ""}</td>
              <td>{i === 0 ? (e.pou ?? "global") : ""}</td>
              <td>{i === 0 ? e.type : ""}</td>
              <td>{i === 0 ? (e.address ?? "") : ""}</td>
              <td>{a.kind}</td>
              <td>
                {placeOf(a)}
                {a.path !== e.name ? ` - ${a.path}` : ""}
              </td>
            </tr>
          ))}
        </tbody>
      ))}
    </table>
  );
}
