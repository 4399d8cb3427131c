// The diagnostics catalogue (docs/diagnostics.md, src/generated/diagnostics.ts: ~55 kB of text) is
// loaded the first time the Diagnostics panel lists a problem, not with the app (issue 22 item 8).
import { useEffect, useState } from "react";

/** A code's entry: what it means, an example that triggers it and how to fix it. */
export interface CatalogueEntry {
  summary: string;
  example?: string;
  example_note?: string;
  fix?: string;
}

export type Catalogue = Readonly<Record<string, CatalogueEntry>>;

let loaded: Catalogue | null = null;
let loading: Promise<Catalogue> | null = null;

/** The catalogue, fetched once. */
export function loadCatalogue(): Promise<Catalogue> {
  loading ??= import("../generated/diagnostics").then((m) => (loaded = m.DIAGNOSTICS.codes));
  return loading;
}

/** The catalogue once it is loaded (null before); asks for it on first use. */
export function useCatalogue(): Catalogue | null {
  const [catalogue, setCatalogue] = useState(loaded);
  useEffect(() => {
    if (!catalogue) void loadCatalogue().then(setCatalogue);
  }, [catalogue]);
  return catalogue;
}
