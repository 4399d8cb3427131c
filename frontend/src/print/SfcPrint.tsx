// An SFC POU on paper: the chart as the editor draws it (SfcDiagram), then each action and named transition with
// its body (ST text, its LD/FBD networks as the other print views draw them, or an SFC action's chart).
import type { ReactNode } from "react";
import type { LibraryEntry, SymbolInfo } from "../generated/api";
import type { FbdBody } from "../fbd/model";
import type { LdBody } from "../ld/model";
import { SfcDiagram } from "../sfc/SfcDiagram";
import { chartOf, type SfcBody } from "../sfc/model";
import "../sfc/sfc.css";
import { FbdPrint } from "./FbdPrint";
import { LdPrint } from "./LdPrint";

export function SfcPrint(props: {
  body: SfcBody;
  library(call: string): LibraryEntry | undefined;
  symbols: readonly SymbolInfo[];
  text(body: string): ReactNode;
}) {
  const { body } = props;
  const parts = [
    ...(body.actions ?? []).map((a) => ({ what: "Action", ...a })),
    ...(body.transitions ?? []).map((t) => ({ what: "Transition", ...t })),
  ];
  return (
    <>
      <SfcDiagram elements={chartOf(body)} selected={null} />
      {parts.map((part) => (
        <section key={`${part.what} ${part.name}`} aria-label={`${part.what} ${part.name}`}>
          <h4>
            {part.what} {part.name} ({(part.language ?? "st").toUpperCase()})
          </h4>
          {typeof part.body === "string" || part.body === undefined ? (
            props.text(typeof part.body === "string" ? part.body : "")
          ) : part.language === "sfc" ? (
            <SfcDiagram elements={chartOf({ chart: part.body as SfcBody["chart"] })} selected={null} />
          ) : part.language === "ld" ? (
            <LdPrint body={part.body as LdBody} library={props.library} />
          ) : (
            <FbdPrint body={part.body as FbdBody} library={props.library} symbols={props.symbols} />
          )}
        </section>
      ))}
    </>
  );
}
