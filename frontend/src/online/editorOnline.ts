// What every editor needs online (LD, FBD, SFC, ST): the instance a POU's view shows, why a diagram is
// read-only online, the library lookup, and the diagram's operand commands (prepare, write, force,
// watch) mapped onto simulation paths.
import { useEffect, useMemo } from "react";
import type { LibraryEntry, SymbolInfo } from "../generated/api";
import type { Pou } from "../generated/api";
import type { LdOnlineActions } from "./operandCommands";
import { operandPath } from "./monitor";
import { operandCommands } from "./operandCommands";
import { partElements } from "./parts";
import type { ElementSubscription } from "./protocol";
import { onlineStore, useOnline } from "./store";

/**
 * The instance whose values a POU's online view shows: a program is its own instance; a function
 * block shows the instance the user chose (its path, e.g. MAIN.BLINK), else its only instance in
 * the simulation (`choices`, by upper-case POU name); functions have none.
 */
export function instanceOf(
  pou: Pick<Pou, "kind" | "name">,
  chosen: Readonly<Record<string, string>> = {},
  choices: Readonly<Record<string, readonly string[]>> = {},
): string | null {
  if (pou.kind === "program" || pou.kind === "plant") return pou.name.toUpperCase(); // a plant: a program too
  if (pou.kind !== "function_block") return null;
  const only = choices[pou.name.toUpperCase()];
  return chosen[pou.name] || (only?.length === 1 ? only[0]! : null);
}

/** `instanceOf` with the online store's choices, for the LD, FBD and ST online hooks. */
export function useShownInstance(pou: Pick<Pou, "kind" | "name">): string | null {
  const chosen = useOnline((s) => s.instances);
  const choices = useOnline((s) => s.instanceChoices);
  return instanceOf(pou, chosen, choices);
}

export const GO_OFFLINE_TO_EDIT = "Online: the diagram shows the running simulation. Go offline to edit.";

/** A library entry by call name in any case, the same function while the library is the same. */
export function useLibraryLookup(library: readonly LibraryEntry[]): (call: string) => LibraryEntry | undefined {
  return useMemo(() => {
    const byName = new Map(library.map((e) => [e.name.toUpperCase(), e]));
    return (call: string) => byName.get(call.toUpperCase());
  }, [library]);
}

/** The online commands on operand texts of a diagram showing `instance` (LD and FBD alike). */
export function operandActions(instance: string, symbols: readonly SymbolInfo[]): LdOnlineActions {
  return operandCommands(
    (operand) => operandPath(operand, instance, symbols),
    (operand) => symbols.find((s) => s.name.toUpperCase() === operand.trim().toUpperCase())?.type,
  );
}

/** Why a diagram is read-only in online mode (null offline). */
export function onlineReadOnly(pou: Pick<Pou, "kind" | "name">, live: boolean, instance: string | null): string | null {
  return !live
    ? null
    : instance
      ? GO_OFFLINE_TO_EDIT
      : pou.kind === "function_block"
        ? `Online: name the instance of ${pou.name} to show (e.g. MAIN.${pou.name.toUpperCase()}1). Go offline to edit.`
        : `Online: a function has no instance to show. Go offline to edit.`;
}

/**
 * Subscribes a diagram's bound variable paths and elements while online (`part`: the body is an SFC action or
 * transition of the POU, online/parts.ts), and ends the subscription when the editor goes.
 */
export function useDiagramSubscription(
  key: string,
  live: boolean,
  binding: { paths: string[]; elements: readonly ElementSubscription[] } | null,
  part?: string,
): void {
  useEffect(() => {
    onlineStore
      .getState()
      .subscribe(
        key,
        live && binding ? { paths: binding.paths, elements: partElements(binding.elements, part) } : null,
      );
  }, [key, live, binding, part]);
  useEffect(() => () => onlineStore.getState().subscribe(key, null), [key]);
}
