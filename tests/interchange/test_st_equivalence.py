"""Equivalence is the contract (issue 8): the exported ST of an LD/FBD program, parsed back and run, gives the
same variable trace as the diagram over 200 scans of random writes (st_support.same_traces).

Programs: hypothesis-generated rungs (the generators of tests/ir/test_diagram_equivalence.py: series/parallel
trees of no/nc/p/n contacts, one to three coils of any mode, an ADD box with EN) drawn as LD and as FBD, with
forward jumps and returns added at random (IF structure when the jumps nest, the state machine when they cross),
and the motor example.
"""

from __future__ import annotations

import importlib
import inspect

import pytest
from hypothesis import given
from hypothesis import strategies as st

import tests.ir.test_diagram_equivalence as generated
from ladderlab.model import ld
from ladderlab.model.project import Pou
from ladderlab.storage.load import load_project_path
from tests.interchange.st_support import as_st, same_traces
from tests.ir.diagram_support import fjump, fret, project, wire

MOTOR = "examples/motor"

controls = st.lists(st.one_of(st.none(), st.none(), st.integers(0, 7), st.just("return")), min_size=4, max_size=4)


def with_controls(pou: Pou, choices: list) -> Pou:
    """Label every network and end some with a forward jump or a return, fed by the rung's power."""
    networks = pou.body.networks
    for index, network in enumerate(networks):
        network.label = f"L{index}"
        choice = choices[index]
        ahead = len(networks) - index - 1
        if choice is None or (choice != "return" and ahead == 0):
            continue
        element = f"ctl{index}"
        if pou.language == "ld":
            network.elements.append(
                ld.Return(id=element)
                if choice == "return"
                else ld.Jump(id=element, target=f"L{index + 1 + choice % ahead}")
            )
            continue
        source = next(w.from_ for w in network.wires if w.to.node.startswith("out"))
        network.nodes.append(fret(element) if choice == "return" else fjump(element, f"L{index + 1 + choice % ahead}"))
        network.wires.append(wire(f"{source.node}.{source.pin}", f"{element}.IN"))
    return pou


@given(st.lists(generated.rungs, min_size=1, max_size=4), controls, st.integers(0, 2**16))
def test_property_exported_ld_and_fbd_run_like_the_diagrams(program, choices, seed):
    for pou in (generated.ld_program(program), generated.fbd_program(program)):
        same_traces(project(with_controls(pou, choices)), seed=seed)


def test_motor_example_exports_and_runs_like_the_diagrams():
    trace = same_traces(load_project_path(MOTOR))
    assert any(row["MOTOR"] for row in trace) and any(row["STARTCOUNT"] for row in trace)


# ------------------------------------------------------------------ every diagram program of the suite

DIAGRAM_TESTS = [
    "test_diagram_examples",
    "test_diagram_mixed",
    "test_diagram_probes",
    "test_diagram_plcopen_examples",
    "test_lower_ld",
    "test_lower_fbd",
]


def _test_functions() -> list[tuple[str, str]]:
    found = []
    for module_name in DIAGRAM_TESTS:
        module = importlib.import_module(f"tests.ir.{module_name}")
        for name, function in vars(module).items():
            if name.startswith("test_") and callable(function) and not hasattr(function, "hypothesis"):
                found.append((module_name, name))
    return found


def _calls(function) -> list[dict]:
    """The keyword arguments of every parametrized case of a test function (one empty call otherwise)."""
    cases = [{}]
    for mark in getattr(function, "pytestmark", []):
        if mark.name != "parametrize":
            continue
        names = [n.strip() for n in mark.args[0].split(",")] if isinstance(mark.args[0], str) else mark.args[0]
        values = [v.values if hasattr(v, "values") and not isinstance(v, (tuple, dict)) else v for v in mark.args[1]]
        values = [v if len(names) > 1 else (v,) for v in values]
        cases = [{**case, **dict(zip(names, value))} for case in cases for value in values]
    parameters = inspect.signature(function).parameters
    return [case for case in cases if set(parameters) <= set(case)]


def _recorded_projects(module_name: str, test_name: str, monkeypatch) -> list:
    """Run the test and record every project it simulates or lowers successfully."""
    module = importlib.import_module(f"tests.ir.{module_name}")
    recorded: dict[str, object] = {}

    def recorder(real):
        def record(*pous, globals: str = "", **options):
            result = real(*pous, globals=globals, **options)
            built = project(*pous, globals=globals)
            recorded.setdefault(built.model_dump_json(), built)
            return result

        return record

    for helper in ("simulate", "lower_ok"):
        if hasattr(module, helper):
            monkeypatch.setattr(module, helper, recorder(getattr(module, helper)))
    function = getattr(module, test_name)
    for case in _calls(function):
        function(**case)
    return [p for p in recorded.values() if any(pou.language != "st" for pou in p.pous)]


