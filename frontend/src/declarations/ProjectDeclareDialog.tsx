// The declare dialog completing from the open project's types (the IEC vocabulary's, its own and its FBs).
// Diagram editors load it on first use: the vocabulary it completes from is 30 kB the opening of an LD POU
// does not need (tests/browser/test_lazy_loading.py).
import { useDeclarableTypes } from "../store/declarableTypes";
import { DeclareDialog, type DeclareDialogProps } from "./DeclareDialog";

export default function ProjectDeclareDialog(props: Omit<DeclareDialogProps, "types">) {
  return <DeclareDialog {...props} types={useDeclarableTypes()} />;
}
