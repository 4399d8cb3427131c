"""Power-flow probes (issue 5 "Power-flow probes", ON-09): what the scan computed per element, and what ran."""

from __future__ import annotations

from tests.ir.diagram_support import (
    blk,
    box,
    coil,
    contact,
    fbd_pou,
    fjump,
    inp,
    jump,
    ld_pou,
    net,
    out,
    parallel,
    rung,
    simulate,
)

DECL = "VAR a, b, skip, q, r : BOOL; n : INT; t1 : TON; END_VAR"


def scan(sim, **inputs):
    for name, value in inputs.items():
        sim.write(f"Main.{name}", value)
    sim.cycle(1)
    return sim.probes("Main")


def test_ld_probes_are_each_elements_right_side_power():
    """The right side of a contact is its power AND its variable; a coil and a parallel pass theirs on."""
    sim = simulate(
        ld_pou(
            "Main",
            DECL,
            rung(
                "n",
                contact("ca", "a"),
                parallel("p", [contact("cb", "b", "nc")], [contact("cq", "q")]),
                coil("out", "q"),
            ),
        ),
        variant="debug",
    )
    view = scan(sim, a=True, b=True)
    assert view.values == {"ca": True, "cb": False, "cq": False, "p": False, "out": False}
    view = scan(sim, b=False)
    assert view.values == {"ca": True, "cb": True, "cq": False, "p": True, "out": True}
    view = scan(sim, a=False)
    assert view.values == {"ca": False, "cb": False, "cq": False, "p": False, "out": False}
    assert view.executed == {"ca", "cb", "cq", "p", "out"}


def test_elements_skipped_by_a_jump_did_not_execute_and_keep_their_last_value():
    sim = simulate(
        ld_pou(
            "Main",
            DECL,
            rung("n1", contact("k", "skip"), jump("j", "end")),
            rung("n2", contact("ca", "a"), coil("cq", "q")),
            rung("n3", label="end"),
        ),
        variant="debug",
    )
    assert scan(sim, skip=False, a=True).executed == {"k", "j", "ca", "cq"}
    view = scan(sim, skip=True, a=False)
    assert view.executed == {"k", "j"}
    assert view.values == {"k": True, "j": True, "ca": True, "cq": True}


def test_a_box_with_en_false_did_not_execute():
    sim = simulate(
        ld_pou(
            "Main",
            DECL,
            rung(
                "n",
                contact("ca", "a"),
                box("add", "ADD", en=True, IN1="n", IN2="1", outputs={"OUT": "n"}),
                coil("cq", "q"),
            ),
        ),
        variant="debug",
    )
    view = scan(sim, a=True)
    assert view.values == {"ca": True, "add": True, "add.OUT": 1, "cq": True}
    view = scan(sim, a=False)
    assert view.executed == {"ca", "cq"} and view.values["add.OUT"] == 1 and view.values["cq"] is False


def test_fbd_probes_every_output_pin_and_every_input_node():
    sim = simulate(
        fbd_pou(
            "Main",
            DECL,
            net(
                "n",
                [
                    inp("x", "a"),
                    inp("pt", "T#20ms"),
                    blk("t", "TON", "t1"),
                    blk("neg", "NOT"),
                    out("o", "q"),
                    out("o2", "r"),
                ],
                [("x.OUT", "t.IN"), ("pt.OUT", "t.PT"), ("t.Q", "o.IN"), ("t.Q", "neg.IN"), ("neg.OUT", "o2.IN")],
            ),
        ),
        variant="debug",
    )
    assert scan(sim, a=True).values == {
        "x": True,
        "pt": 20,
        "t.Q": False,
        "t.ET": 0,
        "neg.OUT": True,
        "o": False,
        "o2": True,
    }
    scan(sim)
    assert scan(sim).values == {"x": True, "pt": 20, "t.Q": True, "t.ET": 20, "neg.OUT": False, "o": True, "o2": False}


def test_fbd_jump_skips_the_probes_of_the_networks_it_passes():
    sim = simulate(
        fbd_pou(
            "Main",
            DECL,
            net("n1", [inp("k", "skip"), fjump("j", "L")], [("k.OUT", "j.IN")]),
            net("n2", [inp("x", "a"), out("o", "q")], [("x.OUT", "o.IN")]),
            net("n3", [], [], label="L"),
        ),
        variant="debug",
    )
    assert scan(sim, skip=True).executed == {"k", "j"}
    assert scan(sim, skip=False).executed == {"k", "j", "x", "o"}


def test_fast_variant_has_no_probe_code():
    """Invariant 6: with monitoring off the probes cost nothing - they are not in the generated code."""
    sim = simulate(ld_pou("Main", DECL, rung("n", contact("ca", "a"), coil("cq", "q"))))
    assert (
        "'ca'" not in sim.compiled.source
        and "'ca'"
        in simulate(
            ld_pou("Main", DECL, rung("n", contact("ca", "a"), coil("cq", "q"))), variant="debug"
        ).compiled.source
    )
