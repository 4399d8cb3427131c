"""Standard FB calls inlined into the fast and monitor code (issue 27, codegen/inline_fbs.py): the pasted body is
the FB's own ``execute``, so it must act exactly as calling it, call after call, whatever the inputs and the clock,
also where it reads its inputs from the locals they were just assigned; in a unit test program a mocked instance
(another class) is still called and counted, and only there is the body guarded by the instance's class."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.engine.codegen.inline_fbs import inline_body
from ladderlab.engine.compile import compile_program
from ladderlab.engine.simulation import Simulation
from ladderlab.engine.stdlib import STANDARD_FBS
from ladderlab.ir.lower_project import lower_project
from ladderlab.st.project_text import source_to_project

from ..support import fuzz_settings
from .test_simulation_st import simulation

INLINED = ["SR", "RS", "R_TRIG", "F_TRIG", "CTU", "CTD", "CTUD", "TP", "TON", "TOF", "CTU_DINT", "CTUD_ULINT"]


def _slots(obj: object) -> dict[str, object]:
    names = {name for cls in type(obj).__mro__ for name in getattr(cls, "__slots__", ())}
    return {name: getattr(obj, name) for name in sorted(names)}


def test_the_ten_standard_fbs_and_the_typed_counters_are_inlined():
    assert all(inline_body(name, "ll_fb", "now") is not None for name in INLINED)


@pytest.mark.parametrize("name", INLINED)
@fuzz_settings(fast=20)
@given(
    calls=st.lists(
        st.tuples(st.lists(st.booleans(), min_size=5, max_size=5), st.integers(-5, 60), st.integers(0, 30)), max_size=25
    )
)
def test_the_inlined_body_acts_as_the_call(name, calls):
    """Pasted as it is, and with every input read from the local it was just assigned (``known``)."""
    cls = STANDARD_FBS[name]
    called, pasted, known = cls(), cls(), cls()
    body = compile("\n".join(inline_body(name, "ll_fb", "now")), f"<inline {name}>", "exec")
    locals_ = tuple((pin, f"ll_t_{pin}") for pin in cls.INPUTS)
    with_locals = compile("\n".join(inline_body(name, "ll_fb", "now", locals_)), f"<inline {name}>", "exec")
    assert all(
        f"ll_fb.{pin}" not in line
        for line in inline_body(name, "ll_fb", "now", locals_)
        for pin in cls.INPUTS
        if not line.lstrip().startswith(f"ll_fb.{pin} =")
    )
    # each output also stored into a local where the body can (every path stores it): the local holds the output
    copying = {
        pin: (cls(), compile("\n".join(lines), f"<inline {name} into {pin}>", "exec"))
        for pin in cls.OUTPUTS
        if (lines := inline_body(name, "ll_fb", "now", locals_, (pin, "ll_t_out"))) is not None
    }
    now = 0
    for flags, preset, step in calls:
        now += step
        inputs = dict(zip([p for p in cls.INPUTS if p not in ("PT", "PV")], flags))
        inputs |= {"PT": preset} if "PT" in cls.INPUTS else {}
        inputs |= {"PV": preset // 10} if "PV" in cls.INPUTS else {}
        for fb in (called, pasted, known, *(fb for fb, _ in copying.values())):
            for pin, value in inputs.items():
                setattr(fb, pin, value)
        called.execute(now)
        exec(body, {}, {"ll_fb": pasted, "now": now})
        exec(with_locals, {}, {"ll_fb": known, "now": now} | {f"ll_t_{pin}": value for pin, value in inputs.items()})
        assert _slots(pasted) == _slots(called) == _slots(known)
        for pin, (fb, code) in copying.items():
            frame = {"ll_fb": fb, "now": now, "ll_t_out": "stale"} | {f"ll_t_{p}": v for p, v in inputs.items()}
            exec(code, {}, frame)
            assert _slots(fb) == _slots(called)
            assert frame["ll_t_out"] == getattr(called, pin)


def test_an_output_is_copied_into_a_local_only_where_every_path_stores_it():
    """A TON stores Q on both of its paths, a TOF not when the delay is over (Q keeps its value): only the first
    can hand Q on in a local (``inline_fbs._output_copied``); a body that reads the local as an input cannot."""
    ton = inline_body("TON", "ll_fb", "now", (("IN", "ll_t_in"),), ("Q", "ll_t_q"))
    assert ton is not None
    assert "    ll_fb._running = ll_fb.Q = ll_t_q = False" in ton
    assert "        ll_fb.Q = ll_t_q = True" in ton and "        ll_fb.ET = ll_s_pt if ll_s_pt > 0 else 0" in ton
    assert inline_body("TOF", "ll_fb", "now", (), ("Q", "ll_t_q")) is None
    assert inline_body("TON", "ll_fb", "now", (("IN", "ll_t_q"),), ("Q", "ll_t_q")) is None
    assert inline_body("SR", "ll_fb", "now", (), ("Q1", "ll_t_q")) is not None


def test_a_timer_hands_its_q_to_the_next_box_in_the_local_it_stores():
    """LD ``--[TON]--[CTU]--``: the fast code stores the TON's Q into the power-flow local where the body stores
    Q, instead of reading ``ll_fb.Q`` back after it; the values are IEC's (SFB-17: Q after PT, SFB-13: CU counts
    rising edges)."""
    sim = simulation(
        "PROGRAM Main VAR t : TON; k : CTU; go : BOOL; n : INT; END_VAR\n"
        "t(IN := go, PT := T#20ms); k(CU := t.Q, PV := 2); n := k.CV; END_PROGRAM",
    )
    sim.write("MAIN.GO", True)
    sim.cycle(1)
    assert sim.read("MAIN.T.Q") is False
    sim.run_for(30)
    assert sim.read("MAIN.T.Q") is True and sim.read("MAIN.K.CV") == 1 and sim.read("MAIN.N") == 1
    sim.write("MAIN.GO", False)
    sim.cycle(1)
    assert sim.read("MAIN.T.Q") is False and sim.read("MAIN.T.ET") == 0
    sim.write("MAIN.GO", True)
    sim.run_for(30)
    assert sim.read("MAIN.K.CV") == 2 and sim.read("MAIN.K.Q") is True


def test_a_simulation_pastes_the_body_without_a_class_guard_and_refuses_a_mock():
    sim = simulation(
        "PROGRAM Main VAR t : TON; go : BOOL := TRUE; END_VAR t(IN := go, PT := T#20ms); END_PROGRAM",
    )
    assert "fb_TON" not in sim.compiled.source.split("# ---- fast variant")[1]
    sim.cycle(3)
    assert sim.read("MAIN.T.Q") is True
    with pytest.raises(RuntimeError, match="MOCK needs a program lowered with its unit tests"):
        sim.mock(sim.value(sim.location("MAIN.T")))


def test_a_mocked_timer_of_a_unit_test_program_is_called_not_inlined():
    project, diagnostics = source_to_project(
        "PROGRAM Main VAR t : TON; go : BOOL := TRUE; END_VAR t(IN := go, PT := T#20ms); END_PROGRAM", "test"
    )
    assert project is not None, diagnostics
    lowered = lower_project(project)
    assert lowered.program is not None
    lowered.program.mockable = True  # as ir/lower_tests.py lowers a test file's program
    sim = Simulation(compile_program(lowered.program, "fast"))
    assert "if ll_fb.__class__ is fb_TON:" in sim.compiled.source
    sim.cycle(3)
    assert sim.read("MAIN.T.Q") is True
    timer = sim.value(sim.location("MAIN.T"))
    sim.mock(timer)
    sim.write("MAIN.GO", False)
    sim.cycle(2)
    assert sim.mocks.count(timer) == 2
    assert sim.read("MAIN.T.Q") is True  # the body did not run: IN FALSE would have reset Q
