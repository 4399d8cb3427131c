// @vitest-environment jsdom
import { describe, expect, it } from "vitest";
import { focusOf } from "./panels";

describe("the place a diagnostic of an SFC action or transition reveals", () => {
  it("names the action or transition as the part of the POU's body it is in, with its line", () => {
    const inAction = { code: "IL-TYPE", message: "", file: "Main/actions/Count", pou: "Main", line: 2, column: 1 };
    expect(focusOf(inAction)).toEqual({
      pou: "Main",
      network: null,
      element: null,
      line: 2,
      part: "body",
      body: "actions/Count",
    });
    const inTransition = { code: "SFC-CONDITION", message: "", file: "Main/transitions/T1", pou: "Main", line: 1 };
    expect(focusOf(inTransition)?.body).toBe("transitions/T1");
    const inChart = { code: "SFC-TIME", message: "", file: "Main/chart", pou: "Main", element: "a3" };
    expect(focusOf(inChart)).toMatchObject({ element: "a3", part: null, body: null });
  });
});
