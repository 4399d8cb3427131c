// An FBD or CFC POU in the workspace: the FBD editor with the project's library and symbols, the
// check's diagnostics, online mode, the POU's breakpoints (debug/store.ts) and the tests' coverage tint.
import { useCallback, useMemo, type ReactNode } from "react";
import type { FbdBody, Pou } from "../generated/api";
import type { History } from "../store/history";
import { debugStore, useDebug } from "../debug/store";
import { haltedAt } from "../online/monitor";
import { useOnline } from "../online/store";
import { useWorkspace } from "../store/project";
import { useDiagramPou } from "../ld/useDiagramPou";
import { FbdEditor, type FbdDebug } from "./editor/FbdEditor";
import { nodeOfProbe } from "./online";
import { useFbdOnline } from "./useFbdOnline";
import { coverageMarks, coverageOf } from "../tests/coverage";
import { useTests } from "../tests/store";

export function FbdPouView({
  pou,
  history,
  onlineActions,
}: {
  pou: Pou;
  history: History<FbdBody>;
  onlineActions: ReactNode;
}) {
  const name = pou.name;
  const setHistory = useWorkspace((s) => s.setFbdHistory);
  const { library, symbols, symbolsLoaded, diagnostics, members, focus, declare } = useDiagramPou(name);
  const byName = useMemo(() => new Map(library.map((e) => [e.name.toUpperCase(), e])), [library]);
  const lookup = useCallback((call: string) => byName.get(call.toUpperCase()), [byName]);
  const body = history.present;
  const live = useFbdOnline(pou, body, lookup, symbolsLoaded ? symbols : null);

  const breakpoints = useDebug((s) => s.breakpoints);
  const at = useOnline((s) => haltedAt(s.monitor));
  const upper = name.toUpperCase();
  const covered = useTests((s) => coverageOf(s.coverage, name));
  const coverage = useMemo(() => coverageMarks(covered), [covered]);
  const debug = useMemo((): FbdDebug => {
    const mine = breakpoints.filter((b) => b.pou.toUpperCase() === upper);
    return {
      networks: new Set(mine.flatMap((b) => ("network" in b ? [b.network] : []))),
      elements: new Set(mine.flatMap((b) => ("element" in b ? [b.element] : []))),
      halted:
        at && at.pou.toUpperCase() === upper
          ? { network: at.network, element: at.element ? nodeOfProbe(body, at.element) : null }
          : null,
      toggle: (bp) => debugStore.getState().toggle({ pou: name, ...bp }),
      coverage,
    };
  }, [breakpoints, at, upper, name, body, coverage]);

  return (
    <FbdEditor
      key={name}
      history={history}
      onHistoryChange={(h) => setHistory(name, h)}
      library={library}
      symbols={symbols}
      members={members}
      diagnostics={diagnostics}
      online={live.online}
      readOnly={live.readOnly}
      readOnlyActions={live.readOnly ? onlineActions : undefined}
      onlineActions={live.actions}
      onDeclareVariable={declare}
      debug={debug}
      onVisibleChange={live.onVisibleChange}
      onFeedbackChange={live.onFeedbackChange}
      focus={focus}
      chart={pou.language === "cfc"}
    />
  );
}
