// "View as IL" (issue 26): one LD network as Instruction List, read-only - a teaching aid. The
// backend writes it (POST /api/ld/il, interchange/ld_il.py, tested to run like the network) or
// says why the network has no plain IL equivalent (an edge contact, a box ...).
import { useEffect, useState } from "react";
import { http, unwrap } from "../../api/client";
import type { LdAsIl, LdNetwork } from "../../generated/api";

export const fetchIl = (network: LdNetwork): Promise<LdAsIl> => unwrap(http.POST("/api/ld/il", { body: network }));

export function IlView({
  network,
  number,
  onClose,
  fetcher = fetchIl,
}: {
  network: LdNetwork;
  number: number;
  onClose(): void;
  fetcher?(network: LdNetwork): Promise<LdAsIl>;
}) {
  const [answer, setAnswer] = useState<LdAsIl | { error: string } | null>(null);
  useEffect(() => {
    let current = true;
    fetcher(network).then(
      (made) => current && setAnswer(made),
      (err: unknown) => current && setAnswer({ error: err instanceof Error ? err.message : String(err) }),
    );
    return () => {
      current = false;
    };
  }, [network, fetcher]);
  const title = `Network ${number} as IL`;
  return (
    <div className="ld-dialog-backdrop" onKeyDown={(e) => e.key === "Escape" && onClose()}>
      <div className="ld-dialog il-view" role="dialog" aria-label={title}>
        <h2>{title}</h2>
        {answer === null ? (
          <p>…</p>
        ) : "error" in answer ? (
          <p role="alert">The IL could not be made: {answer.error}</p>
        ) : answer.text !== null ? (
          <pre aria-label="IL text" className="il-view-text">
            {answer.text}
          </pre>
        ) : (
          <p role="note">This network has no plain IL equivalent: {answer.reason}.</p>
        )}
        <p className="il-view-hint">Read-only: the network stays LD; the IL runs the same, scan by scan.</p>
        <button type="button" autoFocus onClick={onClose}>
          Close
        </button>
      </div>
    </div>
  );
}
