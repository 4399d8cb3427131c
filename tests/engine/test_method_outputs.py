"""VAR_OUTPUT of a METHOD (issue 25, item 5; IEC 61131-3 ed. 3, 6.6.5 and CODESYS "Method" help): outputs are
variables of the call, fresh (their declared initial value) in every call, and the call's ``=>`` targets get their
values when the method returns - at its end or at a RETURN; an output left unconnected is simply lost. With EN
FALSE the method does not run and no target is written. Expected values are worked out by hand from the texts.
"""

from __future__ import annotations

from .oo_support import build, run

DIVIDER = """
FUNCTION_BLOCK Divider
VAR calls : INT; END_VAR
METHOD PUBLIC DivMod : BOOL
VAR_INPUT a : INT; b : INT; END_VAR
VAR_OUTPUT q : INT; r : INT := 7; exact : BOOL; code : BYTE; END_VAR
calls := calls + 1;
IF b = 0 THEN
    DivMod := FALSE;
    code := 16#E1;
    RETURN;
END_IF;
q := a / b;
r := a MOD b;
exact := r = 0;
DivMod := TRUE;
END_METHOD
END_FUNCTION_BLOCK
"""


def test_outputs_reach_their_targets_at_the_end_and_at_a_return_scan_by_scan():
    sim = run(
        DIVIDER
        + """PROGRAM Main
VAR d : Divider; ok : BOOL; q : INT := -1; r : INT := -1; r0 : INT; w : WORD; z : BOOL := TRUE; q0 : INT := 5;
    a : INT := 17; END_VAR
ok := d.DivMod(a := a, b := 5, q => q, r => r);
d.DivMod(a := 1, b := 0, q => q0, r => r0, code => w.%B1, exact => z);
a := a + 1;
END_PROGRAM
"""
    )
    for scan in range(1, 4):
        sim.cycle(1)
        a = 16 + scan
        assert (sim.read("Main.ok"), sim.read("Main.q"), sim.read("Main.r")) == (True, a // 5, a % 5)
        # b = 0: RETURN before q, r, exact are set; they still go out, with their initial values (0, 7, FALSE)
        assert (sim.read("Main.q0"), sim.read("Main.r0"), sim.read("Main.z")) == (0, 7, False)
        assert sim.read("Main.w") == 0xE100  # code 16#E1 into the high byte of w
        assert sim.read("Main.d.calls") == 2 * scan


def test_outputs_converted_negated_and_left_out():
    """``q => wide`` widens INT to DINT, ``NOT exact => odd`` negates, an output with no ``=>`` is dropped; the
    method's outputs start from their initial values in every call (r := 7), not from the last call's."""
    sim = run(
        DIVIDER
        + """PROGRAM Main
VAR d : Divider; wide : DINT; odd : BOOL; n : INT := 9; r : INT; END_VAR
d.DivMod(a := n, b := 2, q => wide, NOT exact => odd);
d.DivMod(a := 0, b := 0, r => r);
n := n + 1;
END_PROGRAM
"""
    )
    for n in (9, 10, 11):
        sim.cycle(1)
        assert (sim.read("Main.wide"), sim.read("Main.odd"), sim.read("Main.r")) == (n // 2, n % 2 == 1, 7)


def test_en_false_writes_no_output():
    sim = run(
        DIVIDER
        + """PROGRAM Main
VAR d : Divider; go : BOOL; q : INT := 99; wide : DINT := 99; done : BOOL; END_VAR
d.DivMod(EN := go, a := 8, b := 3, q => q, ENO => done);
d.DivMod(EN := go, a := 9, b := 3, q => wide);
END_PROGRAM
"""
    )
    sim.cycle(1)
    assert (sim.read("Main.q"), sim.read("Main.wide"), sim.read("Main.done")) == (99, 99, False)
    sim.write("Main.go", True)
    sim.cycle(1)
    assert (sim.read("Main.q"), sim.read("Main.wide"), sim.read("Main.done")) == (2, 3, True)


SHAPES = """
INTERFACE IShape
METHOD Measure : BOOL
VAR_INPUT scale : INT; END_VAR
VAR_OUTPUT area : INT; name : STRING[10]; END_VAR
END_METHOD
END_INTERFACE
FUNCTION_BLOCK Square IMPLEMENTS IShape
VAR side : INT := 3; END_VAR
METHOD Measure : BOOL
VAR_INPUT scale : INT; END_VAR
VAR_OUTPUT area : INT; name : STRING[10]; END_VAR
area := side * side * scale;
name := 'square';
Measure := TRUE;
END_METHOD
METHOD Doubled : INT
VAR a : INT; n : STRING[10]; END_VAR
Measure(scale := 2, area => a, name => n);
Doubled := a;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK Rect EXTENDS Square
VAR other : INT := 4; END_VAR
METHOD Measure : BOOL
VAR_INPUT scale : INT; END_VAR
VAR_OUTPUT area : INT; name : STRING[10]; END_VAR
area := side * other * scale;
name := 'rectangle';
END_METHOD
END_FUNCTION_BLOCK
"""


def test_outputs_through_an_interface_an_override_and_a_bare_call_in_a_method():
    """Dispatch picks the instance's own Measure; a shorter STRING target is cut to its length (STRING[4])."""
    sim = run(
        SHAPES
        + """PROGRAM Main
VAR s : Square; r : Rect; i : IShape; a1 : INT; n1 : STRING[4]; a2 : INT; n2 : STRING; d1 : INT; d2 : INT;
    ok : BOOL := TRUE; n3 : STRING[4]; END_VAR
i := s;
i.Measure(scale := 1, area => a1, name => n1);
i := r;
i.Measure(scale := 1, area => a2, name => n2);
d1 := s.Doubled();
d2 := r.Doubled();
ok := r.Measure(scale := 1, name => n3);
END_PROGRAM
"""
    )
    sim.cycle(1)
    assert (sim.read("Main.a1"), sim.read("Main.n1")) == (9, "squa")
    assert (sim.read("Main.a2"), sim.read("Main.n2")) == (12, "rectangle")
    assert (sim.read("Main.d1"), sim.read("Main.d2")) == (18, 24)
    assert (sim.read("Main.ok"), sim.read("Main.n3")) == (False, "rect")  # Rect.Measure leaves its result FALSE


def test_an_output_that_needs_a_copy_inside_an_expression_is_a_located_error():
    statement = "ok := r.Measure(scale := 1, name => n) AND TRUE;"
    text = SHAPES + f"PROGRAM Main\nVAR r : Rect; ok : BOOL; n : STRING[4]; END_VAR\n{statement}\nEND_PROGRAM\n"
    result = build(text)
    assert [(d.code, d.file, d.line, d.column, d.message) for d in result.diagnostics if d.severity == "error"] == [
        (
            "IR-UNSUPPORTED",
            "Main/body",
            text.splitlines().index(statement) + 1,  # (the lines of the file the project was read from)
            statement.index("name") + 1,
            "the output name => n is converted after the call, which cannot happen inside an expression: call the "
            "method as a statement, or assign its result directly (x := inst.M(...))",
        )
    ]


def test_an_override_and_an_implementation_must_declare_the_same_outputs():
    own = "VAR_OUTPUT area : INT; name : STRING[10]; END_VAR\narea := side * other"
    text = SHAPES.replace(own, "VAR_OUTPUT area : INT; END_VAR\narea := side * other").replace(
        "name := 'rectangle';\n", ""
    )
    expected = "its parameters differ (it takes VAR_INPUT scale, VAR_OUTPUT area, VAR_OUTPUT name)"
    assert [(d.code, d.file, d.message) for d in build(text).diagnostics if d.severity == "error"] == [
        ("ST-DECL", "Rect.Measure/declarations", f"Rect.Measure overrides Square.Measure but {expected}"),
        ("ST-DECL", "Rect/declarations", f"Rect.Measure implements IShape.Measure but {expected}"),
    ]


def test_an_ld_box_writes_a_methods_outputs_to_the_variables_at_its_pins():
    """In LD a method box ``d.DivMod`` (CODESYS) writes its outputs like ``q => x``: the same type directly, a wider
    one converted; EN gates the call, so with the rung open nothing is written."""
    from ladderlab.simulation.build import build_project
    from ladderlab.st.project_text import source_to_project
    from tests.ir.diagram_support import box, contact, ld_pou, rung

    project, _ = source_to_project(DIVIDER, "ld")
    divide = box("b1", "d.DivMod", en=True, a="n", b="4", outputs={"OUT": "ok", "Q": "q", "R": "wide"})
    declarations = "VAR d : Divider; go : BOOL; n : INT := 14; ok : BOOL; q : INT := -1; wide : DINT := -1; END_VAR"
    project.pous.append(ld_pou("Main", declarations, rung("n1", contact("k", "go"), divide)))
    result = build_project(project)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    sim = result.simulation()
    sim.cycle(1)
    assert (sim.read("Main.ok"), sim.read("Main.q"), sim.read("Main.wide")) == (False, -1, -1)
    sim.write("Main.go", True)
    sim.cycle(1)
    assert (sim.read("Main.ok"), sim.read("Main.q"), sim.read("Main.wide")) == (True, 3, 2)  # 14 = 3 * 4 + 2


def test_an_ld_method_box_probes_every_output_pin_wired_or_not():
    """ON-09 (a value on every pin, as an FB box's outputs have): the LD box ``d.DivMod`` probes OUT, its output Q at
    the variable q (read after the call, so the converted DINT ``wide`` would be its own) and the unwired R, EXACT and
    CODE from the slots the call wrote. By hand, 14 / 4: OUT TRUE, Q 3, R 2, EXACT FALSE, CODE 0 (a fresh output)."""
    from ladderlab.simulation.build import build_project
    from ladderlab.st.project_text import source_to_project
    from tests.ir.diagram_support import box, contact, ld_pou, rung

    project, _ = source_to_project(DIVIDER, "ld")
    divide = box("b1", "d.DivMod", en=True, a="n", b="4", outputs={"OUT": "ok", "Q": "q"})
    declarations = "VAR d : Divider; n : INT := 14; ok : BOOL; q : INT := -1; END_VAR"
    project.pous.append(ld_pou("Main", declarations, rung("n1", contact("k", "TRUE"), divide)))
    result = build_project(project, "monitor")  # the variant the editor runs online: probes recorded
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    sim = result.simulation()
    sim.cycle(1)
    values = sim.probes("Main").values
    assert {pin: values[f"b1.{pin}"] for pin in ("OUT", "Q", "R", "EXACT", "CODE")} == {
        "OUT": True,
        "Q": 3,
        "R": 2,
        "EXACT": False,
        "CODE": 0,
    }
    assert (sim.read("Main.ok"), sim.read("Main.q")) == (True, 3)


def test_an_ld_box_pin_that_is_no_output_of_the_method_is_refused():
    from ladderlab.simulation.build import build_project
    from ladderlab.st.project_text import source_to_project
    from tests.ir.diagram_support import box, contact, ld_pou, rung

    project, _ = source_to_project(DIVIDER, "ld")
    divide = box("b1", "d.DivMod", en=True, a="1", b="4", outputs={"REST": "q"})
    project.pous.append(ld_pou("Main", "VAR d : Divider; q : INT; END_VAR", rung("n1", contact("k", "TRUE"), divide)))
    assert [(d.code, d.message) for d in build_project(project).diagnostics if d.severity == "error"] == [
        ("LD-UNKNOWN-PIN", "d.DivMod is a method: its outputs are OUT, Q, R, EXACT, CODE")
    ]


def _fbd_divider(*nodes, wires, en=False, declarations=None):
    from ladderlab.simulation.build import build_project
    from ladderlab.st.project_text import source_to_project
    from tests.ir.diagram_support import fbd_pou, net

    project, _ = source_to_project(DIVIDER, "fbd")
    declarations = declarations or (
        "VAR d : Divider; n : INT := 14; go : BOOL; ok : BOOL; q : INT := -1; wide : DINT := -1; odd : BOOL; "
        "doubled : INT := -1; END_VAR"
    )
    project.pous.append(fbd_pou("Main", declarations, net("n1", list(nodes), wires)))
    return build_project(project)


def test_an_fbd_block_wires_a_methods_outputs_to_variables_and_other_blocks():
    """In FBD the block ``d.DivMod`` has the method's outputs as output pins beside OUT (as LD's box and ST's
    ``q => x``): wired to a variable (converted INT -> DINT), into another block (MUL), negated; EN gates the
    call: with EN FALSE the pins hold the last call's values (as its OUT does) and the variables at them are not
    written."""
    from tests.ir.diagram_support import blk, inp, out

    nodes = [
        inp("a", "n"),
        inp("b", "4"),
        inp("g", "go"),
        blk("b1", "d.DivMod", en=True, EXACT={"negated": True}),
        blk("m", "MUL"),
        inp("two", "2"),
        out("o_ok", "ok"),
        out("o_q", "q"),
        out("o_r", "wide"),
        out("o_odd", "odd"),
        out("o_d", "doubled"),
    ]
    wires = [
        ("a.OUT", "b1.A"),
        ("b.OUT", "b1.B"),
        ("g.OUT", "b1.EN"),
        ("b1.OUT", "o_ok.IN"),
        ("b1.Q", "o_q.IN"),
        ("b1.R", "o_r.IN"),
        ("b1.EXACT", "o_odd.IN"),
        ("b1.Q", "m.IN1"),
        ("two.OUT", "m.IN2"),
        ("m.OUT", "o_d.IN"),
    ]
    result = _fbd_divider(*nodes, wires=wires)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    sim = result.simulation()
    sim.cycle(1)  # EN FALSE: the method does not run; the variables at its pins are not written, and MUL reads
    # the pin's held value (its initial 0), as a block reads a gated block's OUT
    assert (sim.read("Main.q"), sim.read("Main.wide"), sim.read("Main.doubled"), sim.read("Main.d.calls")) == (
        -1,
        -1,
        0,
        0,
    )
    sim.write("Main.go", True)
    for scan, n in ((1, 14), (2, 16)):
        sim.write("Main.n", n)
        sim.cycle(1)
        q, r = divmod(n, 4)
        assert (sim.read("Main.ok"), sim.read("Main.q"), sim.read("Main.wide")) == (True, q, r)
        assert (sim.read("Main.odd"), sim.read("Main.doubled"), sim.read("Main.d.calls")) == (r != 0, 2 * q, scan)
    sim.write("Main.go", False)
    sim.write("Main.n", 9)
    sim.cycle(1)  # EN FALSE again: the variables keep the last call's values (16 / 4)
    assert (sim.read("Main.q"), sim.read("Main.wide"), sim.read("Main.doubled")) == (4, 0, 8)


def test_an_fbd_wire_from_a_pin_the_method_lacks_names_its_outputs():
    from tests.ir.diagram_support import blk, inp, out

    nodes = [inp("a", "1"), inp("b", "4"), blk("b1", "d.DivMod"), out("o", "q")]
    result = _fbd_divider(*nodes, wires=[("a.OUT", "b1.A"), ("b.OUT", "b1.B"), ("b1.REST", "o.IN")])
    assert [(d.code, d.message) for d in result.diagnostics if d.severity == "error"] == [
        ("FBD-UNKNOWN-PIN", "d.DivMod has no output 'REST': its outputs are OUT, Q, R, EXACT, CODE")
    ]
