"""The monitor variant's chunks with probes are compiled at first use (issue 27 item 3, engine/compile.py).

A chunk function of the monitor variant holding networks with probes has a twin without probes that runs while none
of its networks is viewed (docs/runtime.md, "Viewed networks"). Building the variant compiles the twins only;
``Simulation.view`` compiles the chunks of the networks it turns on before the next scan, and a chunk called before
that (a new simulation records every network) is compiled by its first call. Whatever the path, every value is the
one the debug variant, which records every probe and has no lazy code, shows for the same scans: the reference.
"""

from __future__ import annotations

from types import CodeType

import pytest

from ladderlab.engine.codegen import chunks
from ladderlab.engine.compile import CompiledProgram
from ladderlab.engine.simulation import Simulation
from ladderlab.model import ld
from ladderlab.model.project import Pou, Project, Task
from ladderlab.simulation.build import build_project
from ladderlab.simulation.runner import SimRunner
from tests.engine.test_viewed_networks import _Frames  # a client's power flow, from the frames

NETWORKS = 12


def _project(divide_in: int | None = None) -> Project:
    """MAIN: network n is ``--| A |--|/ B |--( Cn )--`` (A, B inputs), or a DIV by Y at network ``divide_in``."""
    networks = []
    for n in range(NETWORKS):
        elements: list = [ld.Contact(id=f"a{n}", var="A"), ld.Contact(id=f"b{n}", var="B", mode="nc")]
        if n == divide_in:
            elements.append(
                ld.Box(id=f"d{n}", call="DIV", en=True, inputs={"IN1": "X", "IN2": "Y"}, outputs={"OUT": "X"})
            )
        elements.append(ld.Coil(id=f"c{n}", var=f"C{n}"))
        networks.append(ld.LdNetwork(id=f"n{n}", elements=elements))
    coils = " ".join(f"C{n} : BOOL;" for n in range(NETWORKS))
    declarations = f"VAR A : BOOL := TRUE; B : BOOL; X : INT := 7; Y : INT := 1; {coils} END_VAR"
    pou = Pou(name="Main", kind="program", language="ld", declarations=declarations, body=ld.LdBody(networks=networks))
    return Project(name="p", pous=[pou], tasks=[Task(name="main", interval="T#10ms", programs=["Main"])])


def _build(project: Project, variant: str) -> CompiledProgram:
    with pytest.MonkeyPatch.context() as patch:  # chunks of one network or so: each chunk with probes has a twin
        patch.setattr(chunks, "CHUNK_STATEMENTS", 3)
        build = build_project(project, variant)
    assert build.compiled is not None, [d.message for d in build.diagnostics]
    return build.compiled


def _compiled_later(compiled: CompiledProgram) -> set[str]:
    """The functions of the pieces compiled after the build, by name."""
    return {compiled.generated.lazy[index].function for index in compiled.compiled_later}


def _network_ids(n: int) -> list[str]:
    return [f"a{n}", f"b{n}", f"c{n}"]


def _shown(sim: Simulation, ids: list[str]) -> dict[str, object]:
    view = sim.probes("Main", ids)
    assert not view.unknown & set(ids)
    return {e: view.values.get(e) if e in view.executed else None for e in ids}


def _chunk_of(compiled: CompiledProgram, network: int) -> str:
    table = compiled.generated.context.probes_of("MAIN")
    run = table.network_of[table.index(f"a{network}")]
    (function,) = [p.function for p in compiled.generated.lazy.values() if run in p.runs]
    return function


def test_the_monitor_build_compiles_no_chunk_with_probes():
    compiled = _build(_project(), "monitor")
    lazy = compiled.generated.lazy
    assert len(lazy) >= NETWORKS // 2  # several chunks, each with its twin
    assert all(compiled.pieces[index] is None for index in lazy)
    assert all(f"def {piece.function}(self, now):" in compiled.source for piece in lazy.values())
    assert all(code is not None for index, code in enumerate(compiled.pieces) if index not in lazy)
    sim = Simulation(compiled)
    sim.view({})
    assert sim.cycle(3) == 3 and sim.read("Main.C0") is True
    assert compiled.compiled_later == {}  # nobody viewed a network: only the twins ran


def test_a_view_started_on_a_running_simulation_is_exact_from_its_first_frame():
    """The chunks of the networks viewed are compiled by ``view``, before the scan; the others stay uncompiled."""
    project = _project()
    compiled, reference = _build(project, "monitor"), Simulation(_build(project, "debug"))
    sim = Simulation(compiled)
    sim.view({})
    for scan in range(6):
        if scan == 2:
            sim.view({"Main": _network_ids(5)})
            assert _compiled_later(compiled) == {_chunk_of(compiled, 5)}
        if scan == 4:
            sim.view({"Main": _network_ids(5) + _network_ids(9)})
        for sim_ in (sim, reference):
            sim_.write("Main.B", scan % 2 == 1)
        assert sim.cycle(1) == reference.cycle(1) == 1
        assert sim.snapshot() == reference.snapshot()
        if scan >= 2:
            assert _shown(sim, _network_ids(5)) == _shown(reference, _network_ids(5)), scan
        if scan >= 4:
            assert _shown(sim, _network_ids(9)) == _shown(reference, _network_ids(9)), scan
    assert _compiled_later(compiled) == {_chunk_of(compiled, 5), _chunk_of(compiled, 9)}
    assert _shown(reference, _network_ids(9)) == {"a9": True, "b9": False, "c9": False}  # B was TRUE last


