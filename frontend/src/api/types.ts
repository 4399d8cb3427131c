// REST shapes of the project, library and symbols endpoints (issue 6). They mirror the pydantic
// models in backend/ladderlab/model/api.py, with the same names, until `make schema` publishes them
// in src/generated/api.ts; then this module re-exports the generated ones and nothing else changes.
import type { Project } from "../generated/project";

export type { ProjectSummary } from "../generated/api";

export interface Diagnostic {
  severity?: "error" | "warning" | "info";
  code: string;
  message: string;
  file?: string | null;
  json_path?: string | null;
  pou?: string | null;
  network?: string | null;
  element?: string | null;
  pin?: string | null;
  line?: number | null;
  column?: number | null;
  end_line?: number | null;
  end_column?: number | null;
}

export interface ProjectDocument {
  name: string;
  revision: string;
  modified: string;
  project: Project;
}

export interface SaveResult {
  revision: string;
  modified: string;
}

export interface ConflictDetail {
  message: string;
  base_revision: string | null;
  current_revision: string;
  current_modified: string | null;
}

export interface SymbolInfo {
  name: string;
  var_class: string;
  type: string;
  initial: string | null;
  address: string | null;
  comment: string | null;
  retain: boolean;
  constant: boolean;
}

export interface SymbolTable {
  pou: string;
  symbols: SymbolInfo[];
  globals: SymbolInfo[];
  diagnostics: Diagnostic[];
}

export interface Pin {
  name: string;
  type: string;
}

export interface LibraryEntry {
  name: string;
  kind: "function" | "function_block";
  source: "standard" | "user";
  inputs: Pin[];
  outputs: Pin[];
  in_outs: Pin[];
  extensible: boolean;
  return_type: string | null;
  comment: string | null;
}
