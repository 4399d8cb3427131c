// @vitest-environment jsdom
import { act, fireEvent, render, screen, within } from "@testing-library/react";
import { useState } from "react";
import { describe, expect, it, vi } from "vitest";
import { bodyOf, c, entry, LIBRARY, motorMain, net, q } from "../fixtures";
import { historyOf, type History } from "../../store/history";
import { locate, networksOf, type LdBody, type LdElement } from "../model";
import { LdEditor, type LdEditorProps } from "./LdEditor";
import { plainSymbol } from "../../store/project";

const sym = (name: string, type = "BOOL") => plainSymbol(name, type);
const SYMBOLS = [sym("Start"), sym("Stop"), sym("Motor"), sym("MotorRunning"), sym("Level", "INT")];

/** Renders the editor with its history in state, like a tab of the app; `current()` is the live body. */
function setup(body: LdBody, props: Partial<LdEditorProps> = {}) {
  let latest: History<LdBody> = historyOf(body);
  function Host() {
    const [history, setHistory] = useState(latest);
    latest = history;
    return <LdEditor history={history} onHistoryChange={setHistory} library={LIBRARY} symbols={SYMBOLS} {...props} />;
  }
  const view = render(<Host />);
  const editor = screen.getByRole("application", { name: "Ladder diagram editor" });
  const key = (k: string, init: Partial<KeyboardEventInit> = {}) => fireEvent.keyDown(editor, { key: k, ...init });
  const hit = (id: string) => {
    const found = view.container.querySelector(`[data-id="${id}"] .ld-hit`);
    if (!found) throw new Error(`element ${id} is not drawn`);
    return found;
  };
  const selected = () =>
    [...view.container.querySelectorAll(".ld-element.ld-selected")].map((e) => e.getAttribute("data-id"));
  return { ...view, editor, key, hit, selected, current: () => latest.present, history: () => latest };
}
const show = (e: LdElement | undefined) =>
  e?.type === "contact" ? `${e.var}:${e.mode}` : e?.type === "coil" ? `(${e.var}):${e.mode}` : e?.type;
const rung = (body: LdBody, n = 0) => networksOf(body)[n]!.elements!.map(show);

describe("selection and keyboard navigation", () => {
  it("selects with the mouse, extends with shift-click and moves with the arrow keys", () => {
    const t = setup(motorMain);
    fireEvent.mouseDown(t.hit("stop"));
    expect(t.selected()).toEqual(["stop"]);
    t.key("ArrowLeft");
    expect(t.selected()).toEqual(["start"]);
    t.key("ArrowDown");
    expect(t.selected()).toEqual(["seal"]);
    fireEvent.mouseDown(t.hit("motor_on"));
    fireEvent.mouseDown(t.hit("running"), { shiftKey: true });
    expect(t.selected()).toEqual(["motor_on", "ton", "running"]);
    t.key("Escape");
    expect(t.selected()).toEqual([]);
  });

  it("extends the selection with shift+arrow and wraps it in a parallel branch with P", () => {
    const t = setup(bodyOf(net("n1", c("a"), c("b"), q("m"))));
    fireEvent.mouseDown(t.hit("a"));
    t.key("ArrowRight", { shiftKey: true });
    expect(t.selected()).toEqual(["a", "b"]);
    t.key("p");
    const [parallel] = networksOf(t.current())[0]!.elements!;
    expect(parallel?.type === "parallel" && parallel.branches.map((b) => b.map(show))).toEqual([
      ["A:no", "B:no"],
      [":no"],
    ]);
  });
});

