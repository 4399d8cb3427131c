// @vitest-environment jsdom
// The FBD editor in jsdom: palette, operand entry with the declare offer, node and pin menus,
// order badges from the (faked) backend, undo. Dragging and wiring run in the browser test.
import { act, fireEvent, render, screen, waitFor, within } from "@testing-library/react";
import { useState } from "react";
import { beforeAll, describe, expect, it, vi } from "vitest";
import { historyOf, type History } from "../../store/history";
import { arithmetic, bodyOf, LIBRARY, SYMBOLS } from "../fixtures";
import { nodesOf, type Block, type FbdBody, type FbdNetwork } from "../model";
import { FbdEditor, type FbdEditorProps } from "./FbdEditor";

beforeAll(() => {
  // xyflow measures nodes and the pane; jsdom has no layout, so observers report nothing.
  globalThis.ResizeObserver ??= class {
    observe() {}
    unobserve() {}
    disconnect() {}
  } as unknown as typeof ResizeObserver;
});

function setup(body: FbdBody, props: Partial<FbdEditorProps> = {}) {
  let latest: History<FbdBody> = historyOf(body);
  const orderOf = vi.fn(async (network: FbdNetwork) => ({ order: nodesOf(network).map((n) => n.id) }));
  function Host() {
    const [history, setHistory] = useState(latest);
    latest = history;
    return (
      <FbdEditor
        history={history}
        onHistoryChange={setHistory}
        library={LIBRARY}
        symbols={SYMBOLS}
        orderOf={orderOf}
        onDeclareVariable={() => undefined}
        {...props}
      />
    );
  }
  const view = render(<Host />);
  const editor = screen.getByRole("application", { name: "Function block diagram editor" });
  const node = (id: string) => view.container.querySelector(`.fbd-node[data-node="${id}"]`)!;
  return { ...view, editor, node, orderOf, current: () => latest.present };
}

