"""Issue 19, item 3: no new ``# type: ignore`` without a reason comment.

Each ignore silences the type checker at one spot; the next engineer must see why. New ones carry a
reason (``# type: ignore[code]  # why``). The ones written before the rule are counted, and the count
may only go down.
"""

from __future__ import annotations

import re
from pathlib import Path

BACKEND = Path(__file__).resolve().parents[2] / "backend" / "ladderlab"
WITHOUT_REASON = re.compile(r"#\s*type:\s*ignore(\[[^\]]*\])?\s*$")
#: Ignores without a reason when the rule came in (2026-11-27); lower it when you add reasons.
BEFORE_THE_RULE = 57


def ignores_without_reason() -> list[str]:
    found = []
    for path in sorted(BACKEND.rglob("*.py")):
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            if WITHOUT_REASON.search(line):
                found.append(f"{path.relative_to(BACKEND)}:{number}")
    return found


def test_bare_ignores_only_go_down() -> None:
    found = ignores_without_reason()
    assert len(found) <= BEFORE_THE_RULE, (
        f"{len(found)} '# type: ignore' without a reason (at most {BEFORE_THE_RULE}); "
        "write '# type: ignore[code]  # why' - the newest: " + ", ".join(found[-5:])
    )


def test_the_pattern_tells_reasons_apart() -> None:
    assert WITHOUT_REASON.search("x = f()  # type: ignore[arg-type]")
    assert WITHOUT_REASON.search("x = f()  # type: ignore")
    assert not WITHOUT_REASON.search("x = f()  # type: ignore[arg-type]  # f is untyped")
