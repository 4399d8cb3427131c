import { afterEach, describe, expect, it } from "vitest";
import { emptyMonitor } from "./monitor";
import { operandCommands } from "./operandCommands";
import { offline, onlineStore } from "./store";

afterEach(() => onlineStore.setState({ ...offline }));

const commands = operandCommands(
  (operand) => (/^\d/.test(operand) ? null : `MAIN.${operand.toUpperCase()}`),
  (operand) => ({ START: "BOOL", SPEED: "INT" })[operand.toUpperCase()],
);

describe("preparing a value (CODESYS double-click)", () => {
  it("toggles a BOOL's prepared value: first the opposite of its value, then back and forth", () => {
    onlineStore.setState({ monitor: { ...emptyMonitor, values: { "MAIN.START": false } } });
    expect(commands.prepare("Start")).toBe(true);
    expect(onlineStore.getState().prepared).toEqual({ "MAIN.START": true });
    expect(commands.prepare("Start")).toBe(true);
    expect(onlineStore.getState().prepared).toEqual({ "MAIN.START": false });
  });

  it("knows a declared BOOL before its first value arrives, or one the diagram says is a BOOL", () => {
    expect(commands.prepare("Start")).toBe(true);
    expect(onlineStore.getState().prepared).toEqual({ "MAIN.START": true });
    expect(commands.prepare("Lamp", undefined, "BOOL")).toBe(true); // a coil's variable
    expect(onlineStore.getState().prepared).toEqual({ "MAIN.START": true, "MAIN.LAMP": true });
  });

  it("asks for any other type's value, and prepares what was typed as the server reads it", () => {
    expect(commands.prepare("Speed")).toBe(false);
    expect(onlineStore.getState().prepared).toEqual({});
    commands.prepare("Speed", "42");
    commands.prepare("Other", "T#2s");
    expect(onlineStore.getState().prepared).toEqual({ "MAIN.SPEED": 42, "MAIN.OTHER": "T#2s" });
    expect(commands.prepare("5")).toBe(true); // a literal: nothing to prepare
  });
});
