"""Issue 22 item 5: LD/FBD problems name the network by number and label and the element by what is written on it
(operand, instance, call) and a box's pin - never an internal id; the ids stay in the machine fields."""

from __future__ import annotations

from ladderlab.ir.lower_project import lower_project
from ladderlab.model.fbd import FbdBody
from ladderlab.model.places import Places
from tests.ir.diagram_support import (
    blk,
    box,
    coil,
    compare,
    connector,
    contact,
    continuation,
    fjump,
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
)


def test_ld_elements_are_named_by_what_is_written_on_them():
    body = ld_pou(
        "Main",
        "",
        rung("a7", contact("c1", "Start"), contact("c2", "Stop", "nc"), coil("q1", "Motor"), label="Motor"),
        rung(
            "b3",
            parallel("p", [contact("c3", "A", "p")], [compare("k", "GE", "Level", "100")]),
            box("t", "TON", instance="RunTimer", PT="T#5s"),
            coil("q2", "Lamp", "set"),
        ),
        rung("x", box("s1", "ADD", en=True), box("s2", "ADD", en=True), box("m", "MUL", en=True), jump("j", "Motor")),
        rung("y", ret("r")),
    ).body
    places = Places(body)
    assert places.where("a7") == 'network 1 "Motor"'
    assert places.where("a7", "c1") == 'network 1 "Motor", contact Start'
    assert places.where("a7", "c2") == 'network 1 "Motor", NC contact Stop'
    assert places.where("a7", "q1") == 'network 1 "Motor", coil Motor'
    assert places.where("b3", "c3") == "network 2, P contact A"
    assert places.where("b3", "k") == "network 2, comparison Level >= 100"
    assert places.where("b3", "p") == "network 2, parallel branch"
    assert places.where("b3", "t", "PT") == "network 2, TON RunTimer.PT"
    assert places.where("b3", "q2") == "network 2, set coil Lamp"
    assert places.where("x", "s1", "IN1") == "network 3, the 1st ADD.IN1"
    assert places.where("x", "s2") == "network 3, the 2nd ADD"
    assert places.where("x", "m", "OUT") == "network 3, MUL.OUT"
    assert places.where("x", "j") == "network 3, jump to Motor"
    assert places.where("y", "r") == "network 4, RETURN"
    assert places.where("nowhere") is None
    assert places.where("y", "nothing") == "network 4"


def test_fbd_blocks_of_one_call_are_counted_top_to_bottom_then_left_to_right():
    body = net(
        "n1",
        [
            blk("low", "ADD", x=0, y=200),
            blk("high", "ADD", x=300, y=10),
            blk("mid", "ADD", x=10, y=100),
            inp("i", "T#2s"),
            out("o", "Level", "reset"),
            connector("k", "C1"),
            continuation("u", "C1"),
            fjump("j", "End"),
        ],
        [],
        label="Sum",
    )
    places = Places(FbdBody(networks=[body]))
    assert [places.where("n1", node) for node in ("high", "mid", "low")] == [
        'network 1 "Sum", the 1st ADD',
        'network 1 "Sum", the 2nd ADD',
        'network 1 "Sum", the 3rd ADD',
    ]
    assert places.where("n1", "i", "OUT") == 'network 1 "Sum", input T#2s'
    assert places.where("n1", "o", "IN") == 'network 1 "Sum", reset output Level'
    assert places.where("n1", "k") == 'network 1 "Sum", connector C1'
    assert places.where("n1", "u") == 'network 1 "Sum", continuation C1'
    assert places.where("n1", "j") == 'network 1 "Sum", jump to End'


def test_a_diagnostic_keeps_the_ids_for_the_editor_and_names_the_place_for_people():
    main = ld_pou("Main", "VAR t : TON; n : INT; END_VAR", rung("r9", box("b4", "TON", instance="t", PT="n")))
    (diagnostic,) = lower_project(project(main)).diagnostics
    assert (diagnostic.network, diagnostic.element, diagnostic.pin) == ("r9", "b4", "PT")
    assert diagnostic.place == "network 1, TON t.PT"
    assert "r9" not in diagnostic.format() and "b4" not in diagnostic.format()


def test_a_runtime_fault_in_a_box_names_network_and_box():
    main = ld_pou(
        "Main",
        "VAR n : INT := 0; q : INT; run : BOOL := TRUE; END_VAR",
        rung("a", contact("c", "run"), coil("o", "run")),
        rung("r2", box("d9", "DIV", en=True, IN1="10", IN2="n", outputs={"OUT": "q"}), label="Ratio"),
    )
    sim = simulate(main)
    sim.cycle(1)
    (fault,) = sim.faults
    assert fault.code == "division_by_zero"
    assert fault.where() == 'POU MAIN, network 2 "Ratio", DIV'
    diagnostic = fault.diagnostic()
    assert (diagnostic.network, diagnostic.element, diagnostic.place) == ("r2", "d9", 'network 2 "Ratio", DIV')
