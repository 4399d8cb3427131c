import { fireEvent, render } from "@testing-library/react";
import { describe, expect, it, vi } from "vitest";
import { bodyOf, c, library, motorMain, net, par, q } from "../fixtures";
import { layoutBody } from "../layout";
import type { LdBody, LdElement } from "../model";
import { LdDiagram, type LdDiagramProps } from "./LdDiagram";

function draw(body: LdBody, props: Partial<LdDiagramProps> = {}) {
  const layout = layoutBody(body, { library });
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

  it("colours power flow, dims elements not executed, marks forced variables and shows values", () => {
    const online = {
      power: { start: false, seal: true, start_or_motor: true, stop: true, motor: true, ton: false },
      executed: { blink: false },
      forced: new Set(["STOP"]),
      values: { "T#5S": 5000, STARTCOUNT: 42, START: false },
    };
    const { one, all } = draw(motorMain, { online });
    expect(one('[data-id="seal"]').classList.contains("ld-on")).toBe(true);
    expect(one('[data-id="start"]').classList.contains("ld-off")).toBe(true);
    expect(one('[data-id="motor_on"]').classList.contains("ld-on")).toBe(false);
    expect(one('[data-network="seal_in"] .ld-rail').classList.contains("ld-on")).toBe(true);
    const sealWire = one('[data-network="seal_in"] line.ld-wire.ld-off');
    expect(sealWire).toBeTruthy();
    expect(one('[data-id="blink"]').classList.contains("ld-not-executed")).toBe(true);
    expect(one('[data-id="stop"] .ld-operand').classList.contains("ld-forced")).toBe(true);
    expect(one('[data-id="stop"] .ld-forced-mark').textContent).toBe("F");
    expect(one('[data-id="ctu"] [data-field="output:CV"] .ld-value').textContent).toBe("42");
    expect(all('[data-id="start"] .ld-value')).toEqual([]); // BOOL values show as colour, not as a label
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

  // The 1 s target is the browser's; jsdom with the other test files in parallel gets twice that.
  it("opens a 1,000-network POU quickly, rendering only what is in view", () => {
    const start = performance.now();
    const { all, layout } = draw(big, { fallbackHeight: 800 });
    expect(performance.now() - start).toBeLessThan(2000);
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
