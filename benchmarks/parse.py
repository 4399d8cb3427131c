"""ST parse throughput (parse + AST), in KB/s: OSCAT BASIC and a generated 10,000-line file.

Run: ``.venv/bin/python benchmarks/parse.py``. Target: at least 300 KB/s on the
2-core CI machine. When the ``blark`` package is installed (``pip install
.[bench]``) the same OSCAT text is parsed with blark for comparison.
"""

from __future__ import annotations

import pathlib
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "backend"))

from ladderlab.st.parser import parse_source  # noqa: E402

OSCAT = (ROOT / ".." / "shared" / "external" / "oscat" / "oscat.st").resolve()
RUNS = 3

POU = """FUNCTION_BLOCK Block{n}
VAR_INPUT
    enable : BOOL;
    setpoint : REAL := 20.0;
END_VAR
VAR_OUTPUT
    done : BOOL;
END_VAR
VAR
    timer : TON;
    count : INT;
    values : ARRAY [1..10] OF REAL;
END_VAR
    timer(IN := enable AND NOT done, PT := T#1s500ms);
    IF timer.Q THEN
        count := count + 1;
    ELSIF count > 100 THEN
        count := 0;
    END_IF;
    FOR count := 1 TO 10 BY 1 DO
        values[count] := setpoint * INT_TO_REAL(count) / 2.5;
    END_FOR;
    CASE count OF
        1, 2: done := TRUE;
        3..9: done := FALSE;
    ELSE
        done := values[1] > setpoint;
    END_CASE;
    (* a comment *)
END_FUNCTION_BLOCK

"""


def generated(lines: int = 10_000) -> str:
    per_pou = POU.count("\n")
    return "".join(POU.format(n=i) for i in range(lines // per_pou + 1))


def throughput(text: str, parse) -> float:
    best = min(_timed(parse, text) for _ in range(RUNS))
    return len(text.encode("utf-8")) / 1024 / best


def _timed(parse, text: str) -> float:
    start = time.perf_counter()
    parse(text)
    return time.perf_counter() - start


def _ladderlab(text: str) -> None:
    result = parse_source(text, nested_comments=True)
    assert result.ast is not None


def _blark():
    try:
        import blark  # noqa: F401
        from blark.parse import parse_source_code
    except ImportError:
        return None
    return lambda text: parse_source_code(text)


def main() -> None:
    parse_source("PROGRAM warm_up END_PROGRAM")  # builds the parser once
    samples = {"generated 10,000 lines": generated()}
    if OSCAT.exists():
        samples["OSCAT BASIC 3.33"] = OSCAT.read_text(encoding="utf-8")
    blark = _blark()
    for name, text in samples.items():
        ours = throughput(text, _ladderlab)
        line = f"{name:<24} {len(text) / 1024:8.0f} KB   ladderlab {ours:7.0f} KB/s"
        if blark is not None:
            theirs = throughput(text, blark)
            line += f"   blark {theirs:7.0f} KB/s   ratio {ours / theirs:5.1f}x"
        print(line)
    if blark is None:
        print("(blark not installed: pip install '.[bench]' to compare)")


if __name__ == "__main__":
    main()
