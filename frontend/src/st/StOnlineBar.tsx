// The ST body's online controls: the inline-values toggle and, for a function block, which
// instance to show (the app's instance picker).
import type { ReactNode } from "react";
import type { StOnline } from "./useStOnline";

export function StOnlineBar({ online, instancePicker }: { online: StOnline; instancePicker?: ReactNode }) {
  if (!online.live) return null;
  return (
    <div
      className="st-online-bar"
      style={{ display: "flex", gap: "0.75rem", alignItems: "center", padding: "0.15rem 0.25rem" }}
    >
      <label>
        <input type="checkbox" checked={online.showValues} onChange={(e) => online.setShowValues(e.target.checked)} />{" "}
        Show values inline
      </label>
      {online.instance ? <span className="st-online-instance">Instance {online.instance}</span> : null}
      {online.instance && online.callShown ? <span>The halted call&apos;s own variables: read only.</span> : null}
      {online.instance ? null : online.view ? (
        <span>The halted call&apos;s values.</span>
      ) : (
        <span>No instance shown.</span>
      )}
      {instancePicker}
    </div>
  );
}
