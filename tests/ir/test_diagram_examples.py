"""The worked examples of the spec, each as an LD and as an FBD network, run scan by scan in the engine.

One row per scan: inputs written before it, outputs read after it (spec §7 conventions).
"""

from __future__ import annotations

import itertools

import pytest

from ladderlab.engine.simulation import Simulation
from ladderlab.ir.lower_project import lower_project
from ladderlab.model.project import Pou
from tests.ir.diagram_support import (
    blk,
    box,
    coil,
    compare,
    contact,
    fbd_pou,
    fjump,
    fret,
    inp,
    jump,
    ld_pou,
    net,
    out,
    parallel,
    project,
    ret,
    rung,
    simulate,
    trace,
)

BOOLS = "VAR in1, in2, in3, in4, C, out1, x : BOOL; END_VAR"


def truth_table(count: int) -> list[dict[str, bool]]:
    return [
        {f"in{i + 1}": bit for i, bit in enumerate(bits)} for bits in itertools.product([False, True], repeat=count)
    ]


def inputs(names: list[str]) -> list:
    """One input node per variable, fed to the block pins IN1, IN2 ... of ``target``."""
    return [inp(f"i_{name}", name) for name in names]


# ------------------------------------------------------------------ series / parallel truth tables (LD-02, GR-14)

FORMULAS = {
    "C := in1 AND NOT in2": (
        2,
        lambda v: v["in1"] and not v["in2"],
        "C",
        ld_pou("Main", BOOLS, rung("n", contact("a", "in1"), contact("b", "in2", "nc"), coil("c", "C"))),
        fbd_pou(
            "Main",
            BOOLS,
            net(
                "n",
                [*inputs(["in1", "in2"]), blk("and", "AND", IN2={"negated": True}), out("o", "C")],
                [("i_in1.OUT", "and.IN1"), ("i_in2.OUT", "and.IN2"), ("and.OUT", "o.IN")],
            ),
        ),
    ),
    "C := in1 AND (in2 OR in3)": (
        3,
        lambda v: v["in1"] and (v["in2"] or v["in3"]),
        "C",
        ld_pou(
            "Main",
            BOOLS,
            rung("n", contact("a", "in1"), parallel("p", [contact("b", "in2")], [contact("c", "in3")]), coil("q", "C")),
        ),
        fbd_pou(
            "Main",
            BOOLS,
            net(
                "n",
                [*inputs(["in1", "in2", "in3"]), blk("or", "OR"), blk("and", "AND"), out("o", "C")],
                [
                    ("i_in2.OUT", "or.IN1"),
                    ("i_in3.OUT", "or.IN2"),
                    ("i_in1.OUT", "and.IN1"),
                    ("or.OUT", "and.IN2"),
                    ("and.OUT", "o.IN"),
                ],
            ),
        ),
    ),
    "out1 := in1 AND in2 AND (in3 OR in4)": (
        4,
        lambda v: v["in1"] and v["in2"] and (v["in3"] or v["in4"]),
        "out1",
        ld_pou(
            "Main",
            BOOLS,
            rung(
                "n",
                contact("a", "in1"),
                contact("b", "in2"),
                parallel("p", [contact("c", "in3")], [contact("d", "in4")]),
                coil("q", "out1"),
            ),
        ),
        fbd_pou(
            "Main",
            BOOLS,
            net(
                "n",
                [*inputs(["in1", "in2", "in3", "in4"]), blk("or", "OR"), blk("and", "AND"), out("o", "out1")],
                [
                    ("i_in3.OUT", "or.IN1"),
                    ("i_in4.OUT", "or.IN2"),
                    ("i_in1.OUT", "and.IN1"),
                    ("i_in2.OUT", "and.IN2"),
                    ("or.OUT", "and.IN3"),
                    ("and.OUT", "o.IN"),
                ],
            ),
        ),
    ),
    "x := in1 XOR in2 XOR NOT in3 (XOR box, negated input)": (
        3,
        lambda v: v["in1"] ^ v["in2"] ^ (not v["in3"]),
        "x",
        ld_pou(
            "Main",
            BOOLS,
            rung(
                "n",
                box(
                    "xor", "XOR", en=True, IN1="in1", IN2="in2", IN3=[contact("n3", "in3", "nc")], outputs={"OUT": "x"}
                ),
            ),
        ),
        fbd_pou(
            "Main",
            BOOLS,
            net(
                "n",
                [*inputs(["in1", "in2", "in3"]), blk("xor", "XOR", IN3={"negated": True}), out("o", "x")],
                [("i_in1.OUT", "xor.IN1"), ("i_in2.OUT", "xor.IN2"), ("i_in3.OUT", "xor.IN3"), ("xor.OUT", "o.IN")],
            ),
        ),
    ),
}


