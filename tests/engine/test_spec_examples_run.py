"""The spec's worked ST examples (tests/st/data/spec_examples.json) run with their stated results.

tests/st/test_spec_examples.py checks the front end's verdict; this runs every
runnable example on the engine: function calls with arguments (through a small
calling PROGRAM), initial values, values after N scans, and input cases.
"""

from __future__ import annotations

import json
import math
import pathlib

import pytest

from ladderlab.engine.simulation import Simulation
from ladderlab.model import Pou, Project
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project

DATA = json.loads((pathlib.Path(__file__).parents[1] / "st" / "data" / "spec_examples.json").read_text("utf-8"))
EXAMPLES = {e["id"]: e for e in DATA["examples"] if e["check"] == "ok"}
HARNESS = "SpecHarness"


def _literal(value) -> str:
    if isinstance(value, bool):
        return "TRUE" if value else "FALSE"
    return repr(value)


def _build(example: dict, extra: list[Pou] = ()) -> tuple[Project, Simulation]:
    project, diagnostics = source_to_project(example["source"], example["id"])
    assert project is not None, diagnostics
    project = project.model_copy(update={"pous": [*project.pous, *extra]})
    build = build_project(project)
    assert build.compiled is not None, [d.format() for d in build.diagnostics]
    return project, build.simulation()


def _harness(project: Project, calls: list[dict], instances: set[str]) -> Pou:
    """A PROGRAM that calls each function once with the stated arguments and holds FB instances to inspect."""
    returns = {p.name.upper(): p.return_type for p in project.pous if p.kind == "function"}
    decls = [f"r{i} : {returns[call['function'].upper()]};" for i, call in enumerate(calls)]
    decls += [f"i_{fb} : {fb};" for fb in sorted(instances)]
    body = [
        f"r{i} := {call['function']}({', '.join(f'{k} := {_literal(v)}' for k, v in call['args'].items())});"
        for i, call in enumerate(calls)
    ]
    return Pou(
        name=HARNESS,
        kind="program",
        language="st",
        declarations="VAR\n" + "\n".join(decls) + "\nEND_VAR",
        body="\n".join(body),
    )


def _path(sim: Simulation, project: Project, name: str) -> str:
    """A program's variable, a global, or (``FbType.var``) a variable of the harness's instance of that FB."""
    head = name.split(".")[0].split("[")[0].upper()
    if head in {p.name.upper() for p in project.pous if p.kind == "function_block"}:
        return f"{HARNESS}.i_{name}"
    for pou in project.pous:
        if pou.kind == "program" and pou.name != HARNESS:
            try:
                sim.location(f"{pou.name}.{name}")
                return f"{pou.name}.{name}"
            except (KeyError, ValueError):
                continue
    return name


def _same(actual, expected, tolerance: float | None = None) -> bool:
    if isinstance(expected, float):
        return math.isclose(actual, expected, abs_tol=tolerance or 0, rel_tol=0 if tolerance else 1e-7)
    return actual == expected


def _run_expectations(example: dict, expect: dict, sets: dict | None = None) -> None:
    calls = expect.get("calls", [])
    fb_types = {name.split(".")[0] for name in expect.get("initial", {}) if "." in name}
    project, _ = source_to_project(example["source"], example["id"])
    fbs = {p.name for p in project.pous if p.kind == "function_block"} & fb_types
    extra = [_harness(project, calls, fbs)] if calls or fbs else []
    project, sim = _build(example, extra)
    for name, value in expect.get("initial", {}).items():
        assert _same(sim.read(_path(sim, project, name)), value), name
    for name, value in (sets or {}).items():
        sim.write(_path(sim, project, name), value)
    done = 0
    for after, values in sorted(expect.get("after_scans", {}).items(), key=lambda kv: int(kv[0])):
        sim.cycle(int(after) - done)
        done = int(after)
        assert sim.fault is None, sim.fault.text()
        for name, value in values.items():
            assert _same(sim.read(_path(sim, project, name)), value), (name, sim.read(_path(sim, project, name)))
    if calls:
        sim.cycle(1)
        assert sim.fault is None, sim.fault.text()
        results = [sim.read(f"{HARNESS}.r{i}") for i in range(len(calls))]
        for call, result in zip(calls, results):
            assert _same(result, call["result"], call.get("tolerance")), (call, result)


RUNNABLE = [k for k, e in EXAMPLES.items() if set(e.get("expect", {})) & {"calls", "initial", "after_scans"}]


@pytest.mark.parametrize("example_id", RUNNABLE)
def test_example_runs_with_the_stated_results(example_id):
    example = EXAMPLES[example_id]
    _run_expectations(example, example["expect"])


@pytest.mark.parametrize(
    "example_id, index",
    [(k, i) for k, e in EXAMPLES.items() for i, _ in enumerate(e.get("expect", {}).get("cases", []))],
)
def test_example_input_cases(example_id, index):
    case = EXAMPLES[example_id]["expect"]["cases"][index]
    _run_expectations(EXAMPLES[example_id], case, case.get("set"))


def test_ex03_star_delta_motor_scenario():
    """EX-03 (VAR-22, POU-24): km2 (delta) goes TRUE 12 s after a rising edge on sb1; km1/km3 stay FALSE."""
    project, sim = _build(EXAMPLES["EX-03"])
    interval = sim.tasks[0].interval_ms
    sim.cycle(1)
    sim.write("sb1", True)
    sim.cycle(1)
    started = sim.time_ms
    trace = []
    while sim.time_ms - started < 13_000:
        sim.cycle(1)
        trace.append((sim.time_ms - started, sim.read("km2"), sim.read("km1"), sim.read("km3")))
    first_on = next(elapsed for elapsed, km2, _, _ in trace if km2)
    assert first_on == 12_000 - 12_000 % interval
    assert not any(km1 or km3 for _, _, km1, km3 in trace)
