"""The lowering's outcome for a set of programs, to compare two checkouts: a speed change must not change it.

For each program: the sha256 of ``repr`` of the lowered program, the lowering's and the ST checker's diagnostics
(``repr``, every field) and the sha256 of the checked symbols (every field but an object's address), or the
exception a build raised. The programs: the benchmark's LD programs (diagrams.py; 1, 7, 100 and 2,003 networks)
and an FBD one, every example's start, the spec's worked ST examples (tests/st/data/spec_examples.json) and 400
seeded random projects whose declarations mix what the declaration checks look at (names declared twice, keywords
and invalid names, FB instances with and without FB_init arguments, edges, initial values, AT, CONSTANT, RETAIN,
VAR_EXTERNAL).

    python benchmarks/lowering_digest.py --backend /tmp/base/backend base.json
    python benchmarks/lowering_digest.py branch.json
    python benchmarks/lowering_digest.py --compare base.json branch.json

Without an output file (as ``make bench`` runs it) it prints the number of programs and one sha256 of them all.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import pathlib
import random
import re
import subprocess
import sys
from typing import Any

ROOT = pathlib.Path(__file__).resolve().parents[1]
NETWORKS = (1, 7, 100, 2003)
RANDOM_PROJECTS = 400
_CHILD = "LADDERLAB_DIGEST_CHILD"
_ADDRESS = re.compile(r" at 0x[0-9a-f]+")  # an object's default repr (the checker's ERROR type): not an outcome
#: the POUs and types the random declarations use (tests/st/test_declaration_checks.py declares against them too)
LIBRARY = """TYPE MyStruct : STRUCT x : INT; END_STRUCT; END_TYPE
FUNCTION_BLOCK Fb
VAR_INPUT n : INT := 1; END_VAR
END_FUNCTION_BLOCK
FUNCTION_BLOCK ABSTRACT Abstract
END_FUNCTION_BLOCK
FUNCTION_BLOCK Fb2
VAR n : INT; END_VAR
METHOD FB_init : BOOL
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; n : INT; END_VAR
END_METHOD
END_FUNCTION_BLOCK
VAR_GLOBAL a : BOOL; q : INT; END_VAR
"""
_NAMES = ["a", "B1", "Start", "x_1", "_t", "motorOn", "IN", "q", "x__y", "end_", "INT", "T1", "DINT"]
_TYPES = [
    *("BOOL", "int", "TON", "STRING", "MyStruct", "LREAL", "Fb", "Fb(3)", "Fb(n := 2)", "Fb2", "Fb2(n := 2)"),
    *("ARRAY [0..1] OF Fb[(n := 1), (n := 2)]", "POINTER TO INT", "Abstract", "Unknown", "STRING[5]"),
]
_EXTRAS = ["", "", "", " := TRUE", " := 3", " R_EDGE"]
_KINDS = ["VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_TEMP", "VAR CONSTANT", "VAR RETAIN", "VAR_EXTERNAL"]


def random_source(rng: random.Random) -> str:
    """A program or function block of random declarations (``_NAMES``, ``_TYPES``...) after ``LIBRARY``."""
    blocks = []
    for _ in range(rng.randint(1, 3)):
        decls = []
        for _ in range(rng.randint(0, 5)):
            names = ", ".join(rng.choice(_NAMES) for _ in range(rng.randint(1, 3)))
            if rng.random() < 0.1:
                decls.append(f"{names.split(',')[0]} AT %IX0.{rng.randint(0, 7)} : {rng.choice(_TYPES)};")
            else:
                decls.append(f"{names} : {rng.choice(_TYPES)}{rng.choice(_EXTRAS)};")
        blocks.append(f"{rng.choice(_KINDS)}\n  " + "\n  ".join(decls) + "\nEND_VAR")
    kind = rng.choice(["PROGRAM", "FUNCTION_BLOCK"])
    return LIBRARY + f"{kind} Main\n" + "\n".join(blocks) + f"\n;\nEND_{kind}\n"


def digest(project: Any) -> dict[str, Any] | str:
    from ladderlab.ir.lower_project import lower_project
    from ladderlab.st.checker import check_project

    try:
        checked = check_project(project)
        lowered = lower_project(project)
    except Exception as error:  # (a build that raises is an outcome too)
        return f"raised {type(error).__name__}: {error}"
    symbols = [
        (key, _ADDRESS.sub("", repr(symbol)), str(symbol.type))
        for table in [*(info.symbols for info in checked.pous.values()), checked.globals]
        for key, symbol in table.items()
    ]
    return {
        "program": hashlib.sha256(repr(lowered.program).encode()).hexdigest(),
        "diagnostics": [repr(d) for d in lowered.diagnostics],
        "check": [repr(d) for d in checked.diagnostics],
        "symbols": hashlib.sha256(repr(symbols).encode()).hexdigest(),
    }


def digests() -> dict[str, Any]:
    from benchmarks.diagrams import project
    from ladderlab.examples import example_names, example_project
    from ladderlab.st.project_text import source_to_project

    out: dict[str, Any] = {f"ld {n}": digest(project("ld", n)) for n in NETWORKS}
    out["fbd 500"] = digest(project("fbd", 500))
    out.update({f"example {name}": digest(example_project(name, name)) for name in example_names()})
    examples = json.loads((ROOT / "tests/st/data/spec_examples.json").read_text(encoding="utf-8"))["examples"]
    rng = random.Random(27)
    sources = [(f"spec {e['id']}", e["source"]) for e in examples]
    sources += [(f"random {i}", random_source(rng)) for i in range(RANDOM_PROJECTS)]
    for name, source in sources:
        parsed, diagnostics = source_to_project(source, "p")
        out[name] = digest(parsed) if parsed is not None else [repr(d) for d in diagnostics]
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("output", nargs="?", help="the JSON file to write")
    parser.add_argument("--backend", help="the backend directory to lower with (default this checkout's)")
    parser.add_argument("--compare", nargs=2, metavar="JSON", help="compare two outputs: the programs that differ")
    args = parser.parse_args()
    if args.compare:
        first, second = (json.loads(pathlib.Path(name).read_text()) for name in args.compare)
        differ = sorted(key for key in first.keys() | second.keys() if first.get(key) != second.get(key))
        print(f"{len(first)} / {len(second)} programs, {len(differ)} differ: {', '.join(differ[:20])}")
        sys.exit(1 if differ else 0)
    if os.environ.get(_CHILD) is None:  # a process whose ladderlab is the backend's, imported first (diagrams.py
        backend = pathlib.Path(args.backend or ROOT / "backend").resolve()  # puts this checkout's on the path)
        environment = {**os.environ, "PYTHONPATH": f"{backend}{os.pathsep}{ROOT}", _CHILD: "1"}
        subprocess.run([sys.executable, __file__, *[args.output] * bool(args.output)], check=True, env=environment)
        return
    import ladderlab  # noqa: F401

    os.environ["LADDERLAB_MAX_SOURCE_CHARACTERS"] = str(100 * max(NETWORKS))
    text = json.dumps(digests(), indent=0, sort_keys=True)
    if args.output:
        pathlib.Path(args.output).write_text(text)
    else:
        total = hashlib.sha256(text.encode()).hexdigest()
        print(f"{len(json.loads(text))} programs lowered, all together sha256 {total}")


if __name__ == "__main__":
    main()
