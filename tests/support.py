"""Paths and helpers shared by the test suites (import as ``from tests.support import ...``)."""

from __future__ import annotations

import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
EXTERNAL = (ROOT / ".." / "shared" / "external").resolve()
SPEC = (ROOT / ".." / "shared" / "spec").resolve()
EXAMPLES = ROOT / "examples"


def external(*parts: str) -> pathlib.Path:
    """Path under ../shared/external; skips the calling test when it is absent."""
    path = EXTERNAL.joinpath(*parts)
    if not path.exists():
        pytest.skip(f"{path} not present (../shared/external is optional)")
    return path


#: External-corpus pass rates (name -> (passed, total)), printed at the end of the run by tests/conftest.py.
PASS_RATES: dict[str, tuple[int, int]] = {}


def api_client(app, **options):
    """A TestClient that talks to ``app`` as the browser app does: at http://localhost, sending JSON.

    The server answers only the names it is served under and takes state-changing requests only as
    JSON (server/security.py); tests of those rules build their requests themselves. Websockets go
    to ws://localhost too (starlette's TestClient would name ``testserver``)."""
    from fastapi.testclient import TestClient

    class LocalClient(TestClient):
        def websocket_connect(self, url: str, *args, **kwargs):
            return super().websocket_connect(f"ws://localhost{url}" if url.startswith("/") else url, *args, **kwargs)

    return LocalClient(app, base_url="http://localhost", headers={"Content-Type": "application/json"}, **options)


def fuzz_settings(fast: int = 40):
    """Hypothesis settings of a fuzzer (issue 18, fuzzing as a habit): a few dozen cases in ``make test``,
    10,000 per surface in ``make test-slow`` (LADDERLAB_HYPOTHESIS=thorough)."""
    import os

    from hypothesis import HealthCheck, settings

    thorough = os.environ.get("LADDERLAB_HYPOTHESIS") == "thorough"
    return settings(
        max_examples=10_000 if thorough else fast,
        deadline=None,
        suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much, HealthCheck.data_too_large],
    )


#: Issue 18's runaway scan: four nested FOR 1 TO 255 (4e9 iterations) once ``Go`` is TRUE (a PROGRAM's declarations
#: and body; the innermost loop, whose back-edge the watchdog sees first, is on line 5 of the body).
NESTED_LOOPS_DECLARATIONS = "VAR\n    Go : BOOL;\n    a, b, c, d : INT;\n    n : DINT;\nEND_VAR"
NESTED_LOOPS = """IF Go THEN
    FOR a := 1 TO 255 DO
        FOR b := 1 TO 255 DO
            FOR c := 1 TO 255 DO
                FOR d := 1 TO 255 DO
                    n := n + 1;
                END_FOR;
            END_FOR;
        END_FOR;
    END_FOR;
END_IF;"""


def line_of(text: str, statement: str) -> int:
    """The line of ``text`` on which ``statement`` stands, a whole line written in one place only."""
    (line,) = [number for number, row in enumerate(text.splitlines(), 1) if row == statement]
    return line


def ld_shapes_project(declarations: str, networks: list[list[tuple[str, str, str]]]) -> object:
    """A project whose program Main (declaring ``declarations``, with the global G1) holds one LD network per entry
    of ``networks``, each element made by ``ld_shape_element`` from its spec: the repeated-shape programs of the
    template tests (tests/engine/test_block_templates.py, tests/ir/test_ld_templates.py)."""
    from ladderlab.model import ld
    from ladderlab.model.project import Pou, Project, Task

    body = ld.LdBody(
        networks=[
            ld.LdNetwork(id=f"n{n}", elements=[ld_shape_element(n, k, spec) for k, spec in enumerate(elements)])
            for n, elements in enumerate(networks)
        ]
    )
    main = Pou(name="Main", kind="program", language="ld", declarations=declarations, body=body)
    return Project(
        name="shapes",
        pous=[main],
        globals="VAR_GLOBAL G1 : BOOL; END_VAR",
        tasks=[Task(name="main", interval="T#10ms", programs=["Main"])],
    )


def ld_shape_element(n: int, k: int, spec: tuple[str, str, str]) -> object:
    """Element ``k`` of network ``n`` from ``(kind, a, b)``: a contact or coil on ``a`` in mode ``b``, ``a < b``, a TON
    ``a`` with PT ``b``, ``a := a + b`` with EN, two parallel contacts (``a``, NOT ``b``), or (``fed``) a TON ``a`` whose
    IN is a contact of its own on ``b``."""
    from ladderlab.model import ld

    kind, a, b = spec
    ident = f"e{n}_{k}"
    if kind == "contact":
        return ld.Contact(id=ident, var=a, mode=b)  # type: ignore[arg-type]
    if kind == "coil":
        return ld.Coil(id=ident, var=a, mode=b)  # type: ignore[arg-type]
    if kind == "compare":
        return ld.Compare(id=ident, op="LT", left=a, right=b)
    if kind == "ton":
        return ld.Box(id=ident, call="TON", instance=a, inputs={"PT": b})
    if kind == "add":
        return ld.Box(id=ident, call="ADD", en=True, inputs={"IN1": a, "IN2": b}, outputs={"OUT": a})
    if kind == "parallel":
        return ld.Parallel(
            id=ident,
            branches=[[ld.Contact(id=f"{ident}a", var=a)], [ld.Contact(id=f"{ident}b", var=b, mode="nc")]],
        )
    assert kind == "fed", kind
    return ld.Box(id=ident, call="TON", instance=a, inputs={"IN": [ld.Contact(id=f"{ident}i", var=b)], "PT": "T#2ms"})