describe("editing by keyboard", () => {
  it("inserts a contact after the selection and opens its operand with autocomplete", () => {
    const t = setup(bodyOf(net("n1", c("a"), q("m"))));
    fireEvent.mouseDown(t.hit("a"));
    t.key("c");
    const input = screen.getByRole("combobox", { name: "Variable" });
    fireEvent.change(input, { target: { value: "mo" } });
    const options = screen.getAllByRole("option").map((o) => o.textContent);
    expect(options).toEqual(["Motor BOOL", "MotorRunning BOOL"]);
    // the first suggestion is highlighted as typed (Enter would take Motor); one ArrowDown moves on
    expect(screen.getByRole("option", { selected: true }).textContent).toBe("Motor BOOL");
    fireEvent.keyDown(input, { key: "ArrowDown" });
    fireEvent.keyDown(input, { key: "Enter" });
    expect(rung(t.current())).toEqual(["A:no", "MotorRunning:no", "(M):normal"]);
    expect(screen.queryByRole("combobox")).toBeNull();
    expect(screen.queryByText(/is not declared/)).toBeNull();
  });

  it("offers to declare an unknown name with a guessed type", async () => {
    const onDeclareVariable = vi.fn();
    const t = setup(bodyOf(net("n1", c("a"), q("m"))), { onDeclareVariable });
    fireEvent.mouseDown(t.hit("m"));
    t.key("Enter");
    const input = screen.getByRole("combobox", { name: "Variable" });
    fireEvent.change(input, { target: { value: "Pump" } });
    fireEvent.keyDown(input, { key: "Enter" });
    expect((await screen.findByRole("dialog", { name: "Declare variable Pump" })).textContent).toContain(
      "Pump is not declared.",
    );
    expect((screen.getByRole("combobox", { name: "Type of the new variable" }) as HTMLInputElement).value).toBe("BOOL");
    fireEvent.click(screen.getByRole("button", { name: "Declare Pump" }));
    expect(onDeclareVariable).toHaveBeenCalledWith({
      name: "Pump",
      type: "BOOL",
      varClass: "VAR",
      initial: "",
      comment: "",
    });
  });

  it("guesses the pin type for a box input and does not offer literals", async () => {
    const onDeclareVariable = vi.fn();
    const t = setup(motorMain, { onDeclareVariable });
    fireEvent.click(t.container.querySelector('[data-id="ton"] [data-field="input:PT"] text')!);
    const input = screen.getByRole("combobox", { name: "Pin PT" });
    fireEvent.change(input, { target: { value: "Delay" } });
    fireEvent.keyDown(input, { key: "Enter" });
    expect(
      ((await screen.findByRole("combobox", { name: "Type of the new variable" })) as HTMLInputElement).value,
    ).toBe("TIME");
    fireEvent.click(t.container.querySelector('[data-id="ton"] [data-field="input:PT"] text')!);
    const again = screen.getByRole("combobox", { name: "Pin PT" });
    fireEvent.change(again, { target: { value: "T#3s" } });
    fireEvent.keyDown(again, { key: "Enter" });
    expect(screen.queryByText(/is not declared/)).toBeNull();
    const ton = locate(t.current(), "ton")!.element;
    expect(ton.type === "box" && ton.inputs).toEqual({ PT: "T#3s" });
  });

  it("cancels an operand edit with Escape", () => {
    const t = setup(bodyOf(net("n1", c("a"))));
    fireEvent.mouseDown(t.hit("a"));
    t.key("F2");
    const input = screen.getByRole("combobox", { name: "Variable" });
    fireEvent.change(input, { target: { value: "Changed" } });
    fireEvent.keyDown(input, { key: "Escape" });
    expect(rung(t.current())).toEqual(["A:no"]);
    expect(t.history().past).toHaveLength(0);
  });

  it("changes modes, toggles EN and deletes by keyboard", () => {
    const t = setup(motorMain);
    fireEvent.mouseDown(t.hit("stop"));
    t.key("3");
    expect(show(locate(t.current(), "stop")!.element)).toBe("Stop:p");
    t.key(" ");
    expect(show(locate(t.current(), "stop")!.element)).toBe("Stop:n");
    fireEvent.mouseDown(t.hit("motor"));
    t.key("4");
    expect(show(locate(t.current(), "motor")!.element)).toBe("(Motor):reset");
    fireEvent.mouseDown(t.hit("ton"));
    t.key("e");
    const ton = locate(t.current(), "ton")!.element;
    expect(ton.type === "box" && ton.en).toBe(true);
    t.key("Delete");
    expect(rung(t.current(), 1)).toEqual(["Motor:no", "(MotorRunning):normal"]);
    expect(t.selected()).toEqual(["running"]);
  });

  it("undoes and redoes every edit with Ctrl+Z / Ctrl+Y and the toolbar", () => {
    const t = setup(bodyOf(net("n1", c("a"), q("m"))));
    fireEvent.mouseDown(t.hit("a"));
    t.key("Delete");
    t.key("Enter", { ctrlKey: true });
    expect(networksOf(t.current())).toHaveLength(2);
    t.key("z", { ctrlKey: true });
    expect(networksOf(t.current())).toHaveLength(1);
    t.key("z", { ctrlKey: true });
    expect(rung(t.current())).toEqual(["A:no", "(M):normal"]);
    expect((screen.getByRole("button", { name: "Undo" }) as HTMLButtonElement).disabled).toBe(true);
    t.key("y", { ctrlKey: true });
    expect(rung(t.current())).toEqual(["(M):normal"]);
    fireEvent.click(screen.getByRole("button", { name: "Redo" }));
    expect(networksOf(t.current())).toHaveLength(2);
  });

  it("shows why an edit was refused", () => {
    const t = setup(bodyOf(net("n1", c("a"), { type: "return", id: "r" })));
    fireEvent.mouseDown(t.hit("r"));
    t.key("j");
    expect(screen.getByRole("alert").textContent).toContain("return must be the last element of its branch");
  });
});

