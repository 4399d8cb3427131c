"""What the fork server imports before it forks workers: the engine, and one build of each language.

``supervisor.py`` starts simulation and build workers by forking a fork server that has
imported this module, so a new worker starts with everything a build needs already in memory
(the ST parser's tables, the lowering and code generator caches, the pydantic models' validators):
the first simulation of a project opens without paying for a cold interpreter. The warm-up objects are then
frozen out of the garbage collector's view (``gc.freeze``), so the forked workers share their pages instead
of copying them on the first collection.
"""

from __future__ import annotations

import gc

from ..model import Project
from ..model.base import build_all
from . import worker  # noqa: F401  (the worker's own imports)
from .build import build_project

_WARM_UP = {
    "name": "warmup",
    "pous": [
        {
            "name": "Counter",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    n : INT;\n    t : TON;\nEND_VAR",
            "body": "t(IN := n < 5, PT := T#10ms);\nIF t.Q THEN\n    n := n + 1;\nEND_IF;",
        },
        {
            "name": "Rung",
            "kind": "program",
            "language": "ld",
            "declarations": "VAR\n    a, q : BOOL;\nEND_VAR",
            "body": {
                "networks": [
                    {
                        "id": "n1",
                        "elements": [
                            {"type": "contact", "id": "c", "var": "a"},
                            {"type": "coil", "id": "q", "var": "q"},
                        ],
                    }
                ]
            },
        },
        {
            "name": "Gate",
            "kind": "program",
            "language": "fbd",
            "declarations": "VAR\n    a, b, q : BOOL;\nEND_VAR",
            "body": {
                "networks": [
                    {
                        "id": "n1",
                        "nodes": [
                            {"type": "input", "id": "a", "expr": "a"},
                            {"type": "input", "id": "b", "expr": "b"},
                            {"type": "block", "id": "and", "call": "AND"},
                            {"type": "output", "id": "q", "var": "q"},
                        ],
                        "wires": [
                            {"from": {"node": "a", "pin": "OUT"}, "to": {"node": "and", "pin": "IN1"}},
                            {"from": {"node": "b", "pin": "OUT"}, "to": {"node": "and", "pin": "IN2"}},
                            {"from": {"node": "and", "pin": "OUT"}, "to": {"node": "q", "pin": "IN"}},
                        ],
                    }
                ]
            },
        },
        {
            "name": "List",
            "kind": "program",
            "language": "il",
            "declarations": "VAR\n    a, q : BOOL;\nEND_VAR",
            "body": "LD a\nJMPC done\nLDN q\ndone: ST q",
        },
    ],
}


def warm_up() -> None:
    """Build a small project in every variant a server uses, so their caches are filled before forking; build
    every pydantic model (they are built at first use: model/base.py), so no worker builds one."""
    build_all()
    project = Project.model_validate(_WARM_UP)
    for variant in ("monitor", "debug"):
        build = build_project(project, variant)
        assert build.compiled is not None, [d.message for d in build.diagnostics]
        build.simulation().cycle(2)


warm_up()
gc.collect()
gc.freeze()