describe("FBD editor", () => {
  it("shows the backend's execution order on every node", async () => {
    const t = setup(bodyOf(arithmetic()));
    await waitFor(() => expect(t.node("r").querySelector(".fbd-order")?.textContent).toBe("6"));
    expect(t.orderOf).toHaveBeenCalledTimes(1);
    expect(t.node("add").querySelector(".fbd-order")?.textContent).toBe("4");
  });

  it("adds an input from the palette, takes its operand and offers to declare it", async () => {
    const t = setup(bodyOf(arithmetic()));
    fireEvent.click(within(t.editor).getByRole("button", { name: "Input" }));
    // (xyflow keeps a node invisible until it has measured it, which jsdom never does.)
    const field = t.node("in1").querySelector<HTMLInputElement>('input[role="combobox"][aria-label="Input operand"]')!;
    fireEvent.change(field, { target: { value: "speed" } });
    fireEvent.keyDown(field, { key: "Enter" });
    expect(nodesOf(t.current().networks![0]!).at(-1)).toMatchObject({ type: "input", id: "in1", expr: "speed" });
    expect(await screen.findByRole("button", { name: "Declare speed" })).toBeTruthy();
    expect((screen.getByLabelText("Type of the new variable") as HTMLInputElement).value).toBe("BOOL");
    // Double-clicking a node's text edits it again.
    fireEvent.doubleClick(t.node("a").querySelector(".fbd-text")!);
    expect(t.node("a").querySelector<HTMLInputElement>('input[aria-label="Input operand"]')!.value).toBe("var1");
  });

  it("adds an input to ADD and negates a pin from the context menus; Ctrl+Z undoes", () => {
    const t = setup(bodyOf(arithmetic()));
    fireEvent.contextMenu(t.node("add"));
    fireEvent.click(screen.getByRole("menuitem", { name: "Add input" }));
    expect(t.node("add").querySelector('[data-pin="IN3"]')).toBeTruthy();
    fireEvent.contextMenu(t.node("add").querySelector('[data-pin="IN2"]')!);
    fireEvent.click(screen.getByRole("menuitem", { name: "Negate IN2" }));
    expect((nodesOf(t.current().networks![0]!).find((n) => n.id === "add") as Block).pins).toEqual({
      IN3: { negated: false },
      IN2: { negated: true },
    });
    expect(t.node("add").querySelector('[data-pin="IN2"] .fbd-bubble')).toBeTruthy();
    fireEvent.keyDown(t.editor, { key: "z", ctrlKey: true });
    fireEvent.keyDown(t.editor, { key: "z", ctrlKey: true });
    expect((nodesOf(t.current().networks![0]!).find((n) => n.id === "add") as Block).pins).toBeUndefined();
  });

  it("refuses to run a node before the block feeding it, with the reason (GR-06 b, GR-31)", async () => {
    const t = setup(bodyOf(arithmetic()));
    await waitFor(() => expect(t.node("sub").querySelector(".fbd-order")).toBeTruthy());
    fireEvent.contextMenu(t.node("sub"));
    fireEvent.click(screen.getByRole("menuitem", { name: /^Run earlier/ }));
    expect(screen.getByRole("alert").textContent).toContain("add feeds sub: data flow makes add run first.");
  });

  it("online (ON-06..09): shows node values, dims skipped blocks, prepares a value on double-click, writes from the menu", () => {
    const write = vi.fn();
    const prepare = vi.fn((operand: string) => operand === "flag"); // a BOOL toggles; others ask for the value
    const network = arithmetic();
    const t = setup(
      bodyOf({
        ...network,
        nodes: [...(network.nodes ?? []), { type: "input", id: "f", expr: "flag", pos: { x: 0, y: 200 } }],
      }),
      {
        readOnly: "Online",
        online: {
          probes: { a: 7, "add.OUT": null, "sub.OUT": 3, r: 3, f: true },
          operands: { VAR1: { text: "7", bool: null, forced: true, prepared: "8" } },
          pins: { sub: { "out:OUT": { text: "3", bool: null, forced: false, prepared: null } } },
        },
        onlineActions: { write, prepare, force: vi.fn(), unforce: vi.fn(), watch: vi.fn() },
      },
    );
    fireEvent.doubleClick(t.node("f").querySelector(".fbd-text")!);
    expect(prepare).toHaveBeenCalledWith("flag", undefined, undefined);
    expect(screen.queryByRole("dialog")).toBeNull();
    fireEvent.doubleClick(screen.getByTestId("value-a"));
    expect(prepare).toHaveBeenLastCalledWith("var1", undefined, undefined);
    act(() => {
      fireEvent.submit(screen.getByRole("dialog", { name: "Prepare a value for var1" }));
    }); // an empty value is not submitted
    fireEvent.change(screen.getByLabelText("Value"), { target: { value: "9" } });
    act(() => {
      fireEvent.submit(screen.getByRole("dialog", { name: "Prepare a value for var1" }));
    });
    expect(prepare).toHaveBeenLastCalledWith("var1", "9");
    expect(screen.getByTestId("value-a").textContent).toBe("7F<8>"); // forced, 8 prepared
    expect(screen.getByTestId("value-f").textContent).toBe("TRUE"); // a literal's probe
    expect(t.node("sub").querySelector('[data-pin-value="out:OUT"]')!.textContent).toBe("3");
    expect(t.node("add").classList.contains("fbd-skipped")).toBe(true);
    expect(t.node("sub").classList.contains("fbd-skipped")).toBe(false);
    expect(t.node("a").classList.contains("fbd-forced")).toBe(true);
    fireEvent.contextMenu(t.node("a"));
    fireEvent.click(screen.getByRole("menuitem", { name: "Write value of var1…" }));
    fireEvent.change(screen.getByLabelText("Value"), { target: { value: "42" } });
    act(() => {
      fireEvent.submit(screen.getByRole("dialog", { name: "Write var1" }));
    });
    expect(write).toHaveBeenCalledWith("var1", "42");
    expect(screen.queryByRole("menuitem", { name: "Delete" })).toBeNull();
  });

  it("marks a diagnostic on its node and pin, and a network's own problem in its header", () => {
    const at = {
      pou: "Main",
      network: "n1",
      file: null,
      line: null,
      column: null,
      end_line: null,
      end_column: null,
      severity: "error" as const,
    };
    const t = setup(bodyOf(arithmetic()), {
      diagnostics: [
        { ...at, element: "add", pin: "IN2", code: "ST-TYPE-MISMATCH", message: "IN2 expects ANY_NUM, got BOOL" },
        { ...at, element: null, pin: null, code: "FBD-DUPLICATE-LABEL", message: "label L1 is used twice" },
      ],
    });
    expect(t.node("add").classList.contains("fbd-error")).toBe(true);
    const pin = t.node("add").querySelector('[data-pin="IN2"]')!;
    expect(pin.classList.contains("fbd-pin-error")).toBe(true);
    expect(pin.getAttribute("title")).toBe("ST-TYPE-MISMATCH: IN2 expects ANY_NUM, got BOOL");
    expect(t.node("sub").classList.contains("fbd-error")).toBe(false);
    expect(screen.getByRole("note").textContent).toBe("FBD-DUPLICATE-LABEL: label L1 is used twice");
  });

  it("cuts a node to the system clipboard and pastes it back, as the same node", () => {
    const t = setup(bodyOf(arithmetic()));
    fireEvent.contextMenu(t.node("add")); // selects it
    const data = new Map<string, string>();
    const cb = {
      setData: (type: string, text: string) => data.set(type, text),
      getData: (type: string) => data.get(type) ?? "",
    };
    fireEvent.cut(t.editor, { clipboardData: cb });
    expect(JSON.parse(data.get("text/plain")!)).toMatchObject({
      format: "ladderlab/fbd-clip",
      nodes: [{ id: "add", call: "ADD" }],
    });
    expect(nodesOf(t.current().networks![0]!).map((n) => n.id)).toEqual(["a", "b", "c", "sub", "r"]);
    fireEvent.paste(t.editor, { clipboardData: cb });
    expect(nodesOf(t.current().networks![0]!).map((n) => n.id)).toEqual(["a", "b", "c", "sub", "r", "add"]);
    fireEvent.paste(t.editor, { clipboardData: { getData: () => "hello" } });
    expect(screen.getByRole("alert").textContent).toContain("The clipboard holds no LadderLab FBD nodes.");
  });
});