@pytest.mark.parametrize("language", ["ld", "fbd"])
@pytest.mark.parametrize("name", list(FORMULAS))
def test_truth_tables(name, language):
    count, oracle, output, ld_version, fbd_version = FORMULAS[name]
    rows = truth_table(count)
    sim = simulate(ld_version if language == "ld" else fbd_version)
    assert trace(sim, "Main", rows, [output]) == [(oracle(row),) for row in rows]


# ------------------------------------------------------------------ EN / ENO (LAB-01, LD-08)

ARITH = "VAR go, ok, big : BOOL; A, B, X : INT; END_VAR"
LAB01 = [
    ({"go": True, "A": 2, "B": 3}, (5, True, False)),
    ({"go": True, "A": 10, "B": -4}, (6, True, True)),
    ({"go": False, "A": 100, "B": 100}, (6, False, True)),
    ({"go": True, "A": 1, "B": 1}, (2, True, False)),
]
EN_ENO = {
    "ld": ld_pou(
        "Main",
        ARITH,
        rung(
            "n1",
            contact("g", "go"),
            box("add", "ADD", en=True, IN1="A", IN2="B", outputs={"OUT": "X"}),
            coil("e", "ok"),
        ),
        rung("n2", contact("g2", "go"), box("gt", "GT", en=True, IN1="A", IN2="B", outputs={"OUT": "big"})),
    ),
    "fbd": fbd_pou(
        "Main",
        ARITH,
        net(
            "n1",
            [inp("g", "go"), inp("a", "A"), inp("b", "B"), blk("add", "ADD", en=True), out("x", "X"), out("e", "ok")],
            [("g.OUT", "add.EN"), ("a.OUT", "add.IN1"), ("b.OUT", "add.IN2"), ("add.OUT", "x.IN"), ("add.ENO", "e.IN")],
        ),
        net(
            "n2",
            [inp("g2", "go"), inp("a2", "A"), inp("b2", "B"), blk("gt", "GT", en=True), out("o", "big")],
            [("g2.OUT", "gt.EN"), ("a2.OUT", "gt.IN1"), ("b2.OUT", "gt.IN2"), ("gt.OUT", "o.IN")],
        ),
    ),
}


@pytest.mark.parametrize("language", ["ld", "fbd"])
def test_lab01_add_and_gt_with_en_eno_keep_outputs_when_en_is_false(language):
    sim = simulate(EN_ENO[language])
    assert trace(sim, "Main", [row for row, _ in LAB01], ["X", "ok", "big"]) == [out for _, out in LAB01]


# ------------------------------------------------------------------ standard FBs

TRIG = "VAR clk, q : BOOL; rt : R_TRIG; END_VAR"


@pytest.mark.parametrize(
    "pou",
    [
        ld_pou("Main", TRIG, rung("n", contact("c", "clk"), box("r", "R_TRIG", "rt"), coil("o", "q"))),
        fbd_pou(
            "Main",
            TRIG,
            net("n", [inp("c", "clk"), blk("r", "R_TRIG", "rt"), out("o", "q")], [("c.OUT", "r.CLK"), ("r.Q", "o.IN")]),
        ),
    ],
    ids=["ld", "fbd"],
)
def test_sfb11_r_trig(pou):
    clk = [False, True, True, False, True, True]
    assert trace(simulate(pou), "Main", [{"clk": c} for c in clk], ["q"]) == [
        (False,),
        (True,),
        (False,),
        (False,),
        (True,),
        (False,),
    ]


TIMER = "VAR start, done : BOOL; t1 : TON; elapsed : TIME; END_VAR"