describe("networks", () => {
  it("adds, labels, moves, duplicates and deletes networks", () => {
    const t = setup(bodyOf(net("n1", c("a")), net("n2", c("b"))));
    fireEvent.mouseDown(t.container.querySelector('[data-network="n1"] .ld-header')!);
    t.key("l");
    const label = screen.getByRole("combobox", { name: "Network label" });
    fireEvent.change(label, { target: { value: "Start" } });
    fireEvent.keyDown(label, { key: "Enter" });
    expect(networksOf(t.current())[0]!.label).toBe("Start");
    t.key("ArrowDown", { altKey: true });
    expect(networksOf(t.current()).map((n) => n.id)).toEqual(["n2", "n1"]);
    t.key("d", { ctrlKey: true });
    expect(networksOf(t.current()).map((n) => n.id)).toEqual(["n2", "n1", "n3"]);
    expect(networksOf(t.current())[2]!.label).toBeNull();
    t.key("Delete");
    expect(networksOf(t.current()).map((n) => n.id)).toEqual(["n2", "n1"]);
  });

  it("starts an empty POU with a network on the first contact", () => {
    const t = setup(bodyOf());
    expect(screen.getByText(/no networks yet/)).toBeTruthy();
    t.key("c");
    expect(networksOf(t.current())).toHaveLength(1);
    expect(rung(t.current())).toEqual([":no"]);
  });
});

