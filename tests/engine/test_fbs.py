"""Standard function blocks, scan by scan (spec SFB-10..SFB-21).

Each table row is one call: (scan clock in ms, inputs set before the call,
outputs expected after it). The rows pin down where implementations differ.
"""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.engine.stdlib import STANDARD_FBS, pins
from ladderlab.engine.stdlib.fbs import CTD, CTU, CTUD, F_TRIG, R_TRIG, RS, SR, TOF, TON, TP

T, F = True, False


def run(fb, rows):
    for number, (now, inputs, expected) in enumerate(rows):
        for pin, value in inputs.items():
            setattr(fb, pin, value)
        fb.execute(now)
        actual = {pin: getattr(fb, pin) for pin in expected}
        assert actual == expected, f"row {number} (t={now} ms, inputs {inputs})"


# --- SFB-10: bistables ----------------------------------------------------------------------------


def test_sr_is_set_dominant_SFB_10():
    run(
        SR(),
        [
            (0, {}, {"Q1": F}),
            (0, {"S1": T}, {"Q1": T}),
            (0, {"S1": F}, {"Q1": T}),  # latched
            (0, {"R": T}, {"Q1": F}),
            (0, {"S1": T}, {"Q1": T}),  # S1 and R both TRUE: set wins
            (0, {"S1": F}, {"Q1": F}),
        ],
    )


def test_rs_is_reset_dominant_SFB_10():
    run(
        RS(),
        [
            (0, {}, {"Q1": F}),
            (0, {"S": T}, {"Q1": T}),
            (0, {"S": F}, {"Q1": T}),
            (0, {"S": T, "R1": T}, {"Q1": F}),  # both TRUE: reset wins
            (0, {"R1": F}, {"Q1": T}),
            (0, {"S": F, "R1": T}, {"Q1": F}),
        ],
    )


# --- SFB-11, SFB-12: edges ------------------------------------------------------------------------


def test_r_trig_pulses_on_a_first_call_with_clk_true_SFB_11():
    run(
        R_TRIG(),
        [
            (0, {"CLK": T}, {"Q": T, "M": T}),  # M starts FALSE
            (0, {}, {"Q": F}),
            (0, {"CLK": F}, {"Q": F, "M": F}),
            (0, {"CLK": T}, {"Q": T}),
            (0, {}, {"Q": F}),
        ],
    )


def test_f_trig_has_no_pulse_on_a_first_call_with_clk_false_SFB_12():
    run(
        F_TRIG(),
        [
            (0, {"CLK": F}, {"Q": F}),  # [REC]: no spurious edge at start-up
            (0, {"CLK": T}, {"Q": F}),
            (0, {"CLK": F}, {"Q": T}),
            (0, {}, {"Q": F}),
        ],
    )


def test_f_trig_after_a_first_call_with_clk_true_SFB_12():
    run(F_TRIG(), [(0, {"CLK": T}, {"Q": F}), (0, {"CLK": F}, {"Q": T}), (0, {}, {"Q": F})])


@given(st.lists(st.booleans(), max_size=30))
def test_edge_detectors_pulse_exactly_on_changes(clocks):
    rising, falling = R_TRIG(), F_TRIG()
    previous = False
    for clk in clocks:
        rising.CLK = falling.CLK = clk
        rising.execute(0)
        falling.execute(0)
        assert (clk and not previous) == rising.Q
        assert (previous and not clk) == falling.Q
        previous = clk


# --- SFB-13..15, SFB-21: counters -----------------------------------------------------------------


def test_ctu_counts_rising_edges_SFB_21():
    run(
        CTU(),
        [
            (0, {"PV": 3}, {"CV": 0, "Q": F}),
            (0, {"CU": T}, {"CV": 1, "Q": F}),
            (0, {}, {"CV": 1}),  # holding CU does not count again
            (0, {"CU": F}, {"CV": 1}),
            (0, {"CU": T}, {"CV": 2}),
            (0, {"CU": F}, {"CV": 2}),
            (0, {"CU": T}, {"CV": 3, "Q": T}),
            (0, {"CU": F}, {"CV": 3, "Q": T}),
            (0, {"CU": T}, {"CV": 4, "Q": T}),  # counts on past PV (up to the type's maximum)
            (0, {"R": T}, {"CV": 0, "Q": F}),
            (0, {"CU": F}, {"CV": 0}),
            (0, {"CU": T}, {"CV": 0, "Q": F}),  # CU and R both TRUE: R wins
            (0, {"R": F, "CU": F}, {"CV": 0}),
        ],
    )


