// The text views of the app, loaded on first use with CodeMirror (their own chunk): an ST or IL POU's
// declarations and body, and a test file.
import { useMemo, useState } from "react";
import { DeclareDialog } from "../declarations/DeclareDialog";
import type { NewVariable } from "../store/newVariable";
import type { Pou } from "../generated/api";
import { useOnline } from "../online/store";
import { panelsStore, usePanels } from "../store/panels";
import { IL_OPERATOR_COMPLETIONS } from "../st/ilLanguage";
import { StEditor } from "../st/StEditor";
import { StOnlineBar } from "../st/StOnlineBar";
import { useStAssist } from "../st/useStAssist";
import { useStOnline } from "../st/useStOnline";
import { useTextDebug } from "../breakpointPlaces/useTextDebug";
import { useTestCheck, useTestCompletions } from "../tests/assist";
import { coverageLines, coverageOf } from "../tests/coverage";
import { testsStore, useTests } from "../tests/store";
import { useDeclarableTypes } from "../store/declarableTypes";
import { InstancePicker } from "./InstancePicker";
import { testOf, useWorkspace } from "../store/project";

/**
 * An ST or IL POU as text: its declarations above its body, each in the text editor, with the live check
 * of the working copy as underlines; online, the body shows values inline.
 */
export function StPouView({ pou }: { pou: Pou }) {
  const setStBody = useWorkspace((s) => s.setStBody);
  const setDeclarations = useWorkspace((s) => s.setDeclarations);
  const declare = useWorkspace((s) => s.declare);
  const types = useDeclarableTypes();
  // The quick fix of an unknown variable opens the declare dialog (BOOL proposed, as CODESYS's Auto Declare does).
  const [offer, setOffer] = useState<NewVariable | null>(null);
  const phase = useOnline((s) => s.phase);
  const body = typeof pou.body === "string" ? pou.body : "";
  const { diagnostics, completions: stCompletions, scope } = useStAssist(pou);
  const il = pou.language === "il";
  const completions = useMemo(
    () => (il ? { ...stCompletions, options: [...IL_OPERATOR_COMPLETIONS, ...stCompletions.options] } : stCompletions),
    [il, stCompletions],
  );
  const online = useStOnline(pou, body, scope);
  const readOnly = phase === "offline" ? null : "Online: go offline to edit.";
  const covered = useTests((s) => coverageOf(s.coverage, pou.name));
  const debug = useTextDebug(pou.name);
  return (
    <div
      className="st-pou"
      style={{
        position: "relative",
        display: "flex",
        flexDirection: "column",
        gap: "0.25rem",
        height: "100%",
        minHeight: 0,
      }}
    >
      {offer ? (
        <DeclareDialog
          key={offer.name}
          offer={offer}
          types={types}
          onDeclare={(variable) => {
            setOffer(null);
            declare(pou.name, variable);
          }}
          onCancel={() => setOffer(null)}
        />
      ) : null}
      <div style={{ flex: "0 0 35%", minHeight: "6rem", overflow: "hidden", borderBottom: "1px solid #ccc" }}>
        <StEditor
          text={pou.declarations ?? ""}
          onChange={(text) => setDeclarations(pou.name, text)}
          file={`${pou.name}/declarations`}
          diagnostics={diagnostics}
          completions={completions}
          readOnly={readOnly === null ? null : ""}
          label={`${pou.name} declarations`}
          onDeclare={readOnly === null ? (name) => setOffer({ name, type: "BOOL" }) : undefined}
        />
      </div>
      <StOnlineBar
        online={online}
        instancePicker={pou.kind === "function_block" ? <InstancePicker pou={pou.name} /> : undefined}
      />
      <div style={{ flex: "1 1 65%", minHeight: "10rem", overflow: "hidden" }}>
        <StEditor
          text={body}
          onChange={(text) => setStBody(pou.name, text)}
          file={`${pou.name}/body`}
          diagnostics={diagnostics}
          completions={completions}
          readOnly={readOnly}
          label={`${pou.name} body`}
          language={il ? "il" : "st"}
          onDeclare={readOnly === null ? (name) => setOffer({ name, type: "BOOL" }) : undefined}
          debug={debug}
          online={online.view}
          coverage={coverageLines(covered)}
        />
      </div>
      {online.overlay}
    </div>
  );
}

/** A test file in the ST editor: live diagnostics, completions, Run this file, jumps from the Tests panel. */
export function TestFileView({ path }: { path: string }) {
  const project = useWorkspace((s) => s.project);
  const test = useWorkspace((s) => testOf(s.project, path));
  const setTestText = useWorkspace((s) => s.setTestText);
  const diagnostics = useTestCheck(project, path);
  const completions = useTestCompletions(project, test?.text ?? "");
  const focus = usePanels((s) => (s.focus?.pou === path && s.focus.line != null ? s.focus : null));
  const running = useTests((s) => s.running !== null);
  if (!test || !project) return <p className="placeholder">{path} is no longer in this project.</p>;
  return (
    <div className="pou-view test-file-view">
      <div className="pou-modes">
        <button
          type="button"
          disabled={running}
          onClick={() => {
            panelsStore.getState().show("tests");
            void testsStore.getState().run(project, { file: path });
          }}
        >
          Run this file
        </button>
      </div>
      <div style={{ flex: "1 1 auto", minHeight: "10rem", overflow: "hidden", height: "100%" }}>
        <StEditor
          text={test.text ?? ""}
          onChange={(text) => setTestText(path, text)}
          file={path}
          diagnostics={diagnostics}
          completions={completions}
          readOnly={null}
          label={path}
          language="test"
          focusLine={focus ? { line: focus.line!, seq: focus.seq } : null}
        />
      </div>
    </div>
  );
}
