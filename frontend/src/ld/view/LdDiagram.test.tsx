// @vitest-environment jsdom
import { fireEvent, render } from "@testing-library/react";
import { describe, expect, it, vi } from "vitest";
import { bodyOf, c, library, motorMain, net, par, q } from "../fixtures";
import { layoutBody } from "../layout";
import type { LdBody, LdElement } from "../model";
import { LdDiagram, type LdDiagramProps } from "./LdDiagram";

function draw(body: LdBody, props: Partial<LdDiagramProps> & { values?: boolean } = {}) {
  const layout = layoutBody(body, { library, values: props.values });
  const view = render(<LdDiagram body={body} layout={layout} selection={null} {...props} />);
  const all = (selector: string) => [...view.container.querySelectorAll(selector)];
  const one = (selector: string) => {
    const found = view.container.querySelector(selector);
    if (!found) throw new Error(`nothing matches ${selector}`);
    return found;
  };
  return { ...view, all, one, layout };
}
const texts = (els: Element[]) => els.map((e) => e.textContent);

describe("LdDiagram rendering", () => {
  it("draws the motor example's networks, elements, rails and texts", () => {
    const { all, one } = draw(motorMain);
    expect(all("svg.ld-network")).toHaveLength(4);
    expect(texts(all(".ld-number"))).toEqual(["1", "2", "3", "4"]);
    expect(texts(all(".ld-comment"))[0]).toBe("Start/stop with seal-in: Motor := (Start OR Motor) AND NOT Stop");
    expect(all(".ld-element.ld-contact")).toHaveLength(7);
    expect(all(".ld-element.ld-coil")).toHaveLength(3);
    expect(all(".ld-element.ld-box")).toHaveLength(3);
    expect(all(".ld-element.ld-parallel")).toHaveLength(1);
    expect(all(".ld-rail")).toHaveLength(8);
    expect(all(".ld-branch")).toHaveLength(2);
    expect(one('[data-id="stop"]').classList.contains("ld-mode-nc")).toBe(true);
    expect(one('[data-id="start_edge"] .ld-mark').textContent).toBe("P");
    expect(texts(all('[data-id="start_or_motor"] ~ [data-id] .ld-operand text')).slice(0, 2)).toEqual([
      "Start",
      "Motor",
    ]);
    const ton = one('[data-id="ton"]');
    expect(ton.querySelector(".ld-title")?.textContent).toBe("TON");
    expect(ton.querySelector('[data-field="instance"]')?.textContent).toBe("RunTimer");
    expect(texts([...ton.querySelectorAll(".ld-pin-name")])).toEqual(["IN", "PT", "Q", "ET"]);
    expect(ton.querySelector('[data-field="input:PT"]')?.textContent).toBe("T#5s");
    expect(ton.querySelector('[data-field="output:ET"]')?.textContent).toBe("???");
    expect(one('[data-id="ctu"] [data-field="output:CV"]').textContent).toBe("StartCount");
    expect(all(".ld-stub")).toHaveLength(1);
  });

  it("draws coil modes, compare contacts, jumps, returns and network labels", () => {
    const body = bodyOf(
      {
        ...net("n1", { type: "compare", id: "cmp", op: "GE", left: "Level", right: "100" }, q("s", "Alarm", "set")),
        label: "Check",
      },
      net("n2", c("a"), { type: "jump", id: "j", target: "Check" }),
      net("n3", { type: "return", id: "r" }),
    );
    const { one, all } = draw(body);
    expect(one('[data-id="s"] .ld-mark').textContent).toBe("S");
    expect(texts([...one('[data-id="cmp"]').querySelectorAll("text")])).toEqual(["GE", "Level", "100"]);
    expect(one('[data-id="j"] [data-field="target"]').textContent).toBe("Check");
    expect(one('[data-id="r"]').textContent).toBe("RETURN");
    expect(texts(all(".ld-label"))).toEqual(["Check:"]);
  });

  it("marks elements with diagnostics, with the message on hover", () => {
    const diagnostics = [
      { code: "LD-UNKNOWN-VAR", message: "unknown variable Stop", network: "seal_in", element: "stop" },
      { code: "LD-PIN", message: "PT needs a TIME", network: "run_timer", element: "ton", pin: "PT" },
      { code: "LD-LABEL", message: "jump to nowhere", network: "lamp" },
    ];
    const { one, all } = draw(motorMain, { diagnostics });
    expect(one('[data-id="stop"]').classList.contains("ld-has-diagnostic")).toBe(true);
    expect(one('[data-id="stop"] .ld-marker title').textContent).toBe("unknown variable Stop");
    expect(one('[data-id="ton"] .ld-marker').getAttribute("aria-label")).toBe("PT: PT needs a TIME");
    expect(one('[data-network="lamp"] .ld-header .ld-marker title').textContent).toBe("jump to nowhere");
    expect(all(".ld-marker")).toHaveLength(3);
  });

  it("highlights the selected elements, place or network", () => {
    expect(
      draw(motorMain, { selection: { kind: "elements", ids: ["stop", "motor"] } })
        .all(".ld-selected")
        .map((e) => e.getAttribute("data-id")),
    ).toEqual(["stop", "motor"]);
    const place = draw(motorMain, {
      selection: {
        kind: "place",
        place: { series: { kind: "branch", parallel: "start_or_motor", branch: 1 }, index: 1 },
      },
    });
    expect(place.all(".ld-slot.ld-selected")).toHaveLength(1);
    expect(
      draw(motorMain, { selection: { kind: "network", id: "lamp" } })
        .all("svg.ld-selected")
        .map((e) => e.getAttribute("data-network")),
    ).toEqual(["lamp"]);
  });

  it("colours power flow, dims elements not executed, badges variable values and marks forced ones (issue 17)", () => {
    const shown = (text: string, forced = false, prepared: string | null = null) => ({
      text,
      bool: text === "TRUE" ? true : text === "FALSE" ? false : null,
      forced,
      prepared,
    });
    const online = {
      power: { start: false, seal: true, start_or_motor: true, stop: true, motor: true, ton: false },
      executed: { blink: false },
      operands: {
        STOP: shown("FALSE", true),
        START: shown("FALSE", false, "TRUE"),
        MOTOR: shown("TRUE"),
        STARTCOUNT: shown("42"),
      },
    };
    const { one, all } = draw(motorMain, { online, values: true });
    expect(one('[data-id="seal"]').classList.contains("ld-on")).toBe(true);
    expect(one('[data-id="start"]').classList.contains("ld-off")).toBe(true);
    expect(one('[data-id="motor_on"]').classList.contains("ld-on")).toBe(false);
    expect(one('[data-network="seal_in"] .ld-rail').classList.contains("ld-on")).toBe(true);
    const sealWire = one('[data-network="seal_in"] line.ld-wire.ld-off');
    expect(sealWire).toBeTruthy();
    expect(one('[data-id="blink"]').classList.contains("ld-not-executed")).toBe(true);
    // Contacts and coils: their variable's value in a badge, apart from the power flow (Stop is TRUE: power passes).
    expect(one('[data-id="motor"] .ld-badge').getAttribute("class")).toBe("ld-badge ld-badge-true");
    expect(one('[data-id="start"] .ld-badge').getAttribute("data-value")).toBe("FALSE");
    expect(one('[data-id="start"] .ld-prepared').textContent).toBe("<TRUE>");
    // Forced: an orange ground under the name, an orange frame and a red F on the value.
    expect(one('[data-id="stop"] .ld-operand').classList.contains("ld-forced")).toBe(true);
    expect(all('[data-id="stop"] .ld-forced-ground')).toHaveLength(1);
    expect(one('[data-id="stop"] .ld-badge').classList.contains("ld-badge-forced")).toBe(true);
    expect(one('[data-id="stop"] .ld-forced-badge').textContent).toBe("F");
    expect(all('[data-id="seal"] .ld-forced-badge')).toEqual([]);
  });

  it("shows every box pin's value next to its name, a power-fed input from the power feeding it", () => {
    const shown = (text: string) => ({ text, bool: null, forced: false, prepared: null });
    const online = {
      power: { motor_on: true, start_edge: false, reset_count: false },
      pins: { ton: { "in:PT": shown("T#5s"), "out:ET": shown("T#2s300ms") } },
    };
    const { one, all } = draw(motorMain, { online, values: true });
    const values = (id: string) =>
      Object.fromEntries(
        all(`[data-id="${id}"] [data-pin-value]`).map((e) => [
          e.getAttribute("data-pin-value"),
          e.querySelector(".ld-badge")!.getAttribute("data-value"),
        ]),
      );
    expect(values("ton")).toEqual({ "in:IN": "TRUE", "in:PT": "T#5s", "out:ET": "T#2s300ms" });
    expect(values("ctu")).toEqual({ "in:CU": "FALSE", "in:R": "FALSE" }); // the rung, and the series into R
    // The value sits inside the box, right of an input's name and left of an output's.
    const x = (sel: string) => Number(one(sel).getAttribute("x"));
    const box = one('[data-id="ton"] .ld-box-body');
    const [left, width] = [Number(box.getAttribute("x")), Number(box.getAttribute("width"))];
    expect(x('[data-id="ton"] [data-pin-value="in:PT"] rect')).toBeGreaterThan(left);
    const et = one('[data-id="ton"] [data-pin-value="out:ET"] rect');
    expect(Number(et.getAttribute("x")) + Number(et.getAttribute("width"))).toBeLessThan(left + width);
  });

  it("leaves room for the values online: boxes wider, rows taller", () => {
    const offline = layoutBody(motorMain, { library });
    const online = layoutBody(motorMain, { library, values: true });
    const body = (l: typeof offline, id: string) => l.networks.flatMap((n) => n.elements).find((e) => e.id === id)!;
    expect(body(online, "ton").body!.width).toBeGreaterThanOrEqual(body(offline, "ton").body!.width + 2 * 60);
    expect(body(online, "stop").height).toBe(body(offline, "stop").height + 12);
  });

  it("marks an empty required operand (a function input) as missing, an empty optional one (FB input, output) as muted", () => {
    const add: LdElement = { type: "box", id: "add", call: "ADD", en: true, inputs: { IN1: "X" }, outputs: {} };
    const { one } = draw(bodyOf(net("n", c("go"), add), ...(motorMain.networks ?? [])));
    expect(one('[data-id="add"] [data-field="input:IN2"]').classList.contains("ld-operand-empty")).toBe(true);
    expect(one('[data-id="add"] [data-field="output:OUT"]').classList.contains("ld-operand-unset")).toBe(true);
    const et = one('[data-id="ton"] [data-field="output:ET"]');
    expect([
      et.classList.contains("ld-operand-unset"),
      et.classList.contains("ld-operand-empty"),
      et.textContent,
    ]).toEqual([true, false, "???"]);
  });

  it("reports clicks on elements, operands, places and headers", () => {
    const handlers = { onPointerDown: vi.fn(), onOperand: vi.fn(), onContextMenu: vi.fn(), onPlaceUp: vi.fn() };
    const { one, all } = draw(motorMain, { handlers });
    fireEvent.mouseDown(one('[data-id="stop"] .ld-hit'));
    expect(handlers.onPointerDown.mock.calls[0]![0]).toEqual({ kind: "element", id: "stop" });
    fireEvent.click(one('[data-id="ton"] [data-field="input:PT"] text'));
    expect(handlers.onOperand.mock.calls[0]!.slice(0, 2)).toEqual(["ton", { kind: "input", pin: "PT" }]);
    fireEvent.contextMenu(one('[data-network="lamp"] .ld-header'));
    expect(handlers.onContextMenu.mock.calls[0]![0]).toEqual({ kind: "network", id: "lamp" });
    fireEvent.mouseUp(all('[data-network="seal_in"] .ld-slot')[0]!);
    expect(handlers.onPlaceUp.mock.calls[0]![0]).toEqual({ series: { kind: "network", network: "seal_in" }, index: 0 });
  });
});

