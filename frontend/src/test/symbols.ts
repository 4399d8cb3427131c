// A declared variable as the server's symbol table lists it (SymbolInfo), for tests that need a scope:
// only the name, type and class vary; the rest are the defaults of a plain declaration.
import type { SymbolInfo } from "../generated/api";

export const symbol = (name: string, type: string, var_class = "VAR"): SymbolInfo => ({
  name,
  type,
  var_class,
  initial: null,
  address: null,
  comment: null,
  retain: false,
  constant: false,
});