@pytest.mark.parametrize(
    "cls, top",
    [
        (CTU, 32767),
        (STANDARD_FBS["CTU_DINT"], 2**31 - 1),
        (STANDARD_FBS["CTU_UDINT"], 2**32 - 1),
        (STANDARD_FBS["CTU_ULINT"], 2**64 - 1),
    ],
)
def test_ctu_stops_at_the_largest_value_of_its_type_SFB_13(cls, top):
    fb = cls()
    fb.CV, fb.PV = top - 1, 5
    run(fb, [(0, {"CU": T}, {"CV": top, "Q": T}), (0, {"CU": F}, {}), (0, {"CU": T}, {"CV": top})])


def test_ctd_counts_down_past_zero_SFB_21():
    run(
        CTD(),
        [
            (0, {"PV": 2, "LD": T}, {"CV": 2, "Q": F}),
            (0, {"LD": F, "CD": T}, {"CV": 1, "Q": F}),  # CD's rising edge counts (CD went TRUE after LD)
            (0, {"CD": F}, {"CV": 1}),
            (0, {"CD": T}, {"CV": 0, "Q": T}),
            (0, {"CD": F}, {}),
            (0, {"CD": T}, {"CV": -1, "Q": T}),
            (0, {}, {"CV": -1}),  # held: no count
            (0, {"CD": F, "LD": T}, {"CV": 2, "Q": F}),
            (0, {"CD": T}, {"CV": 2}),  # LD wins over a CD edge
        ],
    )


def test_ctd_first_call_with_cd_true_is_an_edge_SFB_14():
    run(CTD(), [(0, {"CD": T}, {"CV": -1, "Q": T})])


@pytest.mark.parametrize(
    "cls, bottom", [(CTD, -32768), (STANDARD_FBS["CTD_LINT"], -(2**63)), (STANDARD_FBS["CTD_UDINT"], 0)]
)
def test_ctd_stops_at_the_smallest_value_of_its_type_SFB_14(cls, bottom):
    fb = cls()
    fb.CV = bottom + 1
    run(fb, [(0, {"CD": T}, {"CV": bottom, "Q": T}), (0, {"CD": F}, {}), (0, {"CD": T}, {"CV": bottom})])


def test_ctud_SFB_15_and_SFB_21():
    run(
        CTUD(),
        [
            (0, {"PV": 2}, {"CV": 0, "QU": F, "QD": T}),
            (0, {"CU": T}, {"CV": 1, "QU": F, "QD": F}),
            (0, {"CU": F}, {}),
            (0, {"CU": T}, {"CV": 2, "QU": T, "QD": F}),
            (0, {"CU": F}, {}),
            (0, {"CU": T, "CD": T}, {"CV": 2}),  # both edges in one call: nothing
            (0, {"CU": T, "CD": F}, {"CV": 2}),  # CU held: no edge
            (0, {"CD": T}, {"CV": 1, "QU": F}),  # CD edge while CU is held TRUE: counts down
            (0, {"CU": F, "CD": F}, {}),
            (0, {"LD": T, "PV": 7}, {"CV": 7, "QU": T}),
            (0, {"R": T}, {"CV": 0, "QD": T}),  # R wins over LD
            (0, {"R": F, "LD": F, "CU": T}, {"CV": 1}),
            (0, {"CU": F, "CD": T, "LD": T}, {"CV": 7}),  # LD wins over a CD edge
        ],
    )


def test_ctud_limits_follow_the_type():
    fb = STANDARD_FBS["CTUD_UDINT"]()
    run(fb, [(0, {"CD": T}, {"CV": 0, "QD": T}), (0, {"CD": F, "CU": T}, {"CV": 1})])
    fb = CTUD()
    fb.CV = 32767
    run(fb, [(0, {"CU": T}, {"CV": 32767}), (0, {"CU": F}, {}), (0, {"CD": T}, {"CV": 32766})])


