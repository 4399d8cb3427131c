"""The fast and monitor variants against the debug variant over random LD programs (issue 27).

The fast variant keeps the lowering's power-flow and ENO temporaries in Python locals of each chunk function
(codegen/scope.py, ``temp_locals``); the debug variant keeps every variable in its slot and shares nothing with
it but the IR, so it is the reference. Random LD networks (contacts NO/NC/edges in series and parallel, coils of
every mode, TON/CTU/R_TRIG boxes, ADD with EN, compares) run scan by scan under random writes, with the chunk
size lowered so the temporaries cross chunk boundaries; every variable (and every probe of the monitor variant)
must agree after every scan.
"""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.engine.codegen import chunks
from ladderlab.model import ld
from ladderlab.model.project import Pou, Project, Task
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project
from tests.support import fuzz_settings

BOOLS = [f"B{i}" for i in range(6)]
INTS = ["X", "Y"]
DECLARATIONS = f"VAR {', '.join(BOOLS)} : BOOL; {', '.join(INTS)} : INT; T1, T2 : TON; K1 : CTU; E1 : R_TRIG; END_VAR"


class _Ids:
    def __init__(self) -> None:
        self.n = 0

    def __call__(self, stem: str) -> str:
        self.n += 1
        return f"{stem}{self.n}"


def _contact(draw, ids: _Ids) -> ld.Contact:
    return ld.Contact(id=ids("c"), var=draw(st.sampled_from(BOOLS)), mode=draw(st.sampled_from(["no", "nc", "p", "n"])))


def _series(draw, ids: _Ids, depth: int) -> list:
    # now and then a long run of contacts: folds of folds, bounded by FOLDED_PARENTHESES (codegen/statements.py)
    elements: list = [_contact(draw, ids) for _ in range(10 if depth == 2 and draw(st.integers(0, 4)) == 0 else 0)]
    for _ in range(draw(st.integers(1, 3))):
        if depth > 0 and draw(st.integers(0, 3)) == 0:
            branches = [_series(draw, ids, depth - 1) for _ in range(draw(st.integers(2, 3)))]
            elements.append(ld.Parallel(id=ids("p"), branches=branches))
        elif draw(st.integers(0, 5)) == 0:
            op = draw(st.sampled_from(["GT", "GE", "EQ", "LE", "LT", "NE"]))
            right = str(draw(st.integers(-3, 40)))
            elements.append(ld.Compare(id=ids("q"), op=op, left=draw(st.sampled_from(INTS)), right=right))
        else:
            elements.append(_contact(draw, ids))
    return elements


def _end(draw, ids: _Ids, fork: bool = True) -> list:
    kind = draw(st.sampled_from(["coil", "coil", "ton", "ctu", "trig", "add", *(["fork"] * fork)]))
    if kind == "fork":  # branches that each end in a coil or box (diagrams.py's timer networks): a coil's variable
        # read by a contact of a later branch, FB outputs read right after the call, ORs of the branches unread
        branches = [[*_series(draw, ids, 0), *_end(draw, ids, fork=False)] for _ in range(draw(st.integers(2, 3)))]
        return [ld.Parallel(id=ids("f"), branches=branches)]
    if kind == "coil":
        mode = draw(st.sampled_from(["normal", "negated", "set", "reset", "p", "n"]))
        return [ld.Coil(id=ids("o"), var=draw(st.sampled_from(BOOLS)), mode=mode)]
    if kind == "ton":
        instance = draw(st.sampled_from(["T1", "T2"]))
        box = ld.Box(id=ids("t"), call="TON", instance=instance, inputs={"PT": f"T#{draw(st.integers(0, 40))}ms"})
        return [box, ld.Coil(id=ids("o"), var=draw(st.sampled_from(BOOLS)))]
    if kind == "ctu":
        box = ld.Box(id=ids("k"), call="CTU", instance="K1", inputs={"PV": str(draw(st.integers(0, 4)))})
        return [box, ld.Coil(id=ids("o"), var=draw(st.sampled_from(BOOLS)))]
    if kind == "trig":
        return [
            ld.Box(id=ids("e"), call="R_TRIG", instance="E1"),
            ld.Coil(id=ids("o"), var=draw(st.sampled_from(BOOLS))),
        ]
    target = draw(st.sampled_from(INTS))
    step = str(draw(st.sampled_from([1, 7, 16000, -9])))
    box = ld.Box(id=ids("a"), call="ADD", en=True, inputs={"IN1": target, "IN2": step}, outputs={"OUT": target})
    return [box, ld.Coil(id=ids("o"), var=draw(st.sampled_from(BOOLS)))]