@pytest.mark.parametrize(
    "pou",
    [
        ld_pou(
            "Main",
            TIMER,
            rung(
                "n",
                contact("s", "start"),
                box("t", "TON", "t1", PT="T#10s", outputs={"ET": "elapsed"}),
                coil("d", "done"),
            ),
        ),
        fbd_pou(
            "Main",
            TIMER,
            net(
                "n",
                [inp("s", "start"), inp("pt", "T#10s"), blk("t", "TON", "t1"), out("d", "done"), out("e", "elapsed")],
                [("s.OUT", "t.IN"), ("pt.OUT", "t.PT"), ("t.Q", "d.IN"), ("t.ET", "e.IN")],
            ),
        ),
    ],
    ids=["ld", "fbd"],
)
def test_sfb17_ton_with_pt_10s(pou):
    """Scans every 100 ms; IN rises in scan 1 (t = 100 ms), so Q is TRUE from t = 10.1 s (scan 101)."""
    sim = simulate(pou, interval="T#100ms")
    rows = trace(sim, "Main", [{"start": True}] * 101 + [{"start": False}], ["done", "elapsed"])
    assert rows[0] == (False, 0) and rows[50] == (False, 5000)
    assert rows[99] == (False, 9900) and rows[100] == (True, 10000) and rows[101] == (False, 0)


COUNT = "VAR pulse, reached : BOOL; c1 : CTU; n : INT; END_VAR"


def test_sfb13_ctu_with_an_edge_contact_in_ld():
    """A P contact passes one pulse per rising edge; CTU counts them up to PV = 3."""
    pou = ld_pou(
        "Main",
        COUNT,
        rung("n", contact("p", "pulse", "p"), box("c", "CTU", "c1", PV="3", outputs={"CV": "n"}), coil("q", "reached")),
    )
    pulses = [True, True, False, True, False, True, True]
    assert trace(simulate(pou), "Main", [{"pulse": p} for p in pulses], ["n", "reached"]) == [
        (1, False),
        (1, False),
        (1, False),
        (2, False),
        (2, False),
        (3, True),
        (3, True),
    ]


def test_sfb13_ctu_with_a_falling_edge_pin_in_fbd():
    """The edge flag puts an F_TRIG in front of CU, so CTU counts the falling edges of the pulse."""
    pou = fbd_pou(
        "Main",
        COUNT,
        net(
            "n",
            [
                inp("p", "pulse"),
                inp("pv", "3"),
                blk("c", "CTU", "c1", CU={"edge": "falling"}),
                out("n", "n"),
                out("q", "reached"),
            ],
            [("p.OUT", "c.CU"), ("pv.OUT", "c.PV"), ("c.CV", "n.IN"), ("c.Q", "q.IN")],
        ),
    )
    pulses = [True, False, False, True, True, False, True, False]
    assert trace(simulate(pou), "Main", [{"pulse": p} for p in pulses], ["n", "reached"]) == [
        (0, False),
        (1, False),
        (1, False),
        (1, False),
        (1, False),
        (2, False),
        (2, False),
        (3, True),
    ]


UPDOWN = "VAR up, down, high : BOOL; ud : CTUD; level : INT; END_VAR"


@pytest.mark.parametrize(
    "pou",
    [
        ld_pou(
            "Main",
            UPDOWN,
            rung(
                "n",
                contact("u", "up"),
                box("c", "CTUD", "ud", CD=[contact("d", "down")], PV="2", outputs={"CV": "level"}),
                coil("h", "high"),
            ),
        ),
        fbd_pou(
            "Main",
            UPDOWN,
            net(
                "n",
                [
                    inp("u", "up"),
                    inp("d", "down"),
                    inp("pv", "2"),
                    blk("c", "CTUD", "ud"),
                    out("l", "level"),
                    out("h", "high"),
                ],
                [("u.OUT", "c.CU"), ("d.OUT", "c.CD"), ("pv.OUT", "c.PV"), ("c.CV", "l.IN"), ("c.QU", "h.IN")],
            ),
        ),
    ],
    ids=["ld", "fbd"],
)
def test_sfb15_ctud_with_cu_and_cd_from_contacts_and_cv_to_a_variable(pou):
    """CU and CD count rising edges; both in one scan change nothing (SFB-15); QU := CV >= PV carries the power."""
    scans = [
        (True, False),
        (False, False),
        (True, False),
        (False, True),
        (False, False),
        (True, True),
        (False, False),
        (False, True),
    ]
    assert trace(simulate(pou), "Main", [{"up": u, "down": d} for u, d in scans], ["level", "high"]) == [
        (1, False),
        (1, False),
        (2, True),
        (1, False),
        (1, False),
        (1, False),
        (1, False),
        (0, False),
    ]