describe("virtualisation", () => {
  const big = bodyOf(
    ...Array.from({ length: 1000 }, (_, i) =>
      net(`n${i}`, par(`p${i}`, [c(`a${i}`)], [c(`b${i}`)]), c(`d${i}`), q(`m${i}`)),
    ),
  );

  // Its speed (the 1 s target) is measured in the real browser (tests/browser/test_ld_large.py, benchmarks/RESULTS.md),
  // not timed here: what makes it fast is that only the networks in view are drawn.
  it("opens a 1,000-network POU rendering only what is in view", () => {
    const { all, layout } = draw(big, { fallbackHeight: 800 });
    const shown = all("svg.ld-network");
    expect(shown.length).toBeGreaterThan(3);
    expect(shown.length).toBeLessThan(20);
    expect(layout.height).toBeGreaterThan(100_000);
    expect(shown[0]!.getAttribute("data-network")).toBe("n0");
  });

  it("renders the networks around the scroll position and reveals the selected one", () => {
    const { all, container, rerender, layout } = draw(big, { fallbackHeight: 800 });
    const scroller = container.querySelector(".ld-scroller")!;
    const middle = layout.networks[500]!.top;
    scroller.scrollTop = middle;
    fireEvent.scroll(scroller);
    const ids = all("svg.ld-network").map((e) => e.getAttribute("data-network"));
    expect(ids).toContain("n500");
    expect(ids).not.toContain("n0");
    rerender(
      <LdDiagram
        body={big}
        layout={layout}
        selection={{ kind: "network", id: "n900" }}
        reveal="n900"
        fallbackHeight={800}
      />,
    );
    expect(all("svg.ld-network").map((e) => e.getAttribute("data-network"))).toContain("n900");
    expect(container.querySelector('[data-network="n900"]')?.classList.contains("ld-selected")).toBe(true);
  });
});