def test_counter_type_is_a_constructor_parameter():
    fb = CTU("DINT")
    fb.CV = 32767
    run(fb, [(0, {"CU": T, "PV": 1}, {"CV": 32768})])
    fb.reset()
    assert (fb.CV, fb.CU, fb.Q) == (0, F, F)
    fb.CV = 2**31 - 1
    run(fb, [(0, {"CU": T}, {"CV": 2**31 - 1})])  # still DINT after reset
    with pytest.raises(ValueError, match="integer type"):
        CTU("REAL")


# --- SFB-16..20: timers ---------------------------------------------------------------------------


def test_ton_SFB_20():
    run(
        TON(),
        [
            (0, {"IN": T, "PT": 500}, {"Q": F, "ET": 0}),  # the clock starts at 0
            (100, {}, {"Q": F, "ET": 100}),
            (400, {}, {"Q": F, "ET": 400}),
            (500, {}, {"Q": T, "ET": 500}),  # Q at ET >= PT
            (600, {}, {"Q": T, "ET": 500}),  # ET clamps at PT
            (700, {"IN": F}, {"Q": F, "ET": 0}),
            (800, {"IN": T}, {"Q": F, "ET": 0}),
            (1100, {"IN": F}, {"Q": F, "ET": 0}),  # 300 ms pulse never sets Q
            (1300, {"IN": T}, {"Q": F, "ET": 0}),
            (1799, {}, {"Q": F, "ET": 499}),
            (1800, {}, {"Q": T, "ET": 500}),
        ],
    )


def test_ton_reads_pt_on_every_call_SFB_19():
    run(
        TON(),
        [
            (0, {"IN": T, "PT": 1000}, {"Q": F}),
            (300, {"PT": 200}, {"Q": T, "ET": 200}),  # shorter than already elapsed: done at once
            (400, {"PT": 1000}, {"Q": F, "ET": 400}),  # longer again: keeps timing from the same start
            (1000, {}, {"Q": T, "ET": 1000}),
            (1100, {"PT": -5}, {"Q": T, "ET": 0}),  # a negative PT acts as T#0s
        ],
    )


def test_ton_with_pt_zero_is_immediate():
    run(TON(), [(7, {"IN": T}, {"Q": T, "ET": 0}), (8, {"IN": F}, {"Q": F})])


def test_tof_SFB_20():
    run(
        TOF(),
        [
            (0, {"PT": 500}, {"Q": F, "ET": 0}),  # cold start with IN FALSE
            (100, {"IN": T}, {"Q": T, "ET": 0}),
            (999, {}, {"Q": T, "ET": 0}),
            (1000, {"IN": F}, {"Q": T, "ET": 0}),
            (1400, {}, {"Q": T, "ET": 400}),
            (1500, {}, {"Q": F, "ET": 500}),
            (1600, {}, {"Q": F, "ET": 500}),  # ET stays at PT while IN stays FALSE
            (1700, {"IN": T}, {"Q": T, "ET": 0}),
            (1800, {"IN": F}, {"Q": T, "ET": 0}),
            (2000, {"IN": T}, {"Q": T, "ET": 0}),  # back before PT: Q never dropped
            (2100, {"IN": F}, {"Q": T, "ET": 0}),
            (2599, {"PT": 300}, {"Q": F, "ET": 300}),  # PT shortened while running
        ],
    )


def test_tp_SFB_20():
    run(
        TP(),
        [
            (0, {"IN": T, "PT": 500}, {"Q": T, "ET": 0}),
            (100, {"IN": F}, {"Q": T, "ET": 100}),  # Q stays for PT whatever IN does
            (200, {"IN": T}, {"Q": T, "ET": 200}),  # a second rising edge is ignored
            (300, {"IN": F}, {"Q": T, "ET": 300}),
            (400, {}, {"Q": T, "ET": 400}),
            (500, {}, {"Q": F, "ET": 0}),  # ends; IN already FALSE so ET returns to 0
        ],
    )


