// The websocket monitor protocol of /api/simulations/{id}/ws (issue 6), in one place.
// Every message is a JSON object whose `type` names it. These shapes follow the server's models
// (backend/ladderlab/model/monitor.py); they give way to src/generated/monitor.ts once that is
// generated, and nothing outside src/online/ depends on them directly.
import type { Diagnostic } from "../generated/api";

/** A variable value as JSON carries it (TIME etc. arrive as numbers of ms, strings as text). */
export type Value = boolean | number | string | null;

/** Right-side power of one element in the last scan; null when the scan did not execute it. */
export type PowerState = boolean | null;

export interface ElementSubscription {
  /** The POU instance the element ids belong to, e.g. "MAIN" or "MAIN.FB1". */
  pou_instance: string;
  /** Element ids (box pins as "box.Q"); null: every element of the instance. */
  ids: string[] | null;
}

export type ClientMessage =
  | { type: "subscribe"; paths: string[]; elements: ElementSubscription[]; interval_ms: number }
  | { type: "write"; path: string; value: Value }
  | { type: "force"; path: string; value: Value }
  | { type: "unforce"; path: string }
  | { type: "unforce_all" }
  | { type: "run" }
  | { type: "stop" }
  | { type: "single_cycle" };

export interface ValuesMessage {
  type: "values";
  scan: number;
  time_ms: number;
  /** Only what changed since the previous message to this client (the first is a full snapshot). */
  changed?: Record<string, Value>;
  /** Every path forced now. */
  forced?: string[];
  /** Keyed "<pou_instance>/<element id>" (the instance as subscribed). */
  power?: Record<string, PowerState>;
}

export interface Where {
  pou?: string | null;
  instance?: string | null;
  network?: string | null;
  element?: string | null;
  line?: number | null;
}

/** `faulted`: stopped by a runtime error or a watchdog trip. */
export type SimulationState = "running" | "stopped" | "halted" | "faulted";

export interface StatusMessage {
  type: "status";
  state: SimulationState;
  at?: Where | null;
}

export interface LogMessage {
  type: "log";
  level: string;
  message: string;
  at?: Where | null;
  scan?: number | null;
}

export interface ErrorMessage {
  type: "error";
  code: string;
  message: string;
}

export type ServerMessage = ValuesMessage | StatusMessage | LogMessage | ErrorMessage;

/** `POST /api/projects/{p}/simulations` and `GET /api/simulations/{id}` (the fields the app reads). */
export interface SimulationInfo {
  id: string;
  state?: SimulationState | string;
  scan_count?: number;
  virtual_time_ms?: number;
  /** Duration of the last scan. */
  last_scan_ms?: number | null;
}

/** The 422 detail of a simulation whose project does not compile. */
export interface CompileFailure {
  message: string;
  diagnostics: Diagnostic[];
}

/** Monitoring interval the editor asks for (the server accepts 20-1000 ms). */
export const DEFAULT_INTERVAL_MS = 100;

const isRecord = (v: unknown): v is Record<string, unknown> => typeof v === "object" && v !== null && !Array.isArray(v);

/**
 * Reads one websocket frame; null for anything that is not a known server message, so a newer
 * server's extra message types are ignored rather than breaking the monitor.
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
      return typeof data.scan === "number" ? (data as unknown as ValuesMessage) : null;
    case "status":
      return typeof data.state === "string" ? (data as unknown as StatusMessage) : null;
    case "log":
      return typeof data.message === "string" ? (data as unknown as LogMessage) : null;
    case "error":
      return typeof data.message === "string" ? (data as unknown as ErrorMessage) : null;
    default:
      return null;
  }
}