@pytest.mark.parametrize("module_name, test_name", _test_functions())
def test_every_diagram_program_of_the_suite_exports_to_st_that_runs_identically(module_name, test_name, monkeypatch):
    for recorded in _recorded_projects(module_name, test_name, monkeypatch):
        if any(pou.kind == "program" for pou in recorded.pous):
            same_traces(recorded)
        else:
            as_st(recorded)  # function blocks and functions on their own: the export still checks


# ------------------------------------------------------------------ richer LD rungs

RICH = "VAR i0, i1, i2, o0, o1, o2 : BOOL; c0, c1 : INT; e : TIME; t0, t1 : TON; k0 : CTU; END_VAR"
BOOLS = ["i0", "i1", "i2", "o0", "o1", "o2"]


@st.composite
def rich_series(draw, depth: int = 0) -> list:
    """A series list of contacts, compares, coils anywhere (they pass the power on), nested parallels and boxes
    (TON, CTU with a series list on R, ADD with EN)."""
    kinds = ["contact", "contact", "coil", "compare"] + (["parallel", "box"] if depth < 2 else [])
    elements = []
    for kind in draw(st.lists(st.sampled_from(kinds), min_size=1, max_size=4)):
        if kind == "contact":
            elements.append(("contact", draw(st.sampled_from(BOOLS)), draw(st.sampled_from(["no", "nc", "p", "n"]))))
        elif kind == "coil":
            elements.append(
                (
                    "coil",
                    draw(st.sampled_from(BOOLS[3:])),
                    draw(st.sampled_from(["normal", "negated", "set", "reset", "p", "n"])),
                )
            )
        elif kind == "compare":
            elements.append(
                (
                    "compare",
                    draw(st.sampled_from(["GT", "LE", "EQ", "NE"])),
                    draw(st.sampled_from(["c0", "c1"])),
                    draw(st.integers(0, 6)),
                )
            )
        elif kind == "parallel":
            elements.append(("parallel", draw(st.lists(rich_series(depth + 1), min_size=2, max_size=3))))
        else:
            elements.append(("box", draw(st.sampled_from(["TON", "CTU", "ADD"])), draw(rich_series(depth + 1))))
    return elements


def rich_elements(series: list, ids) -> list:
    built = []
    for item in series:
        if item[0] == "contact":
            built.append(ld.Contact(id=ids("k"), var=item[1], mode=item[2]))
        elif item[0] == "coil":
            built.append(ld.Coil(id=ids("q"), var=item[1], mode=item[2]))
        elif item[0] == "compare":
            built.append(ld.Compare(id=ids("cmp"), op=item[1], left=item[2], right=str(item[3])))
        elif item[0] == "parallel":
            built.append(ld.Parallel(id=ids("p"), branches=[rich_elements(b, ids) for b in item[1]]))
        elif item[1] == "TON":
            built.append(
                ld.Box(
                    id=ids("ton"),
                    call="TON",
                    instance=f"t{ids.count % 2}",
                    inputs={"PT": "T#30ms"},
                    outputs={"ET": "e"} if ids.count % 3 == 0 else {},
                )
            )
        elif item[1] == "CTU":
            built.append(
                ld.Box(
                    id=ids("ctu"),
                    call="CTU",
                    instance="k0",
                    inputs={"PV": "3", "R": rich_elements(item[2], ids)},
                    outputs={"CV": "c0"},
                )
            )
        else:
            built.append(
                ld.Box(id=ids("add"), call="ADD", en=True, inputs={"IN1": "c1", "IN2": "1"}, outputs={"OUT": "c1"})
            )
    return built


@given(st.lists(rich_series(), min_size=1, max_size=4), st.integers(0, 2**16))
def test_property_rich_ld_rungs_export_to_st_that_runs_identically(program, seed):
    ids = generated._Ids()
    networks = [
        ld.LdNetwork(id=f"n{index}", elements=rich_elements(series, ids)) for index, series in enumerate(program)
    ]
    pou = Pou(name="Main", kind="program", language="ld", declarations=RICH, body=ld.LdBody(networks=networks))
    same_traces(project(pou), seed=seed)