# ------------------------------------------------------------------ set / reset (APB-01, LD-06)

LATCH = "VAR s, r, x : BOOL; END_VAR"


@pytest.mark.parametrize(
    "pou",
    [
        ld_pou(
            "Main",
            LATCH,
            rung("n1", contact("cs", "s"), coil("set", "x", "set")),
            rung("n2", contact("cr", "r"), coil("reset", "x", "reset")),
        ),
        fbd_pou(
            "Main",
            LATCH,
            net("n1", [inp("s", "s"), out("set", "x", "set")], [("s.OUT", "set.IN")]),
            net("n2", [inp("r", "r"), out("reset", "x", "reset")], [("r.OUT", "reset.IN")]),
        ),
    ],
    ids=["ld", "fbd"],
)
def test_apb01_set_and_reset_latch_and_reset_written_last_dominates(pou):
    scans = [(True, False), (False, False), (False, True), (False, False), (True, True), (True, False)]
    assert trace(simulate(pou), "Main", [{"s": s, "r": r} for s, r in scans], ["x"]) == [
        (True,),
        (True,),
        (False,),
        (False,),
        (False,),
        (True,),
    ]


# ------------------------------------------------------------------ jumps and returns (GR-07..10)

FLOW = "VAR skip, stop, a, y, z : BOOL; END_VAR"


@pytest.mark.parametrize(
    "pou",
    [
        ld_pou(
            "Main",
            FLOW,
            rung("n1", contact("k", "skip"), jump("j", "L")),
            rung("n2", contact("a", "a"), coil("y", "y")),
            rung("n3", contact("a3", "a"), coil("z", "z"), label="L"),
        ),
        fbd_pou(
            "Main",
            FLOW,
            net("n1", [inp("k", "skip"), fjump("j", "L")], [("k.OUT", "j.IN")]),
            net("n2", [inp("a", "a"), out("y", "y")], [("a.OUT", "y.IN")]),
            net("n3", [inp("a3", "a"), out("z", "z")], [("a3.OUT", "z.IN")], label="L"),
        ),
    ],
    ids=["ld", "fbd"],
)
def test_gr08_conditional_jump_over_a_network(pou):
    scans = [(True, True), (False, True), (True, False), (False, False)]
    assert trace(simulate(pou), "Main", [{"skip": k, "a": a} for k, a in scans], ["y", "z"]) == [
        (False, True),
        (True, True),
        (True, False),
        (False, False),
    ]


@pytest.mark.parametrize(
    "pou",
    [
        ld_pou("Main", FLOW, rung("n1", contact("s", "stop"), ret("r")), rung("n2", contact("a", "a"), coil("y", "y"))),
        fbd_pou(
            "Main",
            FLOW,
            net("n1", [inp("s", "stop"), fret("r")], [("s.OUT", "r.IN")]),
            net("n2", [inp("a", "a"), out("y", "y")], [("a.OUT", "y.IN")]),
        ),
    ],
    ids=["ld", "fbd"],
)
def test_gr10_conditional_return(pou):
    scans = [(False, True), (True, False), (False, False), (True, True)]
    assert trace(simulate(pou), "Main", [{"stop": s, "a": a} for s, a in scans], ["y"]) == [
        (True,),
        (True,),
        (False,),
        (False,),
    ]


def test_gr19_compare_contact():
    pou = ld_pou(
        "Main",
        "VAR n : INT; r : REAL; hot, low : BOOL; END_VAR",
        rung("n1", compare("gt", "GT", "n", "10"), coil("h", "hot")),
        rung("n2", compare("le", "LE", "r", "2.5"), coil("l", "low")),
    )
    scans = [{"n": 10, "r": 2.5}, {"n": 11, "r": 2.6}, {"n": -3, "r": -1.0}]
    assert trace(simulate(pou), "Main", scans, ["hot", "low"]) == [(False, True), (True, False), (False, True)]