describe("box picker", () => {
  it("searches the library, inserts the block with an instance and offers to declare it", async () => {
    const onDeclareVariable = vi.fn();
    const t = setup(bodyOf(net("n1", c("a"), q("m"))), { onDeclareVariable });
    fireEvent.mouseDown(t.hit("a"));
    t.key("b");
    const dialog = screen.getByRole("dialog", { name: "Insert box" });
    const search = within(dialog).getByRole("textbox", { name: "Search functions and function blocks" });
    fireEvent.change(search, { target: { value: "counter" } });
    expect(
      within(dialog)
        .getAllByRole("option")
        .map((o) => o.querySelector(".ld-entry-name")?.textContent),
    ).toEqual(["CTU"]);
    fireEvent.change(search, { target: { value: "t" } });
    expect(
      within(dialog)
        .getAllByRole("option")
        .map((o) => o.querySelector(".ld-entry-name")?.textContent),
    ).toEqual(["TON", "CTU", "GT"]);
    fireEvent.keyDown(search, { key: "Enter" });
    const [, box] = networksOf(t.current())[0]!.elements!;
    expect(box).toMatchObject({ type: "box", call: "TON", instance: "TON_1", en: false });
    fireEvent.click(await screen.findByRole("button", { name: "Declare TON_1" }));
    expect(onDeclareVariable).toHaveBeenCalledWith({
      name: "TON_1",
      type: "TON",
      varClass: "VAR",
      initial: "",
      comment: "",
    });
  });

  it("offers a program's method as Prog.M and inserts its box without an instance (issue 25)", () => {
    const add = entry("Tally.Add", "function", [["k", "INT"]], [["twice", "INT"]], {
      source: "user",
      return_type: "INT",
    });
    const t = setup(bodyOf(net("n1", c("a"), q("m"))), { library: [...LIBRARY, add] });
    fireEvent.mouseDown(t.hit("a"));
    t.key("b");
    const dialog = screen.getByRole("dialog", { name: "Insert box" });
    fireEvent.change(within(dialog).getByRole("textbox"), { target: { value: "tally" } });
    const [option] = within(dialog).getAllByRole("option");
    expect(
      ["name", "signature", "kind"].map((part) => option!.querySelector(`.ld-entry-${part}`)?.textContent),
    ).toEqual(["Tally.Add", "(k) : INT", "METHOD · user"]);
    fireEvent.keyDown(within(dialog).getByRole("textbox"), { key: "Enter" });
    expect(networksOf(t.current())[0]!.elements![1]).toMatchObject({
      type: "box",
      call: "Tally.Add",
      instance: null,
      en: true, // no BOOL input to carry the rung's power (GR-27)
    });
  });

  it("offers an FB instance's method as inst.M and draws the method's pins on its box (issue 25)", () => {
    const step = entry("Step", "function", [["k", "INT"]], [["done", "BOOL"]], { source: "user", return_type: "INT" });
    const counter = entry("Counter", "function_block", [], [], { source: "user", methods: [step] });
    const t = setup(bodyOf(net("n1", c("a"), q("m"))), {
      library: [...LIBRARY, counter],
      symbols: [...SYMBOLS, sym("c1", "Counter")],
    });
    fireEvent.mouseDown(t.hit("a"));
    t.key("b");
    const dialog = screen.getByRole("dialog", { name: "Insert box" });
    fireEvent.change(within(dialog).getByRole("textbox"), { target: { value: "c1." } });
    const [option] = within(dialog).getAllByRole("option");
    expect(
      ["name", "signature", "kind"].map((part) => option!.querySelector(`.ld-entry-${part}`)?.textContent),
    ).toEqual(["c1.Step", "(k) : INT", "METHOD · user"]);
    fireEvent.keyDown(within(dialog).getByRole("textbox"), { key: "Enter" });
    const box = networksOf(t.current())[0]!.elements![1]!;
    expect(box).toMatchObject({ type: "box", call: "c1.Step", instance: null });
    const drawn = t.container.querySelector(`[data-id="${box.id}"]`)!.textContent;
    expect(drawn).toContain("k");
    expect(drawn).toContain("done");
  });

  it("turns EN/ENO on for a block without BOOL inputs (GR-27)", () => {
    const t = setup(bodyOf(net("n1", c("a"))));
    fireEvent.mouseDown(t.hit("a"));
    t.key("b");
    const dialog = screen.getByRole("dialog", { name: "Insert box" });
    fireEvent.change(within(dialog).getByRole("textbox"), { target: { value: "ADD" } });
    expect((within(dialog).getByRole("checkbox", { name: "EN/ENO" }) as HTMLInputElement).checked).toBe(true);
    fireEvent.mouseDown(within(dialog).getByRole("option"));
    expect(networksOf(t.current())[0]!.elements![1]).toMatchObject({
      type: "box",
      call: "ADD",
      instance: null,
      en: true,
    });
  });
});

