// Inject faults into the signals between plant and program (recorded input events, from the next scan):
// stuck TRUE/FALSE, stuck at a value (numbers), open circuit, noisy (seeded, so a replay is the same).
import { useState } from "react";
import type { ClientMessage } from "../online/protocol";
import type { Live } from "./widgets";

const NUMERIC = /^(S|U)?(INT|DINT|LINT)$|^U?SINT$|^(BYTE|WORD|DWORD|LWORD|REAL|LREAL)$/;

/** The faults a signal of `type` can take (BOOL or numeric; others none). */
export function faultModes(type: string | undefined): { mode: string; label: string }[] {
  const name = (type ?? "").toUpperCase();
  if (name === "BOOL")
    return [
      { mode: "stuck_true", label: "stuck TRUE" },
      { mode: "stuck_false", label: "stuck FALSE" },
      { mode: "open", label: "open circuit" },
      { mode: "noisy", label: "noisy" },
    ];
  if (NUMERIC.test(name))
    return [
      { mode: "stuck", label: "stuck at a value" },
      { mode: "open", label: "open circuit (0)" },
      { mode: "noisy", label: "noisy" },
    ];
  return [];
}

/** A fresh seed for a noisy fault: shown, and recorded with the event. */
export const newSeed = (): number => Math.floor(Math.random() * 2 ** 31);

export function FaultDialog({
  paths,
  live,
  send,
  onClose,
}: {
  paths: readonly string[];
  live: Live;
  send(msg: ClientMessage): boolean;
  onClose(): void;
}) {
  const signals = paths.filter((p) => faultModes(live.type(p)?.name).length > 0);
  return (
    <div className="ld-dialog-backdrop" onClick={onClose}>
      <div
        className="ld-dialog hmi-dialog"
        role="dialog"
        aria-label="Inject faults"
        onClick={(e) => e.stopPropagation()}
      >
        <h2>Inject faults</h2>
        <p className="hmi-notice">
          A fault acts where plant and program meet, from the next scan on, and is recorded with its scan.
        </p>
        {signals.length ? (
          <table>
            <tbody>
              {signals.map((path) => (
                <FaultRow key={path} path={path} live={live} send={send} />
              ))}
            </tbody>
          </table>
        ) : (
          <p>No BOOL or numeric signal on this panel (values arrive once the simulation runs).</p>
        )}
        <div className="dialog-buttons">
          <button type="button" onClick={() => send({ type: "inject_clear" })}>
            Remove every fault
          </button>
          <button type="button" onClick={onClose}>
            Close
          </button>
        </div>
      </div>
    </div>
  );
}

function FaultRow({ path, live, send }: { path: string; live: Live; send(msg: ClientMessage): boolean }) {
  const modes = faultModes(live.type(path)?.name);
  const current = live.injected(path);
  const [mode, setMode] = useState(modes[0]!.mode);
  const [value, setValue] = useState("");
  const [seed, setSeed] = useState(newSeed);
  const [amount, setAmount] = useState("");
  const bool = live.type(path)?.name.toUpperCase() === "BOOL";
  const inject = () => {
    const spread = amount.trim() ? Number(amount) : null;
    send({
      type: "inject",
      path,
      mode: mode as "stuck_true",
      value: mode === "stuck" && value.trim() ? Number(value) : null,
      seed: mode === "noisy" ? seed : null,
      rate: mode === "noisy" && bool && spread !== null ? spread : null,
      amplitude: mode === "noisy" && !bool && spread !== null ? spread : null,
    });
    setSeed(newSeed());
  };
  return (
    <tr data-path={path}>
      <th scope="row">{path}</th>
      <td>{current ? <span className="hmi-notice error">{current.replace("_", " ")}</span> : "ok"}</td>
      <td>
        <select aria-label={`Fault of ${path}`} value={mode} onChange={(e) => setMode(e.target.value)}>
          {modes.map((m) => (
            <option key={m.mode} value={m.mode}>
              {m.label}
            </option>
          ))}
        </select>
        {mode === "stuck" ? (
          <input
            aria-label={`Value of ${path}`}
            value={value}
            onChange={(e) => setValue(e.target.value)}
            size={6}
            placeholder="now"
          />
        ) : null}
        {mode === "noisy" ? (
          <>
            <input
              aria-label={bool ? `Flip rate of ${path}` : `Amplitude of ${path}`}
              value={amount}
              onChange={(e) => setAmount(e.target.value)}
              size={5}
              placeholder={bool ? "0.1" : "1.0"}
            />
            <span className="hmi-notice"> seed {seed}</span>
          </>
        ) : null}
      </td>
      <td>
        <button type="button" onClick={inject}>
          Inject
        </button>
        <button type="button" disabled={!current} onClick={() => send({ type: "inject_clear", path })}>
          Remove
        </button>
      </td>
    </tr>
  );
}