def test_lab27_fire_alarm_in_ld_fbd_and_st_agree():
    """LD: votes as series/parallel contacts, (S) then (R) coils (reset dominant); FBD: AND/OR + RS; ST."""
    decl = "VAR d11, d12, d13, on1, off1, lamp1, alarm : BOOL; END_VAR"
    votes = parallel(
        "v",
        [contact("a1", "d11"), contact("a2", "d12")],
        [contact("b1", "d11"), contact("b3", "d13")],
        [contact("c2", "d12"), contact("c3", "d13")],
        [contact("o", "on1")],
    )
    ld_version = ld_pou(
        "Main",
        decl,
        rung(
            "lamp",
            parallel("any", [contact("l1", "d11")], [contact("l2", "d12")], [contact("l3", "d13")]),
            coil("lc", "lamp1"),
        ),
        rung("set", votes, coil("s", "alarm", "set")),
        rung("reset", contact("off", "off1"), coil("r", "alarm", "reset")),
    )
    names = ["d11", "d12", "d13", "on1", "off1"]
    fbd_version = fbd_pou(
        "Main",
        decl + " VAR rs : RS; END_VAR",
        net(
            "n",
            [
                *[inp(n, n) for n in names],
                blk("any", "OR"),
                out("lamp", "lamp1"),
                blk("p1", "AND"),
                blk("p2", "AND"),
                blk("p3", "AND"),
                blk("vote", "OR"),
                blk("rs", "RS", "rs"),
                out("alarm", "alarm"),
            ],
            [
                ("d11.OUT", "any.IN1"),
                ("d12.OUT", "any.IN2"),
                ("d13.OUT", "any.IN3"),
                ("any.OUT", "lamp.IN"),
                ("d11.OUT", "p1.IN1"),
                ("d12.OUT", "p1.IN2"),
                ("d11.OUT", "p2.IN1"),
                ("d13.OUT", "p2.IN2"),
                ("d12.OUT", "p3.IN1"),
                ("d13.OUT", "p3.IN2"),
                ("p1.OUT", "vote.IN1"),
                ("p2.OUT", "vote.IN2"),
                ("p3.OUT", "vote.IN3"),
                ("on1.OUT", "vote.IN4"),
                ("vote.OUT", "rs.S"),
                ("off1.OUT", "rs.R1"),
                ("rs.Q1", "alarm.IN"),
            ],
        ),
    )
    st_version = Pou(
        name="Main",
        kind="program",
        language="st",
        declarations=decl + " VAR rs : RS; END_VAR",
        body="lamp1 := d11 OR d12 OR d13;\n"
        "rs(S := (d11 AND d12) OR (d11 AND d13) OR (d12 AND d13) OR on1, R1 := off1);\n"
        "alarm := rs.Q1;",
    )
    scans = [
        {"d11": True, "d12": True},
        {"d11": False, "d12": False},
        {"off1": True},
        {"off1": False},
        {"d11": True, "d13": True, "off1": True},
        {"off1": False},
        {"d11": False, "d13": False, "on1": True},
        {"on1": False},
        {"d12": True},
    ]
    expected = [
        (True, True),
        (False, True),
        (False, False),
        (False, False),
        (True, False),
        (True, True),
        (False, True),
        (False, True),
        (True, True),
    ]
    for pou in (ld_version, fbd_version, st_version):
        assert trace(simulate(pou), "Main", scans, ["lamp1", "alarm"]) == expected, pou.language


def test_backward_jump_loops_within_one_scan_and_an_endless_one_trips_the_watchdog():
    """Invariant 4: backward jumps are allowed; n counts to 5 in one scan. Jumping back forever is a fault."""
    loop = ld_pou(
        "Main",
        "VAR n : INT; forever : BOOL; END_VAR",
        rung("count", box("inc", "ADD", en=True, IN1="n", IN2="1", outputs={"OUT": "n"}), label="again"),
        rung("test", compare("lt", "LT", "n", "5"), jump("back", "again")),
        rung("stuck", contact("f", "forever"), jump("spin", "again")),
    )
    sim = simulate(loop)
    assert trace(sim, "Main", [{"n": 0}], ["n"]) == [(5,)]
    spinning = Simulation(lower_project(project(loop)).program, watchdog_s=0.05)
    spinning.write("Main.forever", True)
    spinning.cycle(1)
    assert spinning.fault is not None and "watchdog" in spinning.fault.message.lower()
