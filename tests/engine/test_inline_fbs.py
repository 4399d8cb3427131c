"""Standard FB calls inlined into the fast and monitor code (issue 27, codegen/inline_fbs.py): the pasted body is
the FB's own ``execute``, so it must act exactly as calling it, call after call, whatever the inputs and the clock;
a mocked instance (another class) is still called and counted."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.engine.codegen.inline_fbs import inline_body
from ladderlab.engine.stdlib import STANDARD_FBS

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
    cls = STANDARD_FBS[name]
    called, pasted = cls(), cls()
    body = compile("\n".join(inline_body(name, "ll_fb", "now")), f"<inline {name}>", "exec")
    now = 0
    for flags, preset, step in calls:
        now += step
        for fb in (called, pasted):
            for pin, flag in zip([p for p in cls.INPUTS if p not in ("PT", "PV")], flags):
                setattr(fb, pin, flag)
            if "PT" in cls.INPUTS:
                fb.PT = preset
            if "PV" in cls.INPUTS:
                fb.PV = preset // 10
        called.execute(now)
        exec(body, {}, {"ll_fb": pasted, "now": now})
        assert _slots(pasted) == _slots(called)


def test_a_mocked_timer_is_called_not_inlined():
    sim = simulation(
        "PROGRAM Main VAR t : TON; go : BOOL := TRUE; END_VAR t(IN := go, PT := T#20ms); END_PROGRAM",
    )
    assert "if ll_fb.__class__ is fb_TON:" in sim.compiled.source
    sim.cycle(3)
    assert sim.read("MAIN.T.Q") is True
    timer = sim.value(sim.location("MAIN.T"))
    sim.mock(timer)
    sim.write("MAIN.GO", False)
    sim.cycle(2)
    assert sim.mocks.count(timer) == 2
    assert sim.read("MAIN.T.Q") is True  # the body did not run: IN FALSE would have reset Q