def test_a_new_simulation_records_every_network_compiling_each_chunk_at_its_first_call():
    project = _project()
    compiled, reference = _build(project, "monitor"), Simulation(_build(project, "debug"))
    sim = Simulation(compiled)  # no view: every network records, as a new simulation does
    assert sim.cycle(1) == reference.cycle(1) == 1
    assert len(compiled.compiled_later) == len(compiled.generated.lazy)
    every = [e for n in range(NETWORKS) for e in _network_ids(n)]
    assert _shown(sim, every) == _shown(reference, every)
    assert _shown(sim, _network_ids(0)) == {"a0": True, "b0": True, "c0": True}


def test_a_view_started_on_a_stopped_simulation_shows_the_last_scan_exactly():
    """The runner reads a network viewed after the last scan from the history's replay of that scan, whose code is
    its own (``own_code``): its chunks with probes are compiled there, the live simulation's stay uncompiled."""
    project = _project()
    compiled, reference = _build(project, "monitor"), Simulation(_build(project, "debug"))
    frames = _Frames()
    runner = SimRunner(Simulation(compiled), frames, history_bytes=1 << 24)
    for scan in range(3):
        runner.write("Main.B", scan == 1)
        reference.write("Main.B", scan == 1)
        runner.single_cycle()
        reference.cycle(1)
    runner._settle(publish=True)
    runner.watch("client", [], [("Main", _network_ids(7))])
    runner._settle(publish=True)
    assert frames.power["MAIN"] == _shown(reference, _network_ids(7))
    assert frames.power["MAIN"] == {"a7": True, "b7": True, "c7": True}
    runner.single_cycle()  # the next scan records network 7 live, with the chunk compiled when it was viewed
    runner._settle(publish=True)
    reference.cycle(1)
    assert _compiled_later(compiled) == {_chunk_of(compiled, 7)}
    assert frames.power["MAIN"] == _shown(reference, _network_ids(7))


def test_a_breakpoint_set_before_any_debug_build_halts_and_the_monitor_code_comes_back(monkeypatch):
    monkeypatch.setattr(chunks, "CHUNK_STATEMENTS", 3)  # the debug variant compiled by the runner too
    project = _project()
    compiled = _build(project, "monitor")
    runner = SimRunner(Simulation(compiled), _Frames(), history_bytes=1 << 24)
    runner.single_cycle()
    assert runner.sim.variant_program("debug") is None
    runner.set_breakpoint("Main", network="n6")  # compiles the debug variant now
    assert runner.sim.variant == "debug"
    runner.single_cycle()
    assert runner.sim.halted is not None and runner.sim.halted.origin.network == "n6"
    runner.clear_breakpoint()
    runner.resume()
    runner._settle(publish=True)
    assert runner.sim.halted is None and runner.sim.variant == "monitor"
    runner.watch("client", [], [("Main", _network_ids(6))])  # the monitor code again, its chunk compiled now
    runner.single_cycle()
    runner._settle(publish=True)
    assert _compiled_later(compiled) == {_chunk_of(compiled, 6)}
    assert isinstance(runner.sim._ns[_chunk_of(compiled, 6)].__code__, CodeType)
    assert _shown(runner.sim, _network_ids(6)) == {"a6": True, "b6": True, "c6": True}


def test_a_fault_in_a_chunk_compiled_at_first_use_is_reported_as_in_the_fast_variant():
    project = _project(divide_in=8)
    reports = []
    for variant in ("fast", "monitor"):
        sim = Simulation(_build(project, variant))
        sim.write("Main.Y", 0)
        if variant == "monitor":
            sim.view({"Main": _network_ids(8)})
            assert _compiled_later(sim.compiled) == {_chunk_of(sim.compiled, 8)}
        sim.cycle(1)
        assert sim.fault is not None
        reports.append(sim.fault.diagnostic().message)
    assert reports[0] == reports[1]
    assert "division by zero: 7 / 0 at POU MAIN, network 9, DIV" in reports[1]


def test_a_chunk_compiled_at_its_first_call_does_not_count_against_the_watchdog(monkeypatch):
    """The compile runs inside the scan when no view came first: the task's budget stops meanwhile. Here each
    compile takes 10 s of the watchdog's clock; the loop of the function network 11 calls checks the clock."""
    spin = Pou(
        name="Spin",
        kind="function",
        language="st",
        return_type="INT",
        declarations="VAR_INPUT N : INT; END_VAR VAR I : INT; END_VAR",
        body="FOR I := 1 TO N DO Spin := Spin + 1; END_FOR;",
    )
    project = _project()
    main = project.pous[0]
    call = ld.Box(id="s", call="SPIN", en=True, inputs={"N": "1000"}, outputs={"OUT": "X"})
    main.body.networks[-1].elements.insert(2, call)
    project = project.model_copy(update={"pous": [main, spin]})
    compiled = _build(project, "monitor")
    clock = [0.0]
    code = CompiledProgram.code

    def slow_code(self, index):
        clock[0] += 10.0
        return code(self, index)

    monkeypatch.setattr(CompiledProgram, "code", slow_code)
    sim = Simulation(compiled, watchdog_s=0.1, watchdog_clock=lambda: clock[0])
    assert sim.cycle(1) == 1 and sim.fault is None
    assert clock[0] == 10.0 * len(compiled.generated.lazy) and sim.read("Main.X") == 1000
