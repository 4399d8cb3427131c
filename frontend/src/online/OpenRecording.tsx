// "Open recording" (issue 23): a recording file - what `ladderlab run --record` writes or "Download recording"
// gives - opens as a simulation of the saved project that holds only its history: the server runs the recorded
// scans with their inputs, the timeline shows the last one, and every scan can be viewed, compared and continued
// from ("Continue from here" makes it a live simulation again). The server refuses a recording of another revision
// of the project or a file that is no recording; its message shows in the toolbar.
import { useRef } from "react";
import { History } from "lucide-react";
import { workspaceStore } from "../store/project";
import { openRecording } from "./api";
import { onlineStore, useOnline } from "./store";

/** Opens `file` as a history-only simulation of the saved project `project` (going offline first, as Compile does). */
export async function openRecordingFile(project: string, file: File): Promise<void> {
  const text = await file.text();
  await onlineStore.getState().compile(project, () => openRecording(project, text, file.name));
}

export function OpenRecording() {
  const phase = useOnline((s) => s.phase);
  const input = useRef<HTMLInputElement>(null);
  return (
    <>
      <button
        type="button"
        onClick={() => input.current?.click()}
        disabled={phase === "compiling" || phase === "connecting"}
        title="Open a recording of this project (ladderlab run --record, Download recording) to go through its scans"
      >
        <History size={16} aria-hidden="true" /> Open recording
      </button>
      <input
        ref={input}
        type="file"
        accept=".json,.rec,application/json"
        hidden
        aria-label="Recording file"
        onChange={(event) => {
          const file = event.target.files?.[0];
          event.target.value = ""; // the same file can be chosen again
          const name = workspaceStore.getState().name;
          if (file && name) void openRecordingFile(name, file);
        }}
      />
    </>
  );
}