describe("context menu", () => {
  it("offers the commands for the clicked element and runs them", () => {
    const t = setup(motorMain);
    fireEvent.contextMenu(t.hit("stop"));
    const menu = screen.getByRole("menu");
    const items = within(menu)
      .getAllByRole("menuitem")
      .map((b) => b.querySelector("span")?.textContent);
    expect(items).toEqual(
      expect.arrayContaining([
        "Contact",
        "Coil",
        "Parallel branch",
        "Normally open",
        "Falling edge (N)",
        "Delete",
        "Copy",
        "New network below",
      ]),
    );
    expect(items).not.toContain("EN/ENO");
    expect(items).not.toContain("Set coil (S)");
    fireEvent.click(within(menu).getByRole("menuitem", { name: /Normally open/ }));
    expect(show(locate(t.current(), "stop")!.element)).toBe("Stop:no");
    expect(screen.queryByRole("menu")).toBeNull();
  });
});

describe("drag to move", () => {
  it("drops a dragged contact on a wire elsewhere in the rung", () => {
    const t = setup(bodyOf(net("n1", c("a"), c("b"), c("d"), q("m"))));
    fireEvent.mouseDown(t.hit("a"), { clientX: 10, clientY: 10 });
    fireEvent.mouseMove(window, { clientX: 60, clientY: 12 });
    const slots = t.container.querySelectorAll(".ld-slot.ld-drop");
    expect(slots).toHaveLength(5);
    fireEvent.mouseUp(slots[3]!);
    expect(rung(t.current())).toEqual(["B:no", "D:no", "A:no", "(M):normal"]);
    expect(t.container.querySelectorAll(".ld-slot.ld-drop")).toHaveLength(0);
  });

  it("does not move on a plain click", () => {
    const t = setup(bodyOf(net("n1", c("a"), c("b"))));
    fireEvent.mouseDown(t.hit("a"), { clientX: 10, clientY: 10 });
    fireEvent.mouseUp(t.container.querySelectorAll(".ld-slot")[2]!);
    expect(rung(t.current())).toEqual(["A:no", "B:no"]);
  });
});

describe("copy and paste", () => {
  const clipboard = () => {
    const data = new Map<string, string>();
    return {
      setData: (type: string, value: string) => data.set(type, value),
      getData: (type: string) => data.get(type) ?? "",
      data,
    };
  };

  it("copies elements as JSON and pastes them into another editor (another tab)", () => {
    const source = setup(motorMain);
    fireEvent.mouseDown(source.hit("start_or_motor"));
    const cb = clipboard();
    fireEvent.copy(source.editor, { clipboardData: cb });
    expect(JSON.parse(cb.data.get("text/plain")!)).toMatchObject({ format: "ladderlab/ld-clip", kind: "elements" });
    source.unmount();

    const target = setup(bodyOf(net("n1", c("a"), q("m"))));
    fireEvent.mouseDown(target.hit("a"));
    fireEvent.paste(target.editor, { clipboardData: cb });
    expect(rung(target.current())).toEqual(["A:no", "parallel", "(M):normal"]);
    expect(target.selected()).toEqual(["start_or_motor"]);
  });

  it("cuts a network and pastes it after the selected one", () => {
    const t = setup(bodyOf(net("n1", c("a")), net("n2", c("b")), net("n3", c("d"))));
    fireEvent.mouseDown(t.container.querySelector('[data-network="n1"] .ld-header')!);
    const cb = clipboard();
    fireEvent.cut(t.editor, { clipboardData: cb });
    expect(networksOf(t.current()).map((n) => n.id)).toEqual(["n2", "n3"]);
    fireEvent.mouseDown(t.container.querySelector('[data-network="n3"] .ld-header')!);
    fireEvent.paste(t.editor, { clipboardData: cb });
    expect(networksOf(t.current()).map((n) => n.id)).toEqual(["n2", "n3", "n1"]);
  });

  it("says so when the clipboard holds something else", () => {
    const t = setup(bodyOf(net("n1", c("a"))));
    fireEvent.mouseDown(t.hit("a"));
    fireEvent.paste(t.editor, { clipboardData: { getData: () => "hello" } });
    expect(screen.getByRole("alert").textContent).toContain("no LadderLab elements or networks");
  });
});

