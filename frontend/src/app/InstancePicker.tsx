// Next to an online view: which instance of a function block it shows, and going offline to edit.
import { useState } from "react";
import type { Pou } from "../generated/api";
import { onlineStore, useOnline } from "../online/store";

/** Which instance of a function block the online view shows (a path such as MAIN.BLINK), typed or picked from the simulation's. */
export function InstancePicker({ pou }: { pou: string }) {
  const current = useOnline((s) => s.instances[pou] ?? "");
  const choices = useOnline((s) => s.instanceChoices[pou.toUpperCase()]);
  const [text, setText] = useState(current);
  const listId = `instances-of-${pou}`;
  return (
    <form
      className="instance-picker"
      onSubmit={(e) => {
        e.preventDefault();
        onlineStore.getState().setInstance(pou, text);
      }}
    >
      <input
        aria-label={`Instance of ${pou}`}
        list={listId}
        value={text}
        onChange={(e) => setText(e.target.value)}
        placeholder={choices?.[0] ?? "MAIN.Instance"}
        spellCheck={false}
      />
      <datalist id={listId}>
        {choices?.map((path) => (
          <option key={path} value={path} />
        ))}
      </datalist>
      <button type="submit">Show</button>
    </form>
  );
}

/** Next to an online diagram's read-only notice: the FB instance shown, and going offline. */
export function OnlineActions({ pou }: { pou: Pou }) {
  return (
    <>
      {pou.kind === "function_block" ? <InstancePicker pou={pou.name} /> : null}
      <button type="button" onClick={() => void onlineStore.getState().goOffline()}>
        Go offline to edit
      </button>
    </>
  );
}