@st.composite
def ld_programs(draw) -> Project:
    ids = _Ids()
    networks = [
        ld.LdNetwork(id=ids("n"), elements=[*_series(draw, ids, 2), *_end(draw, ids)])
        for _ in range(draw(st.integers(1, 8)))
    ]
    pou = Pou(name="Main", kind="program", language="ld", declarations=DECLARATIONS, body=ld.LdBody(networks=networks))
    return Project(name="p", pous=[pou], tasks=[Task(name="main", interval="T#10ms", programs=["Main"])])


_writes = st.lists(st.lists(st.tuples(st.sampled_from(BOOLS), st.booleans()), max_size=3), min_size=1, max_size=8)


@pytest.mark.parametrize("chunk_statements", [3, chunks.CHUNK_STATEMENTS])
@fuzz_settings(fast=30)
@given(project=ld_programs(), writes=_writes)
def test_the_fast_variant_computes_what_the_debug_variant_does(chunk_statements, project, writes):
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(chunks, "CHUNK_STATEMENTS", chunk_statements)
        builds = [build_project(project, variant) for variant in ("fast", "monitor", "debug")]
    assert all(build.compiled is not None for build in builds), [d.message for d in builds[0].diagnostics]
    fast, monitor, debug = (build.simulation() for build in builds)
    for scan, scan_writes in enumerate(writes):
        for name, value in scan_writes:
            for sim in (fast, monitor, debug):
                sim.write(f"Main.{name}", value)
        assert fast.cycle(1) == monitor.cycle(1) == debug.cycle(1) == 1
        assert fast.snapshot() == debug.snapshot() == monitor.snapshot(), f"scan {scan}"
        assert monitor.probes("Main") == debug.probes("Main"), f"scan {scan}"
        assert (fast.fault is None) == (monitor.fault is None) == (debug.fault is None)


def test_power_flow_temporaries_are_locals_of_the_fast_code_only():
    """The shape the property relies on: the fast code names no ``v___P`` slot inside a network (only where a
    chunk takes or hands on its temporaries); the debug code keeps them in their slots."""
    networks = [
        ld.LdNetwork(
            id=f"n{n}",
            elements=[
                ld.Contact(id=f"a{n}", var="B0"),
                ld.Contact(id=f"b{n}", var="B1", mode="nc"),
                ld.Coil(id=f"c{n}", var="B2"),
            ],
        )
        for n in range(3)
    ]
    pou = Pou(name="Main", kind="program", language="ld", declarations=DECLARATIONS, body=ld.LdBody(networks=networks))
    project = Project(name="p", pous=[pou])
    fast = build_project(project, "fast").compiled
    debug = build_project(project, "debug").compiled
    assert fast is not None and debug is not None
    body = fast.source[fast.source.index("def ll_x_MAIN") :]
    # (the series' power flow is read in its place: only the coil uses it, liveness.py's folds)
    assert "self.v_B2 = (self.v_B0 and (not self.v_B1))" in body and "self.v___P" not in body
    assert "self.v___P_1 = (self.v___P and (not self.v_B1))" in debug.source


def test_a_fault_report_shows_the_temporaries_as_the_debug_variant_does():
    """A fault's report lists the values of the variables its statement mentions, power flow included: the fast
    variant reads its local temporaries from the faulting frame (codegen/faults.py)."""
    net = ld.LdNetwork(
        id="n1",
        elements=[
            ld.Contact(id="a", var="B0"),
            ld.Box(id="d", call="DIV", en=True, inputs={"IN1": "X", "IN2": "Y"}, outputs={"OUT": "X"}),
            ld.Coil(id="c", var="B1"),
        ],
    )
    declarations = "VAR B0 : BOOL := TRUE; B1 : BOOL; X : INT := 7; Y : INT; END_VAR"
    pou = Pou(name="Main", kind="program", language="ld", declarations=declarations, body=ld.LdBody(networks=[net]))
    reports = []
    for variant in ("fast", "debug"):
        sim = build_project(Project(name="p", pous=[pou]), variant).simulation()
        sim.cycle(1)
        assert sim.fault is not None
        reports.append(sim.fault.diagnostic().message)
    assert reports[0] == reports[1]
    assert "division by zero: 7 / 0" in reports[0] and "__P = True" in reports[0]


