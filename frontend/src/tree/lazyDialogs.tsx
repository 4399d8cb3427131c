// The tree's dialogs (dialogs.tsx) as components loaded when first shown: the app opens without their code
// (issue 22 item 8; tests/browser/test_lazy_loading.py). Each waits in its own Suspense, so the view that
// opens one keeps showing (and keeps its state) while the code loads.
import { lazy, Suspense, type ComponentType } from "react";

function suspended<P extends object>(Lazy: ComponentType<P>) {
  return function LazyDialog(props: P) {
    return (
      <Suspense fallback={null}>
        <Lazy {...props} />
      </Suspense>
    );
  };
}

const dialogs = () => import("./dialogs");

export const RenameDialog = suspended(lazy(() => dialogs().then((m) => ({ default: m.RenameDialog }))));
export const DeleteDialog = suspended(lazy(() => dialogs().then((m) => ({ default: m.DeleteDialog }))));
export const DuplicateDialog = suspended(lazy(() => dialogs().then((m) => ({ default: m.DuplicateDialog }))));
export const KindDialog = suspended(lazy(() => dialogs().then((m) => ({ default: m.KindDialog }))));
export const ConvertDialog = suspended(lazy(() => dialogs().then((m) => ({ default: m.ConvertDialog }))));
