"""Object orientation in the exports (issue 25, items 5 and 6): the ST export writes METHODs, EXTENDS, IMPLEMENTS,
ABSTRACT / FINAL and INTERFACEs as IEC 61131-3 ed. 3 text that imports back to the same project; PLCopen XML carries
methods and EXTENDS as CODESYS does (addData ``.../plcopenxml/method`` and ``.../pouinheritance``), so a document
without LadderLab's own data still brings them back. Each imported project runs to the values worked out by hand.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.interchange.plcopen.xml_io import LADDERLAB_DATA
from ladderlab.interchange.st.project import export_project_st
from ladderlab.model.project import Method
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project

SOURCE = """
INTERFACE IShape
METHOD Area : INT
END_METHOD
END_INTERFACE
FUNCTION_BLOCK ABSTRACT Shape IMPLEMENTS IShape
VAR calls : INT; END_VAR
METHOD PUBLIC ABSTRACT Area : INT
END_METHOD
METHOD PROTECTED Count : INT
calls := calls + 1;
Count := calls;
END_METHOD
METHOD Describe : INT
Describe := Area() * 10 + Count();
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK Square EXTENDS Shape
VAR_INPUT side : INT; END_VAR
METHOD Area : INT
Area := side * side;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK FINAL Cube EXTENDS Square
METHOD Area : INT
Area := SUPER^.Area() * 6;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR sq : Square := (side := 2); cu : Cube := (side := 3); s : IShape; a, b, c : INT; END_VAR
a := sq.Describe();
b := cu.Describe();
s := cu;
c := s.Area();
END_PROGRAM
"""


def values(project, scans: int = 2) -> tuple:
    result = build_project(project)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    sim = result.simulation()
    sim.cycle(scans)
    return sim.read("Main.a"), sim.read("Main.b"), sim.read("Main.c")


EXPECTED = (2 * 2 * 10 + 2, (3 * 3 * 6) * 10 + 2, 3 * 3 * 6)  # after two scans: each instance counted twice


def project():
    made, diagnostics = source_to_project(SOURCE, "oo")
    assert made is not None and diagnostics == []
    return made


def test_the_st_export_writes_object_orientation_that_imports_back_the_same():
    original = project()
    assert values(original) == EXPECTED
    text = export_project_st(original).text
    assert "FUNCTION_BLOCK ABSTRACT Shape IMPLEMENTS IShape" in text
    assert "FUNCTION_BLOCK FINAL Cube EXTENDS Square" in text
    assert "METHOD PROTECTED Count : INT" in text and "METHOD PUBLIC ABSTRACT Area : INT" in text
    assert "INTERFACE IShape" in text
    again, diagnostics = source_to_project(text, "oo")
    assert diagnostics == [] and again is not None
    assert [(p.name, [m.name for m in p.methods], p.extends, p.implements) for p in again.pous] == [
        (p.name, [m.name for m in p.methods], p.extends, p.implements) for p in original.pous
    ]
    assert values(again) == EXPECTED


def test_plcopen_round_trip_keeps_methods_inheritance_and_interfaces():
    original = project()
    imported = import_plcopen(export_plcopen(original), name="oo")
    assert imported.diagnostics == []
    assert imported.project == original
    assert values(imported.project) == EXPECTED


def test_plcopen_methods_and_extends_as_codesys_writes_them_are_read_without_ladderlabs_data():
    document = ET.fromstring(export_plcopen(project()))
    for parent in list(document.iter()):
        for child in list(parent):
            if child.get("name") == LADDERLAB_DATA:
                parent.remove(child)
    result = import_plcopen(ET.tostring(document), name="oo")
    by_name = {p.name: p for p in result.project.pous}
    assert [m.name for m in by_name["Shape"].methods] == ["Area", "Count", "Describe"]
    assert (by_name["Square"].extends, by_name["Cube"].extends) == ("Shape", "Square")
    assert by_name["Square"].methods[0].return_type == "INT"
    assert "Area := side * side;" in by_name["Square"].methods[0].body


def test_plcopen_properties_and_implements_as_codesys_writes_them_are_read_without_ladderlabs_data():
    """CODESYS's property entries (``.../plcopenxml/property``: type, GET and SET with their variables and bodies) and
    the IMPLEMENTS of its declaration text (``.../interfaceasplaintext``) come back without LadderLab's data."""
    text = """
INTERFACE IGauge
METHOD Read : INT
END_METHOD
END_INTERFACE
FUNCTION_BLOCK Gauge IMPLEMENTS IGauge
VAR raw : INT; END_VAR
METHOD Read : INT
Read := raw;
END_METHOD
PROPERTY Level : INT
GET
VAR twice : INT; END_VAR
twice := raw * 2;
Level := twice;
END_GET
SET
raw := Level;
END_SET
END_PROPERTY
END_FUNCTION_BLOCK
PROGRAM Main
VAR g : Gauge; i : IGauge; l : INT; r : INT; END_VAR
g.Level := 21;
l := g.Level;
i := g;
r := i.Read();
END_PROGRAM
"""
    original, _ = source_to_project(text, "oo")
    document = ET.fromstring(export_plcopen(original))
    interfaces = [e for e in document.iter() if e.tag.endswith("}interface")]  # the POUs' (the types text stays)
    for add in (child for interface in interfaces for child in interface if child.tag.endswith("}addData")):
        for data in [d for d in add if d.get("name") == LADDERLAB_DATA]:
            add.remove(data)
    result = import_plcopen(ET.tostring(document), name="oo")
    assert [d.format() for d in result.diagnostics] == []
    gauge = next(p for p in result.project.pous if p.name == "Gauge")
    assert gauge.implements == ["IGauge"]
    [level] = gauge.properties
    assert (level.name, level.type) == ("Level", "INT")
    assert "twice : INT;" in level.get.declarations and "Level := twice;" in level.get.body
    assert "raw := Level;" in level.set.body
    sim = build_project(result.project).simulation()
    sim.cycle(1)
    assert (sim.read("Main.l"), sim.read("Main.r")) == (42, 21)