def test_tp_holds_et_at_pt_while_in_stays_true_SFB_16():
    run(
        TP(),
        [
            (0, {"IN": T, "PT": 300}, {"Q": T}),
            (300, {}, {"Q": F, "ET": 300}),
            (900, {}, {"Q": F, "ET": 300}),  # IN held: no new pulse, ET stays at PT
            (1000, {"IN": F}, {"Q": F, "ET": 0}),
            (1100, {"IN": T}, {"Q": T, "ET": 0}),  # a new rising edge: a new pulse
            (1400, {}, {"Q": F, "ET": 300}),
        ],
    )


def test_tp_ignores_an_edge_in_the_call_where_the_pulse_ends():
    run(
        TP(),
        [
            (0, {"IN": T, "PT": 300}, {"Q": T}),
            (100, {"IN": F}, {"Q": T}),
            (300, {"IN": T}, {"Q": F, "ET": 300}),  # the edge happened while the pulse ran
            (400, {}, {"Q": F}),
            (500, {"IN": F}, {"ET": 0}),
        ],
    )


def test_tp_with_pt_zero_gives_no_pulse():
    run(TP(), [(0, {"IN": T}, {"Q": F, "ET": 0}), (10, {"IN": F}, {"Q": F, "ET": 0})])


@given(start=st.integers(0, 10**12), steps=st.lists(st.tuples(st.integers(0, 400), st.booleans()), max_size=25))
def test_ton_matches_its_definition_at_any_clock(start, steps):
    """Q = IN has been TRUE for at least PT; ET = min(time since IN rose, PT), 0 while IN is FALSE."""
    fb, now, rose = TON(), start, None
    fb.PT = 500
    for delta, value in steps:
        now += delta
        rose = (now if rose is None else rose) if value else None
        fb.IN = value
        fb.execute(now)
        elapsed = 0 if rose is None else now - rose
        assert (rose is not None and elapsed >= 500, min(elapsed, 500)) == (fb.Q, fb.ET)


# --- instances: cold state, pins, registry ------------------------------------------------------------


@pytest.mark.parametrize(
    "name, pin_names",
    [
        ("SR", ["S1", "R", "Q1"]),
        ("RS", ["S", "R1", "Q1"]),
        ("R_TRIG", ["CLK", "Q", "M"]),
        ("F_TRIG", ["CLK", "Q", "M"]),
        ("CTU", ["CU", "R", "PV", "Q", "CV"]),
        ("CTD", ["CD", "LD", "PV", "Q", "CV"]),
        ("CTUD", ["CU", "CD", "R", "LD", "PV", "QU", "QD", "CV"]),
        ("TP", ["IN", "PT", "Q", "ET"]),
        ("TON", ["IN", "PT", "Q", "ET"]),
        ("TOF", ["IN", "PT", "Q", "ET"]),
    ],
)
def test_pins_are_named_as_iec_and_start_at_their_defaults_SFB_02(name, pin_names):
    fb = STANDARD_FBS[name]()
    snapshot = pins(fb)
    assert sorted(snapshot) == sorted(pin_names)
    assert all(value in (False, 0) for value in snapshot.values())
    assert not hasattr(fb, "__dict__")  # __slots__ only: a typo in generated code fails loudly


@pytest.mark.parametrize("name", sorted(STANDARD_FBS))
def test_reset_returns_to_the_cold_state(name):
    fb, fresh = STANDARD_FBS[name](), STANDARD_FBS[name]()
    for pin in (*fb.INPUTS, *fb.OUTPUTS):
        setattr(fb, pin, 1 if pin in ("PV", "PT", "CV", "ET") else True)
    fb.execute(1000)
    fb.reset()
    fb.execute(2000)
    fresh.execute(2000)
    assert pins(fb) == pins(fresh)


def test_every_standard_fb_is_registered_SFB_01():
    expected = {"SR", "RS", "R_TRIG", "F_TRIG", "CTU", "CTD", "CTUD", "TP", "TON", "TOF"}
    expected |= {f"{c}_{t}" for c in ("CTU", "CTD", "CTUD") for t in ("INT", "DINT", "LINT", "UDINT", "ULINT")}
    expected |= {"ACTION_CONTROL", "SFC_STEP"}  # what SFC charts are lowered to (IEC 61131-3 figure 15, docs/sfc.md)
    assert set(STANDARD_FBS) == expected
