// The project tree's menu of a POU: rename (everywhere, with a preview), duplicate, change the kind of an
// empty POU, convert FBD <-> CFC, delete (listing what refers to it). The dialogs load on first use.
import { useMemo } from "react";
import type { Pou } from "../generated/api";
import { isEmptyPou } from "./refactor";
import { TreeActions, type MenuEntry } from "../ui/TreeActions";
import { ConvertDialog, DeleteDialog, DuplicateDialog, KindDialog, RenameDialog } from "./lazyDialogs";
import { pouOperations } from "./operations";

type Action = "rename" | "duplicate" | "kind" | "convert" | "delete";

/** The "⋯" button of a POU in the tree and its menu. */
export function PouActions({ pou }: { pou: Pou }) {
  const empty = isEmptyPou(pou);
  const operations = useMemo(() => pouOperations(pou), [pou]);
  const entries: MenuEntry<Action>[] = [
    { action: "rename", label: "Rename…" },
    { action: "duplicate", label: "Duplicate…" },
    {
      action: "kind",
      label: "Change kind…",
      disabledBecause: empty ? undefined : "Only an empty POU (no variables, no body) can change its kind.",
    },
    ...(pou.language === "fbd" || pou.language === "cfc"
      ? [{ action: "convert" as const, label: pou.language === "fbd" ? "Convert to CFC…" : "Convert to FBD…" }]
      : []),
    { action: "delete", label: "Delete…" },
  ];
  return (
    <TreeActions
      item={pou.name}
      entries={entries}
      dialog={(action, close) =>
        action === "rename" ? (
          <RenameDialog current={pou.name} isPou onClose={close} />
        ) : action === "duplicate" ? (
          <DuplicateDialog name={pou.name} item={operations} onClose={close} />
        ) : action === "kind" ? (
          <KindDialog pou={pou} onClose={close} />
        ) : action === "convert" ? (
          <ConvertDialog pou={pou} onClose={close} />
        ) : (
          <DeleteDialog name={pou.name} item={operations} onClose={close} />
        )
      }
    />
  );
}