PROGRAM_METHODS = """
PROGRAM Store
VAR total : INT; END_VAR
METHOD PRIVATE Put : INT
VAR_INPUT n : INT; END_VAR
total := total + n;
Put := total;
END_METHOD
METHOD Twice : INT
VAR_OUTPUT was : INT; END_VAR
was := total;
Twice := THIS^.Put(total);
END_METHOD
PROPERTY Sum : INT
GET
Sum := total;
END_GET
SET
total := Sum;
END_SET
END_PROPERTY
Put(1);
END_PROGRAM
PROGRAM Main
VAR a : INT; b : INT; s : INT; END_VAR
a := Store.Twice(was => b);
IF a > 10 THEN
    Store.Sum := 0;
END_IF;
s := Store.Sum;
END_PROGRAM
"""


def program_values(project) -> list[tuple[int, int, int]]:
    """(Main.a, Main.b, Main.s) for three scans; by hand: Store adds 1, then Main's Twice doubles the total (was is
    the total before) and a total above 10 is set back to 0 through the property's SET: total 1 -> 2 (a 2, b 1);
    3 -> 6 (a 6, b 3); 7 -> 14 > 10 -> 0 (a 14, b 7, s 0)."""
    result = build_project(project)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    sim = result.simulation()
    return [(sim.cycle(1), sim.read("Main.a"), sim.read("Main.b"), sim.read("Main.s"))[1:] for _ in range(3)]


PROGRAM_EXPECTED = [(2, 1, 2), (6, 3, 6), (14, 7, 0)]