def test_the_fast_code_shapes_keep_iec_values():
    """Each shape of the fast code (docs/runtime.md, "Dead stores, forwarding, FB outputs") against values worked
    out from IEC 61131-3 by hand, in every variant: a coil's variable read by a later branch after a reset coil
    changed it (a store forwarded to a read must not outlive the reset's IF), a TON whose constant PT expired
    (ET = PT, SFB-17: the folded ``pt if pt > 0 else 0``), and an ADD whose unread ENO is dropped (X still counts)."""
    reset_then_read = ld.LdNetwork(
        id="n1",
        elements=[
            ld.Contact(id="a", var="B0"),
            ld.Parallel(
                id="p",
                branches=[
                    [ld.Coil(id="c", var="B2")],
                    [ld.Coil(id="r", var="B2", mode="reset")],
                    [ld.Contact(id="d", var="B2"), ld.Coil(id="e", var="B3")],
                ],
            ),
        ],
    )
    timer = ld.LdNetwork(
        id="n2",
        elements=[
            ld.Contact(id="f", var="B0"),
            ld.Box(id="t", call="TON", instance="T1", inputs={"PT": "T#30ms"}),
            ld.Coil(id="g", var="B4"),
        ],
    )
    adder = ld.LdNetwork(
        id="n3",
        elements=[
            ld.Contact(id="h", var="B0"),
            ld.Box(id="x", call="ADD", en=True, inputs={"IN1": "X", "IN2": "1"}, outputs={"OUT": "X"}),
        ],
    )
    pou = Pou(
        name="Main",
        kind="program",
        language="ld",
        declarations=DECLARATIONS.replace("B0, ", "").replace("VAR ", "VAR B0 : BOOL := TRUE; "),
        body=ld.LdBody(networks=[reset_then_read, timer, adder]),
    )
    project = Project(name="p", pous=[pou], tasks=[Task(name="main", interval="T#10ms", programs=["Main"])])
    for variant in ("fast", "monitor", "debug"):
        build = build_project(project, variant)
        assert build.compiled is not None, [d.message for d in build.diagnostics]
        sim = build.simulation()
        sim.cycle(6)  # 60 ms with B0 TRUE from the first scan: the 30 ms timer has expired
        assert sim.read("Main.B2") is False and sim.read("Main.B3") is False, variant  # reset, then read
        assert sim.read("Main.T1.ET") == 30 and sim.read("Main.T1.Q") is True and sim.read("Main.B4") is True, variant
        assert sim.read("Main.X") == 6, variant


def test_a_long_series_folds_into_bounded_expressions():
    """Folds of folds nest one parenthesis each (``FOLDED_PARENTHESES`` stops them): a series of 60 contacts
    compiles and conducts only while every contact does."""
    contacts = [ld.Contact(id=f"c{n}", var=BOOLS[n % 3]) for n in range(60)]
    network = ld.LdNetwork(id="n1", elements=[*contacts, ld.Coil(id="o", var="B5")])
    pou = Pou(name="Main", kind="program", language="ld", declarations=DECLARATIONS, body=ld.LdBody(networks=[network]))
    sim = build_project(Project(name="p", pous=[pou]), "fast").simulation()
    for values in [(True, True, False), (True, True, True)]:
        for name, value in zip(BOOLS, values, strict=False):
            sim.write(f"Main.{name}", value)
        sim.cycle(1)
        assert sim.read("Main.B5") is all(values)