describe("read-only (online)", () => {
  it("shows the reason and ignores editing keys but still navigates", () => {
    const t = setup(motorMain, { readOnly: "Go offline to edit" });
    expect(screen.getByText("Go offline to edit")).toBeTruthy();
    fireEvent.mouseDown(t.hit("stop"));
    t.key("Delete");
    t.key("c");
    expect(t.current()).toBe(motorMain);
    t.key("ArrowRight");
    expect(t.selected()).toEqual(["motor"]);
    expect((screen.getByRole("button", { name: "Contact" }) as HTMLButtonElement).disabled).toBe(true);
  });
});

describe("shortcut help", () => {
  it("lists the keymap: every LD key with what it does, and the app's own keys", () => {
    setup(motorMain);
    fireEvent.click(screen.getByRole("button", { name: "Shortcuts" }));
    const help = screen.getByRole("dialog", { name: "Keyboard shortcuts" });
    const rows = (section: string) =>
      within(within(help).getByRole("region", { name: section }))
        .getAllByRole("row")
        .map((r) => r.textContent);
    expect(rows("LD editor")).toEqual(
      expect.arrayContaining([
        "CInsert a contact after the selection",
        "Shift+CInsert a contact before the selection",
        "PPut the selection in a parallel branch",
        "Ctrl+ZUndo",
        "Alt+ArrowUpMove the network up",
        "F9Toggle a breakpoint on the selected element or network",
        "Alt+clickToggle a breakpoint on an element",
      ]),
    );
    expect(rows("Everywhere")).toEqual(
      expect.arrayContaining([
        "Ctrl+SSave the project",
        "F5Run; continue a halted scan",
        "F7Force the prepared values",
      ]),
    );
  });

  it("shows each toolbar command's key from the keymap in its tooltip", () => {
    setup(motorMain);
    expect(screen.getByRole("button", { name: "Contact" }).getAttribute("title")).toBe("Contact (C)");
    expect(screen.getByRole("button", { name: "Redo" }).getAttribute("title")).toBe("Redo (Ctrl+Y / Ctrl+Shift+Z)");
  });
});

describe("history depth", () => {
  it("undoes 100 edits in a row", () => {
    const t = setup(bodyOf(net("n1", c("a"))));
    fireEvent.mouseDown(t.hit("a"));
    for (let i = 0; i < 100; i += 1) t.key(" ");
    expect(t.history().past).toHaveLength(100);
    for (let i = 0; i < 100; i += 1) t.key("z", { ctrlKey: true });
    expect(t.current()).toEqual(bodyOf(net("n1", c("a"))));
  });
});

