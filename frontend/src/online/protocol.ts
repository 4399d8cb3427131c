// The websocket monitor protocol of /api/simulations/{id}/ws, from the generated types
// (src/generated/monitor.ts, from backend/ladderlab/model/monitor.py). Every message is a JSON
// object whose `type` names it; this module names the parts the app uses and reads frames.
import type { At, Error as ErrorMessage, Log, MonitorProtocol, Status, TraceData, Values } from "../generated/monitor";

export type { At, ElementSubscription } from "../generated/monitor";
export type { ErrorMessage };

export type ClientMessage = MonitorProtocol["client"];
/** The server messages the app handles (trace chunks go to the trace panel, src/trace/). */
export type ServerMessage = Values | Status | Log | ErrorMessage | TraceData;
export type TraceDataMessage = TraceData;
export type ValuesMessage = Values;
export type SimulationState = Status["state"];

/** A variable value as JSON carries it (TIME etc. arrive as numbers of ms, strings as text). */
export type Value = Values["changed"][string];
/** A value the client writes or forces: a JSON scalar or IEC literal text ('T#1s', '16#FF'). */
export type WriteValue = Extract<ClientMessage, { type: "write" }>["value"];
/** Power of one element in the last scan (a box pin's value for pins); null when the scan skipped it. */
export type PowerState = Values["power"][string];

/** Monitoring interval the editor asks for (the server accepts 20-1000 ms). */
export const DEFAULT_INTERVAL_MS = 100;

const isRecord = (v: unknown): v is Record<string, unknown> => typeof v === "object" && v !== null && !Array.isArray(v);

/**
 * Reads one websocket frame; null for anything that is not a server message the app handles, so
 * a newer server's extra message types are ignored rather than breaking the monitor.
 */
export function parseServerMessage(text: string): ServerMessage | null {
  let data: unknown;
  try {
    data = JSON.parse(text);
  } catch {
    return null;
  }
  if (!isRecord(data)) return null;
  switch (data.type) {
    case "values":
      return typeof data.scan === "number" && typeof data.time_ms === "number" ? (data as unknown as Values) : null;
    case "status":
      return typeof data.state === "string" ? (data as unknown as Status) : null;
    case "log":
      return typeof data.message === "string" ? (data as unknown as Log) : null;
    case "error":
      return typeof data.message === "string" ? (data as unknown as ErrorMessage) : null;
    case "trace_data":
      return typeof data.id === "number" && Array.isArray(data.scans) && isRecord(data.values)
        ? (data as unknown as TraceData)
        : null;
    default:
      return null;
  }
}

export type Where = At;
