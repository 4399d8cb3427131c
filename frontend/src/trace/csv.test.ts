import { describe, expect, it } from "vitest";
import { csvField, traceCsv } from "./csv";
import { SampleRing } from "./ring";

describe("traceCsv", () => {
  it("writes time in ms, scan and one column per path, oldest first, BOOLs as TRUE/FALSE", () => {
    const ring = new SampleRing(3, 3);
    ring.push(7, 70, [0, 0, 1.5]);
    ring.push(8, 80, [0, 10, NaN]);
    ring.push(9, 90, [1, 20, Infinity]);
    ring.push(10, 100, [1, 20, -0.25]); // scan 7 falls out of the buffer
    expect(traceCsv(["MAIN.Q", "MAIN.ET", "MAIN.LEVEL"], ["bool", "number", "number"], ring.columnsInOrder())).toBe(
      "time_ms,scan,MAIN.Q,MAIN.ET,MAIN.LEVEL\n" +
        "80,8,FALSE,10,NaN\n" +
        "90,9,TRUE,20,Infinity\n" +
        "100,10,TRUE,20,-0.25\n",
    );
  });

  it("writes an enumeration's values by name, as the server spells them (declared: Run, not RUN)", () => {
    const ring = new SampleRing(2, 2);
    ring.push(1, 10, [5, 5]);
    ring.push(2, 20, [0, 0]);
    const mode = { name: "MODE", names: { "0": "Idle", "5": "Run" } };
    expect(traceCsv(["MAIN.M", "MAIN.N"], ["number", "number"], ring.columnsInOrder(), [mode, null])).toBe(
      "time_ms,scan,MAIN.M,MAIN.N\n10,1,Run,5\n20,2,Idle,0\n",
    );
  });

  it("quotes paths that hold a comma or a quote", () => {
    expect(csvField("MAIN.GRID[1,2]")).toBe('"MAIN.GRID[1,2]"');
    expect(csvField('say "hi"')).toBe('"say ""hi"""');
    expect(csvField("MAIN.X")).toBe("MAIN.X");
    expect(traceCsv(["MAIN.GRID[1,2]"], ["number"], new SampleRing(1, 1).columnsInOrder())).toBe(
      'time_ms,scan,"MAIN.GRID[1,2]"\n',
    );
  });
});