def test_a_programs_methods_and_properties_survive_the_st_export_and_plcopen():
    """Issue 25 item 5 (CODESYS: methods and properties of a PROGRAM): the ST export writes them inside the PROGRAM
    and imports back the same; PLCopen carries them as it carries an FB's, with LadderLab's data and without it
    (CODESYS's ``.../plcopenxml/method`` and ``.../property`` entries alone); each import runs to the same values."""
    original, diagnostics = source_to_project(PROGRAM_METHODS, "pm")
    assert original is not None and diagnostics == []
    assert program_values(original) == PROGRAM_EXPECTED
    text = export_project_st(original).text
    assert "METHOD PRIVATE Put : INT" in text and "PROPERTY PUBLIC Sum : INT" in text
    assert text.index("PROGRAM Store") < text.index("METHOD PRIVATE Put") < text.index("END_PROGRAM")
    again, diagnostics = source_to_project(text, "pm")
    assert diagnostics == [] and again is not None
    store = again.pou("Store")
    assert ([m.name for m in store.methods], [p.name for p in store.properties]) == (["Put", "Twice"], ["Sum"])
    assert program_values(again) == PROGRAM_EXPECTED
    imported = import_plcopen(export_plcopen(original), name="pm")
    assert imported.diagnostics == [] and imported.project == original
    document = ET.fromstring(export_plcopen(original))
    for parent in list(document.iter()):
        for child in list(parent):
            if child.get("name") == LADDERLAB_DATA:
                parent.remove(child)
    bare = import_plcopen(ET.tostring(document), name="pm")
    assert bare.diagnostics == []
    store = bare.project.pou("Store")
    assert (store.kind, [(m.name, m.access) for m in store.methods]) == (
        "program",
        [("Put", "PRIVATE"), ("Twice", "PUBLIC")],
    )
    assert [p.name for p in store.properties] == ["Sum"] and "total := Sum;" in store.properties[0].set.body
    assert program_values(bare.project) == PROGRAM_EXPECTED


SFC_WITH_METHOD = """
PROGRAM Seq
VAR n : INT; END_VAR
METHOD Bump : INT
VAR_INPUT inc : INT; END_VAR
n := n + inc;
Bump := n;
END_METHOD
INITIAL_STEP S1:
  Count(N);
END_STEP
STEP S2:
END_STEP
TRANSITION FROM S1 TO S2 := n >= 3;
END_TRANSITION
TRANSITION FROM S2 TO S1 := FALSE;
END_TRANSITION
ACTION Count:
  Bump(inc := 1);
END_ACTION
END_PROGRAM
"""


def test_diagram_and_sfc_programs_keep_their_methods_through_the_st_export():
    """A program's methods are ST whatever its body's language: the ST export of an LD program and of an SFC one
    (its scan as ST, and IEC textual SFC) writes them in the PROGRAM, and the text imports back with them and runs to
    the same values. By hand, per scan: Lad's rung calls Lad.Twice through THIS^ (k + 2); Seq's step S1 runs Count
    (N), which calls Bump(1), until n >= 3 takes the transition: n 1, 2, 3 (S2 active after scan 3); scan 4 runs Count
    a last time as its step has left (IEC 61131-3's final scan of an action, Q falling): 4, then 4."""
    from tests.ir.diagram_support import box, contact, ld_pou, rung

    project, diagnostics = source_to_project(SFC_WITH_METHOD, "diagrams")
    assert diagnostics == [] and project is not None
    assert [m.name for m in project.pou("Seq").methods] == ["Bump"]  # (the textual SFC import keeps them)
    twice = Method(name="Twice", return_type="INT", body="k := k + 2;\nTwice := k;")
    lad = ld_pou(
        "Lad",
        "VAR q : INT; k : INT; END_VAR",
        rung("n1", contact("c", "TRUE"), box("b", "THIS^.Twice", en=True, outputs={"OUT": "q"})),
    )
    project.pous.append(lad.model_copy(update={"methods": [twice]}))

    def scans(made) -> list[tuple]:
        result = build_project(made)
        assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
        sim = result.simulation()
        return [(sim.cycle(1), sim.read("Seq.n"), sim.read("Seq.S2.X"), sim.read("Lad.q"))[1:] for _ in range(5)]

    expected = [(1, False, 2), (2, False, 4), (3, True, 6), (4, True, 8), (4, True, 10)]
    assert scans(project) == expected
    for sfc_text in (False, True):
        exported = export_project_st(project, sfc_text=sfc_text)
        assert exported.diagnostics == [] and "METHOD PUBLIC Twice : INT" in exported.text
        assert "METHOD PUBLIC Bump : INT" in exported.text
        again, diagnostics = source_to_project(exported.text, "diagrams")
        assert diagnostics == [] and again is not None
        assert [[m.name for m in again.pou(name).methods] for name in ("Seq", "Lad")] == [["Bump"], ["Twice"]]
        assert scans(again) == expected
