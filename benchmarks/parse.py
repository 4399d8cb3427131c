"""ST parse throughput (parse + AST), in KB/s of CPU time: OSCAT BASIC and a generated 10,000-line file.

Run: ``.venv/bin/python benchmarks/parse.py``. Target: at least 300 KB/s on the
2-core CI machine. When the ``blark`` package is installed (``pip install
.[bench]``) the same texts are parsed with blark for comparison. A comparison counts only what
both parsers accept: each sample is cut into its POUs and TYPE blocks, each piece is parsed by
both, and only the pieces both parse without an error are timed (blark stops early on parts of
OSCAT; timing that failure as a parse would flatter it). blark parses about 2 KB/s, so the
comparison takes the first pieces both accept, in file order, up to 20 KB per sample.
"""

from __future__ import annotations

import pathlib
import re
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "backend"), str(ROOT)]

from benchmarks.common import load_average, settle  # noqa: E402
from ladderlab.st.parser import parse_source  # noqa: E402

OSCAT = (ROOT / ".." / "shared" / "external" / "oscat" / "oscat.st").resolve()
RUNS = 3
COMPARED_KB = 20

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


_END = re.compile(r"^\s*END_(?:FUNCTION_BLOCK|FUNCTION|PROGRAM|TYPE|CONFIGURATION)\b.*$", re.M | re.I)


def pieces(text: str) -> list[str]:
    """The text cut after every END_FUNCTION_BLOCK / END_FUNCTION / END_PROGRAM / END_TYPE line."""
    cuts = [m.end() for m in _END.finditer(text)]
    return [text[a:b] for a, b in zip([0, *cuts], cuts) if text[a:b].strip()]


def throughput(pieces_: list[str], parse) -> tuple[float, str]:
    """KB/s over ``pieces_`` (one pass parses each once), timed until the passes agree."""
    size = sum(len(p.encode("utf-8")) for p in pieces_)
    settled = settle(lambda: _timed(parse, pieces_), batch=RUNS, max_batches=4)
    return size / 1024 / settled.median, settled.note()


def _timed(parse, pieces_: list[str]) -> float:
    """CPU seconds of one pass (the machine is shared: wall time would measure the others' load)."""
    start = time.process_time()
    for piece in pieces_:
        parse(piece)
    return time.process_time() - start


def _ladderlab_ok(text: str) -> bool:
    result = parse_source(text, nested_comments=True)
    return result.ast is not None and not any(d.severity == "error" for d in result.diagnostics)


def _ladderlab(text: str) -> None:
    parse_source(text, nested_comments=True)


def _blark():
    try:
        from blark.parse import parse_source_code
    except ImportError:
        return None, None
    from blark.parse import get_parser

    parser = get_parser()  # built once, as ours is

    def parse(text: str):
        return parse_source_code(text, parser=parser)

    def ok(text: str) -> bool:
        result = parse(text)
        return result.exception is None and result.tree is not None

    return parse, ok


def _first_kb(pieces_: list[str], kb: int) -> list[str]:
    taken, size = [], 0
    for piece in pieces_:
        if size >= kb * 1024:
            break
        taken.append(piece)
        size += len(piece.encode("utf-8"))
    return taken


def main() -> None:
    parse_source("PROGRAM warm_up END_PROGRAM")  # builds the parser once
    samples = {"generated 10,000 lines": generated()}
    if OSCAT.exists():
        samples["OSCAT BASIC 3.33"] = OSCAT.read_text(encoding="utf-8")
    blark, blark_ok = _blark()
    print(load_average())
    for name, text in samples.items():
        ours_ok = [p for p in pieces(text) if _ladderlab_ok(p)]
        total = len(pieces(text))
        ours, note = throughput(ours_ok, _ladderlab)
        print(
            f"{name:<24} {len(text) / 1024:6.0f} KB, {len(ours_ok)}/{total} pieces parse: "
            f"ladderlab {ours:7.0f} KB/s ({note})"
        )
        if blark is not None:
            both = _first_kb([p for p in ours_ok[:200] if blark_ok(p)], COMPARED_KB)
            kb = sum(len(p.encode("utf-8")) for p in both) / 1024
            mine, note_mine = throughput(both, _ladderlab)
            theirs, note_theirs = throughput(both, blark)
            print(
                f"{'':<24} both accept {len(both)}/{total} pieces ({kb:.0f} KB): ladderlab {mine:7.0f} KB/s "
                f"({note_mine}), blark {theirs:7.0f} KB/s ({note_theirs}), ratio {mine / theirs:5.1f}x"
            )
    if blark is None:
        print("(blark not installed: pip install '.[bench]' to compare)")
    print(load_average())


if __name__ == "__main__":
    main()
