"""LD and FBD boxes calling a PROGRAM (seed 003's FBD program call, IL-08's program call drawn; issue 26 item 3):
the box is ``PRGexample2(in_var := a, out_var => erg)`` - the program's one instance runs at the box, as the ST
call does (docs/st.md, "Program calls"). Expected values by hand: out_var := in_var + 1."""

from __future__ import annotations

from ladderlab.model.project import Pou
from tests.interchange.st_support import same_traces
from tests.ir.diagram_support import (
    blk,
    box,
    contact,
    errors,
    fbd_pou,
    inp,
    ld_pou,
    net,
    out,
    project,
    rung,
    simulate,
    trace,
)

PRG = Pou(
    name="PRGexample2",
    kind="program",
    language="st",
    declarations="VAR_INPUT in_var : INT; END_VAR\nVAR_OUTPUT out_var : INT; END_VAR",
    body="out_var := in_var + 1;",
)


def fbd_main(kind: str = "program") -> Pou:
    return fbd_pou(
        "Main",
        "VAR a, erg : INT; END_VAR",
        net(
            "n1",
            [inp("i", "a"), blk("b", "PRGexample2"), out("o", "erg")],
            [("i.OUT", "b.in_var"), ("b.out_var", "o.IN")],
        ),
        kind=kind,
    )


def test_an_fbd_block_calls_a_program_IL_08():
    sim = simulate(fbd_main(), PRG)
    assert trace(sim, "Main", [{"a": 33}, {"a": 5}], ["erg"]) == [(34,), (6,)]


def ld_main(kind: str = "program") -> Pou:
    return ld_pou(
        "Main",
        "VAR a, erg : INT; go : BOOL; END_VAR",
        rung("r1", contact("c", "go"), box("b", "PRGexample2", en=True, in_var="a", outputs={"out_var": "erg"})),
        kind=kind,
    )


def test_an_ld_box_calls_a_program_under_en_IL_08():
    """With EN FALSE (go FALSE) the program does not run: erg keeps 34 although a changed."""
    sim = simulate(ld_main(), PRG)
    scans = [{"a": 33, "go": True}, {"a": 5, "go": False}, {"a": 5, "go": True}]
    assert trace(sim, "Main", scans, ["erg"]) == [(34,), (34,), (6,)]


def test_a_program_box_in_a_function_block_is_a_located_error():
    assert errors(fbd_main("function_block"), PRG) == [
        "POU Main, network 1, PRGexample2: error FBD-NOT-CALLABLE: a function block cannot call the program "
        "PRGexample2: only programs call programs"
    ]


def test_a_program_box_in_an_ld_function_block_is_a_located_error():
    """As in ST (only programs call programs, docs/st.md "Program calls"), also in LD."""
    assert errors(ld_main("function_block"), PRG) == [
        "POU Main, network 1, PRGexample2: error LD-NOT-CALLABLE: a function block cannot call the program "
        "PRGexample2: only programs call programs"
    ]


def test_a_program_box_with_an_instance_is_a_located_error():
    main = fbd_pou("Main", "VAR a : INT; END_VAR", net("n1", [blk("b", "PRGexample2", instance="a")], []))
    assert errors(main, PRG) == [
        "POU Main, network 1, PRGexample2 a: error FBD-INSTANCE: PRGexample2 is a program: its one instance is the "
        "program itself (remove 'a')"
    ]


def test_the_st_export_of_a_program_box_runs_alike():
    same_traces(project(fbd_main(), PRG))
    same_traces(project(ld_main(), PRG))


def test_a_program_box_goes_through_plcopen():
    """A block whose typeName is the program and no instanceName; it comes back the same and runs alike."""
    from ladderlab.interchange.plcopen.exporter import export_plcopen
    from ladderlab.interchange.plcopen.importer import import_plcopen
    from tests.interchange.plcopen_helpers import xsd_errors

    for main in (fbd_main(), ld_main()):
        original = project(main, PRG)
        data = export_plcopen(original)
        assert xsd_errors(data) == []
        result = import_plcopen(data)
        assert [d.format() for d in result.diagnostics] == []
        assert result.project.pou("Main") == original.pou("Main")
