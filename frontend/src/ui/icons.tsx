// The toolbar icons (issue 22 item 7): lucide-react for the generic actions, and the IEC 61131-3 graphic
// symbols (contacts, coil, FBD connections) drawn here in lucide's style (24-unit box, 2-unit stroke,
// currentColor), since no icon library has them.
import {
  ArrowDown,
  Columns2,
  GitFork,
  Link,
  SquarePlus,
  ArrowUp,
  ClipboardPaste,
  Copy,
  CopyPlus,
  CornerDownRight,
  CornerUpLeft,
  Equal,
  Keyboard,
  LayoutGrid,
  ListEnd,
  Maximize,
  ListOrdered,
  ListPlus,
  ListStart,
  MessageSquare,
  Plus,
  Repeat,
  Scissors,
  Split,
  SquareFunction,
  StickyNote,
  Tag,
  ToggleRight,
  Trash2,
  Undo2,
  Redo2,
  ZoomIn,
  ZoomOut,
  type LucideIcon,
  type LucideProps,
} from "lucide-react";

/** An icon as the toolbars draw it: a lucide icon or one of the symbols below. */
export type Icon = LucideIcon | ((props: LucideProps) => React.JSX.Element);

function Symbol({ children, size = 24, ...props }: LucideProps & { children: React.ReactNode }) {
  return (
    <svg
      xmlns="http://www.w3.org/2000/svg"
      width={size}
      height={size}
      viewBox="0 0 24 24"
      fill="none"
      stroke="currentColor"
      strokeWidth={2}
      strokeLinecap="round"
      strokeLinejoin="round"
      {...props}
    >
      {children}
    </svg>
  );
}

/** Normally open contact: --| |-- */
export const ContactIcon = (props: LucideProps) => (
  <Symbol {...props}>
    <path d="M2 12h6M16 12h6M8 5v14M16 5v14" />
  </Symbol>
);

/** Normally closed contact: --|/|-- */
export const ContactNcIcon = (props: LucideProps) => (
  <Symbol {...props}>
    <path d="M2 12h6M16 12h6M8 5v14M16 5v14M17 6 7 18" />
  </Symbol>
);

/** Coil: --( )-- */
export const CoilIcon = (props: LucideProps) => (
  <Symbol {...props}>
    <path d="M2 12h5M17 12h5M9 5a9 9 0 0 0 0 14M15 5a9 9 0 0 1 0 14" />
  </Symbol>
);

/** FBD input variable: a name feeding a wire to the right. */
export const FbdInputIcon = (props: LucideProps) => (
  <Symbol {...props}>
    <rect x="2" y="8" width="11" height="8" rx="1" />
    <path d="M13 12h9" />
  </Symbol>
);

/** FBD output variable: a wire ending in a name. */
export const FbdOutputIcon = (props: LucideProps) => (
  <Symbol {...props}>
    <path d="M2 12h9" />
    <rect x="11" y="8" width="11" height="8" rx="1" />
  </Symbol>
);

/** FBD connector and continuation: the named ends of a wire that jumps across the network. */
export const ConnectorIcon = (props: LucideProps) => (
  <Symbol {...props}>
    <path d="M2 12h7M9 7h10l3 5-3 5H9z" />
  </Symbol>
);
export const ContinuationIcon = (props: LucideProps) => (
  <Symbol {...props}>
    <path d="M22 12h-7M15 7H5l-3 5 3 5h10z" />
  </Symbol>
);

/** The icon of each editing command, by the command's id in the LD, FBD and SFC editors. */
export const COMMAND_ICONS: Readonly<Record<string, Icon>> = {
  contact: ContactIcon,
  "contact-nc": ContactNcIcon,
  coil: CoilIcon,
  compare: Equal,
  box: SquareFunction,
  block: SquareFunction,
  parallel: Split,
  jump: CornerDownRight,
  return: CornerUpLeft,
  label: Tag,
  input: FbdInputIcon,
  output: FbdOutputIcon,
  connector: ConnectorIcon,
  continuation: ContinuationIcon,
  comment: StickyNote,
  "add-input": Plus,
  "run-earlier": ListStart,
  "run-later": ListEnd,
  arrange: LayoutGrid,
  "order-by-flow": ListOrdered,
  "cycle-mode": Repeat,
  "toggle-en": ToggleRight,
  delete: Trash2,
  "network-add": ListPlus,
  "network-duplicate": CopyPlus,
  "network-up": ArrowUp,
  "network-down": ArrowDown,
  "network-label": Tag,
  "network-comment": MessageSquare,
  copy: Copy,
  cut: Scissors,
  paste: ClipboardPaste,
  undo: Undo2,
  redo: Redo2,
  "zoom-in": ZoomIn,
  "zoom-out": ZoomOut,
  "zoom-fit": Maximize,
  shortcuts: Keyboard,
  "insert-step": SquarePlus,
  alternative: GitFork,
  "sfc-parallel": Columns2,
  associate: Link,
};