def test_folded_temporaries_and_a_chained_counter_output_keep_iec_values():
    """The shapes of liveness.py's folds and of a coil chained to an inlined FB's last output store (docs/runtime.md,
    "Folded temporaries"), in every variant, against IEC values: a series ``A AND NOT B``, and a CTU (PV 2) whose Q
    drives a coil: Q := CV >= PV after the second rising edge of CU (SFB-13), and CV stays at the INT maximum on a
    further edge (it counts only while CV < 32767)."""
    series = ld.LdNetwork(
        id="n1",
        elements=[ld.Contact(id="a", var="B0"), ld.Contact(id="b", var="B1", mode="nc"), ld.Coil(id="c", var="B2")],
    )
    counter = ld.LdNetwork(
        id="n2",
        elements=[
            ld.Contact(id="d", var="B3"),
            ld.Box(id="k", call="CTU", instance="K1", inputs={"PV": "2"}),
            ld.Coil(id="e", var="B4"),
        ],
    )
    pou = Pou(
        name="Main",
        kind="program",
        language="ld",
        declarations=DECLARATIONS,
        body=ld.LdBody(networks=[series, counter]),
    )
    project = Project(name="p", pous=[pou], tasks=[Task(name="main", interval="T#10ms", programs=["Main"])])
    for variant in ("fast", "monitor", "debug"):
        build = build_project(project, variant)
        assert build.compiled is not None, [d.message for d in build.diagnostics]
        if variant == "fast":
            source = build.compiled.source
            assert "self.v_B2 = (self.v_B0 and (not self.v_B1))" in source
            assert "self.v_B4 = ll_fb.Q = ll_fb.CV >= 2" in source
        sim = build.simulation()
        seen = []
        for b0, b1, b3 in [(True, False, True), (True, True, False), (False, False, True), (True, False, True)]:
            for name, value in (("B0", b0), ("B1", b1), ("B3", b3)):
                sim.write(f"Main.{name}", value)
            sim.cycle(1)
            seen.append((sim.read("Main.B2"), sim.read("Main.K1.CV"), sim.read("Main.K1.Q"), sim.read("Main.B4")))
        assert seen == [
            (True, 1, False, False),
            (False, 1, False, False),
            (False, 2, True, True),
            (True, 2, True, True),
        ]
        sim.write("Main.K1.CV", 32767)
        for b3 in (False, True):
            sim.write("Main.B3", b3)
            sim.cycle(1)
        assert sim.read("Main.K1.CV") == 32767 and sim.read("Main.B4") is True, variant


TEMP_REFERENCES = """
FUNCTION_BLOCK Walker
VAR_INPUT n : INT; END_VAR
VAR_OUTPUT sum : INT; whole : INT; END_VAR
VAR_TEMP buf : ARRAY[1..4] OF INT; t : INT; i : INT; pt : POINTER TO INT; rt : REF_TO INT; END_VAR
FOR i := 1 TO 4 DO
  buf[i] := n * i;
END_FOR;
pt := ADR(buf[1]);
sum := 0;
FOR i := 1 TO 4 DO
  sum := sum + pt^;
  pt := pt + SIZEOF(buf[1]);
END_FOR;
rt := REF(t);
rt^ := rt^ + n;
whole := t + rt^;
END_FUNCTION_BLOCK
FUNCTION Bump : INT
VAR_IN_OUT io : INT; END_VAR
VAR p : REF_TO INT; END_VAR
p := REF(io);
p^ := p^ + 1;
Bump := io;
END_FUNCTION
PROGRAM Main
VAR w : Walker; k : INT; peek : BOOL; kept : POINTER TO INT; late, doubled, bumped : INT; END_VAR
VAR_TEMP tp : INT; pm : POINTER TO INT; END_VAR
w(n := k);
pm := ADR(tp);
pm^ := tp + k * 2;
bumped := Bump(tp);
doubled := tp;
IF peek THEN
  late := kept^;
END_IF;
kept := pm;
END_PROGRAM
"""

_temp_writes = st.lists(st.tuples(st.integers(-3000, 3000), st.booleans()), min_size=1, max_size=8)


@fuzz_settings(fast=20)
@given(writes=_temp_writes)
def test_the_variants_agree_on_references_to_temporaries_and_their_dangling_faults(writes):
    """References to VAR_TEMP (a program's and an FB's, tests/engine/test_temp_references.py) and to a function's
    VAR_IN_OUT bound to one: the fast and monitor variants (an inline body with a frame) against the debug variant,
    scan by scan under random inputs (INT overflow wraps alike); a ``peek`` reads a pointer kept from the last scan:
    NULL the first time, dangling after, the same fault in every variant."""
    project, diagnostics = source_to_project(TEMP_REFERENCES, "temps")
    assert project is not None and diagnostics == []
    fast, monitor, debug = (build_project(project, variant).simulation() for variant in ("fast", "monitor", "debug"))
    for scan, (k, peek) in enumerate(writes):
        for sim in (fast, monitor, debug):
            sim.write("Main.k", k)
            sim.write("Main.peek", peek)
            sim.cycle(1)
        assert fast.snapshot() == debug.snapshot() == monitor.snapshot(), f"scan {scan}"
        faults = [None if sim.fault is None else (sim.fault.code, sim.fault.message) for sim in (fast, monitor, debug)]
        assert faults[0] == faults[1] == faults[2], f"scan {scan}"
        if peek:  # kept was NULL before the first scan, and refers to a gone tp after it
            assert faults[0] is not None and faults[0][0] == ("null_dereference" if scan == 0 else "dangling_reference")
            break
        assert faults[0] is None
        assert fast.read("Main.doubled") == fast.read("Main.bumped") == ((k * 2 + 1 + 32768) & 0xFFFF) - 32768