describe("online commands (issue 7 online mode)", () => {
  // prepare: a BOOL's prepared value toggles (true); any other variable needs a value asked for (false)
  const actions = () => ({
    prepare: vi.fn((operand: string) => !operand.endsWith(".CV")),
    write: vi.fn(),
    force: vi.fn(),
    unforce: vi.fn(),
    watch: vi.fn(),
  });

  it("prepares a value on double-click instead of editing: a BOOL toggles, others ask for it (CODESYS)", () => {
    const onlineActions = actions();
    const t = setup(motorMain, { readOnly: "Go offline to edit", onlineActions });
    fireEvent.doubleClick(t.hit("start"));
    fireEvent.doubleClick(t.hit("motor"));
    // a contact's and a coil's variable is a BOOL: the editor says so, for before its first value arrives
    expect(onlineActions.prepare.mock.calls).toEqual([
      ["Start", undefined, "BOOL"],
      ["Motor", undefined, "BOOL"],
    ]);
    expect(screen.queryByRole("combobox")).toBeNull();
    expect(screen.queryByRole("dialog")).toBeNull();
    expect(t.current()).toBe(motorMain);
  });

  it("prepares a box pin's value: the FB instance's pin (asking for a non-BOOL's value)", () => {
    const onlineActions = actions();
    const online = {
      pins: {
        ton: { "in:PT": { text: "T#5s", bool: null, forced: false, prepared: null } },
        ctu: { "out:CV": { text: "3", bool: null, forced: false, prepared: null } },
      },
    };
    const t = setup(motorMain, { readOnly: "Go offline to edit", onlineActions, online });
    fireEvent.doubleClick(t.editor.querySelector('[data-id="ton"] [data-pin-value="in:PT"] text')!);
    expect(onlineActions.prepare).toHaveBeenLastCalledWith("RunTimer.PT", undefined, "TIME");
    fireEvent.doubleClick(t.editor.querySelector('[data-id="ctu"] [data-pin-value="out:CV"] text')!);
    expect(onlineActions.prepare).toHaveBeenLastCalledWith("StartCounter.CV", undefined, "INT");
    fireEvent.change(
      within(screen.getByRole("dialog", { name: "Prepare a value for StartCounter.CV" })).getByLabelText("Value"),
      {
        target: { value: "5" },
      },
    );
    act(() => void fireEvent.submit(screen.getByRole("dialog", { name: "Prepare a value for StartCounter.CV" })));
    expect(onlineActions.prepare).toHaveBeenLastCalledWith("StartCounter.CV", "5");
  });

  it("writes, forces, releases and watches the clicked element's variable from the context menu", () => {
    const onlineActions = actions();
    const t = setup(motorMain, { readOnly: "Go offline to edit", onlineActions });
    const menuItem = (name: string | RegExp) => {
      fireEvent.contextMenu(t.hit("stop"));
      return within(screen.getByRole("menu")).getByRole("menuitem", { name });
    };
    fireEvent.click(menuItem("Force TRUE"));
    fireEvent.click(menuItem("Force FALSE"));
    fireEvent.click(menuItem("Release force"));
    fireEvent.click(menuItem("Add to watch list"));
    expect(onlineActions.force.mock.calls).toEqual([
      ["Stop", true],
      ["Stop", false],
    ]);
    expect(onlineActions.unforce.mock.calls).toEqual([["Stop"]]);
    expect(onlineActions.watch.mock.calls).toEqual([["Stop"]]);

    fireEvent.click(menuItem(/Write value of Stop/));
    const dialog = screen.getByRole("dialog", { name: "Write Stop" });
    fireEvent.change(within(dialog).getByRole("textbox", { name: "Value" }), { target: { value: "TRUE" } });
    fireEvent.click(within(dialog).getByRole("button", { name: "OK" }));
    expect(onlineActions.write.mock.calls).toEqual([["Stop", "TRUE"]]);

    fireEvent.click(menuItem("Force value…"));
    const force = screen.getByRole("dialog", { name: "Force Stop" });
    fireEvent.change(within(force).getByRole("textbox", { name: "Value" }), { target: { value: "FALSE" } });
    fireEvent.submit(force);
    expect(onlineActions.force.mock.calls.at(-1)).toEqual(["Stop", "FALSE"]);
  });

  it("offers no online items offline, and a Go offline button with the read-only reason", () => {
    const run = vi.fn();
    const t = setup(motorMain, {
      readOnly: "Online",
      readOnlyActions: (
        <button type="button" onClick={run}>
          Go offline to edit
        </button>
      ),
    });
    fireEvent.contextMenu(t.hit("stop"));
    expect(within(screen.getByRole("menu")).queryByRole("menuitem", { name: "Force TRUE" })).toBeNull();
    fireEvent.click(screen.getByRole("button", { name: "Go offline to edit" }));
    expect(run).toHaveBeenCalledOnce();
  });

  it("reports the networks in view and selects what a focus request names", () => {
    const onVisibleChange = vi.fn();
    const t = setup(motorMain, { onVisibleChange });
    expect(onVisibleChange).toHaveBeenLastCalledWith(networksOf(motorMain).map((n) => n.id));
    t.rerender(
      <LdEditor history={historyOf(motorMain)} onHistoryChange={() => undefined} focus={{ element: "stop", seq: 1 }} />,
    );
    expect(t.selected()).toEqual(["stop"]);
  });
});
