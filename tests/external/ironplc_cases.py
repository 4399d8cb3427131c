"""Runs one IronPLC end-to-end case (../shared/external/ironplc/end_to_end_cases.json) on our engine.

The case format and value conventions are the MANIFEST's: scans with ``set`` and
absolute ``time_ms``, ``expect`` after the last scan or ``expect_after_scan``,
DATE/DT in seconds, TIME/TOD in ms (our LTIME/LTOD/LDATE/LDT count ns), enums as ordinals, ``tolerance`` / ``float_compare`` for REALs,
and ``{"op": ...}`` matchers. ``run_case`` returns None on success or why it failed.
"""

from __future__ import annotations

import math
import struct

from ladderlab.engine.simulation import Simulation
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project

#: The case's unit for a type -> ours: DATE/DT are seconds there and ms here, the long forms ms/seconds there and ns here.
_SCALE = {
    **dict.fromkeys(("DATE", "DT", "DATE_AND_TIME"), 1000),
    **dict.fromkeys(("LDATE", "LDT", "LDATE_AND_TIME"), 1_000_000_000),
    **dict.fromkeys(("LTIME", "LTOD", "LTIME_OF_DAY"), 1_000_000),
}


def run_case(case: dict) -> str | None:
    project, diagnostics = source_to_project(case["source"], "case")
    if project is not None and _libraries(case):  # ``library=Tc2_Math``: the project uses that vendor library
        project = project.model_copy(update={"libraries": _libraries(case)})
    refused = any(d.severity == "error" for d in diagnostics)  # a POU that does not parse is not in ``project``
    build = build_project(project) if project is not None and not refused else None
    compiled = build is not None and build.compiled is not None
    if case["kind"] == "compile_error":
        return None if not compiled else f"compiled, expected the error: {case['error']}"
    if not compiled:
        found = diagnostics if build is None else build.diagnostics
        errors = [d.format() for d in found if d.severity == "error"]
        return "does not compile: " + "; ".join(errors[:2])
    if case.get("compile_only"):
        return None
    sim = build.simulation()
    prefix = _program_prefix(sim, project)
    checkpoints = {int(k): v for k, v in case.get("expect_after_scan", {}).items()}
    if "expect" in case:
        checkpoints[len(case["scans"]) - 1] = case["expect"]
    for index, scan in enumerate(case["scans"]):
        for name, value in scan.get("set", {}).items():
            sim.write(prefix(name), _to_engine(value, case.get("var_types", {}).get(name)))
        sim.scan_at(max(scan.get("time_ms", 0), sim.time_ms))
        if sim.fault is not None:
            if case["kind"] == "runtime_error":
                return None
            return f"scan {index}: fault {sim.fault.text()}"
        for name, expected in checkpoints.get(index, {}).items():
            problem = _compare(sim.read(prefix(name)), expected, case, name)
            if problem:
                return f"scan {index}: {name}: {problem}"
    if case["kind"] == "runtime_error":
        return f"no fault, expected {case['error']}"
    return None


def _libraries(case: dict) -> list[str]:
    options = (case.get("options") or "").split(",")
    return [option.strip().removeprefix("library=") for option in options if option.strip().startswith("library=")]


def _program_prefix(sim: Simulation, project):
    """Paths "in the PROGRAM's scope" (the MANIFEST): through its instance - named after it, or the one a
    CONFIGURATION declares (``PROGRAM inst WITH task : main``) - else a global."""
    programs = [p.name for p in project.pous if p.kind == "program"]
    instances = [
        p if isinstance(p, str) else p.name
        for task in project.all_tasks()
        for p in task.programs
        if (p if isinstance(p, str) else p.type).upper() in {n.upper() for n in programs}
    ]
    roots = instances[:1] if len(instances) == 1 else programs[:1] if len(programs) == 1 else []

    def path(name: str) -> str:
        for root in roots:
            try:
                sim.location(f"{root}.{name}")
                return f"{root}.{name}"
            except (KeyError, ValueError):
                pass
        return name  # a global

    return path


def _to_engine(value, type_text: str | None):
    if type_text and type_text.split()[0].upper() in _SCALE and isinstance(value, (int, float)):
        return int(value * _SCALE[type_text.split()[0].upper()])
    return value


def _compare(actual, expected, case: dict, name: str) -> str | None:
    type_text = (case.get("var_types", {}).get(name) or "").split()[0].upper() if case.get("var_types") else ""
    if type_text in _SCALE and isinstance(expected, (int, float)):
        expected = expected * _SCALE[type_text]
    if isinstance(expected, dict) and "op" in expected:
        return _matcher(actual, expected)
    if isinstance(expected, float) or (
        isinstance(actual, float) and isinstance(expected, int) and not isinstance(expected, bool)
    ):
        if not isinstance(actual, (int, float)) or isinstance(actual, bool):
            return f"{actual!r} != {expected!r}"
        if "tolerance" in case:
            return (
                None
                if abs(actual - expected) < case["tolerance"]
                else f"{actual!r} != {expected!r} ± {case['tolerance']}"
            )
        if case.get("float_compare") == "f32":
            expected = struct.unpack("f", struct.pack("f", expected))[0]
        return None if actual == expected else f"{actual!r} != {expected!r}"
    if isinstance(expected, list) and isinstance(actual, list):
        return None if actual == expected else f"{actual!r} != {expected!r}"
    if isinstance(expected, bool) or isinstance(actual, bool):  # TRUE is not 1
        return None if actual is expected else f"{actual!r} != {expected!r}"
    return None if actual == expected else f"{actual!r} != {expected!r}"


def _matcher(actual, spec: dict) -> str | None:
    op = spec["op"]
    ok = {
        "nan": lambda: isinstance(actual, float) and math.isnan(actual),
        "pos_inf": lambda: actual == math.inf,
        "neg_inf": lambda: actual == -math.inf,
        "neg_zero": lambda: actual == 0 and math.copysign(1, actual) < 0,
        "ne": lambda: actual != spec["value"],
        "gt": lambda: actual > spec["value"],
        "approx": lambda: abs(actual - spec["value"]) <= spec["tol"],
    }[op]()
    return None if ok else f"{actual!r} does not satisfy {spec}"
