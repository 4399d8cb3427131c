// The accumulator per IL line online: probes `L<line>:<type>` of the shown instance at their line ends.
import { describe, expect, it } from "vitest";
import { emptyMonitor } from "../online/monitor";
import { accumulatorMarks } from "./ilOnline";

const body = "LD a\nADD 1\nJMPC skip\nST x\nskip:\nLD t";

describe("IL accumulator marks", () => {
  it("puts each line's value at its end, typed, and nothing on a line that did not run", () => {
    const monitor = {
      ...emptyMonitor,
      power: {
        "MAIN/L1:INT": 4,
        "MAIN/L2:INT": 5,
        "MAIN/L4:INT": null, // skipped by the jump
        "MAIN/L6:TIME": 1500,
        "OTHER/L1:INT": 99,
        "MAIN/blk1.OUT": 7,
      },
    };
    const marks = accumulatorMarks(body, monitor, "MAIN");
    expect(marks.map((m) => [body.slice(0, m.pos).split("\n").length, m.pos, m.shown.text])).toEqual([
      [1, 4, "4"],
      [2, 10, "5"],
      [6, 36, "T#1s500ms"],
    ]);
  });
});
