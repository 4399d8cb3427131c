"""References to the VAR_TEMP of a PROGRAM, FUNCTION_BLOCK or METHOD, and REF()/ADR() of a function's VAR_IN_OUT
(issue 25; IEC 61131-3 ed. 3 6.4.4.10 references, CODESYS ADR).

A VAR_TEMP is made anew at every call of its POU and is gone when the call returns (VAR-41). CODESYS accepts
``pt := ADR(buf)`` of one inside an FB (OSCAT's FBs walk a temporary buffer so within the call): reading and writing
through such a reference works while the call runs; once the call returned, a dereference (the next scan, or in
another POU that kept it) is the located runtime fault ``dangling_reference`` - never the value of the next call's
VAR_TEMP. A VAR_IN_OUT is passed by reference (VAR-51): a reference a function takes of it refers to the caller's
variable, outlives the function's call and writes the caller's variable; when that variable is itself a variable
of a call (a function's local, a VAR_TEMP), the reference dies with that call. Every expected value is worked out
by hand from the program text, in each engine variant (fast, monitor, debug: docs/runtime.md).
"""

from __future__ import annotations

import pickle

import pytest

from ladderlab.engine.paths import NoTarget

from .ed3_support import build

VARIANTS = ("fast", "monitor", "debug")

WALKER = """
TYPE Pair : STRUCT a : INT; b : INT; END_STRUCT; END_TYPE
FUNCTION_BLOCK Walker
VAR_INPUT n : INT; END_VAR
VAR_OUTPUT sum : INT; whole : INT; member : INT; END_VAR
VAR_TEMP
  buf : ARRAY[1..4] OF INT; t : INT; s : Pair; i : INT;
  pt : POINTER TO INT; rt : REF_TO INT; rb : REF_TO INT; rs : REF_TO Pair;
END_VAR
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
rt^ := rt^ + n + 100;
whole := t;
t := t + 1;
whole := whole + rt^;
rb := REF(s.b);
rb^ := n * 3;
rs := REF(s);
rs^.a := rs^.a + 5;
member := s.a + s.b;
END_FUNCTION_BLOCK
PROGRAM Main
VAR w : Walker; k : INT := 1; doubled : INT; pm : POINTER TO INT; END_VAR
VAR_TEMP tp : INT; END_VAR
w(n := k);
pm := ADR(tp);
pm^ := tp + k * 2;
doubled := tp;
k := k + 1;
END_PROGRAM
"""


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_temporary_buffer_walked_through_pointers_within_the_call_scan_by_scan(variant):
    """Within the call: a pointer walks the VAR_TEMP array (TYP-42, TYP-43), a reference to the whole VAR_TEMP
    reads and writes it (TYP-44), one to a member and one to the whole structure too. Each call starts from fresh
    VAR_TEMP (VAR-41: t and s.a are 0 again, so the sums do not grow from scan to scan). For n = k:
    sum = n * (1 + 2 + 3 + 4); t := 0 + n + 100, whole := t + (t + 1) = 2n + 201; s.b := 3n, s.a := 0 + 5.
    The program's own VAR_TEMP tp: tp := 0 + 2k."""
    sim = build(WALKER, variant).simulation()
    for k in (1, 2, 3, 4):
        sim.cycle(1)
        assert sim.fault is None, sim.fault.text()
        assert [sim.read(f"Main.w.{v}") for v in ("sum", "whole", "member")] == [10 * k, 2 * k + 201, 3 * k + 5]
        assert sim.read("Main.doubled") == 2 * k


KEEPER = """
FUNCTION_BLOCK Keeper
VAR_OUTPUT last : INT; END_VAR
VAR kept : POINTER TO INT; k : INT; END_VAR
VAR_TEMP t : INT; END_VAR
k := k + 1;
t := 10 * k;
IF k >= 2 THEN
  last := kept^;
END_IF;
kept := ADR(t);
last := kept^ + 1;
END_FUNCTION_BLOCK
PROGRAM Main
VAR f : Keeper; END_VAR
f();
END_PROGRAM
"""


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_reference_kept_past_the_call_is_a_located_fault_never_the_next_calls_value(variant):
    """The first call keeps ADR(t) in the FB's VAR and reads through it while t lives (last = 10 + 1). In the second
    call the kept reference refers to the first call's t, which is gone: reading it is the fault, located at the
    statement, with the pointer's value - not 20, the new call's t that lives where the old one did."""
    sim = build(KEEPER, variant).simulation()
    sim.cycle(1)
    assert (sim.fault, sim.read("Main.f.last"), sim.read("Main.f.kept")) == (None, 11, "ADR(t)")
    sim.cycle(1)
    fault = sim.fault
    assert fault is not None and (fault.code, fault.scan) == ("dangling_reference", 1)
    assert fault.message == (
        "dangling reference: ADR(t) refers to a variable of a call of FUNCTION_BLOCK KEEPER that has returned"
    )
    assert (fault.pou, fault.origin.line, fault.instance) == ("KEEPER", 9, "MAIN.F")  # last := kept^;
    assert fault.values["KEPT"] == "ADR(t)"
    assert sim.read("Main.f.last") == 11  # the faulting statement did not run


SHARED = """
VAR_GLOBAL g : POINTER TO INT; END_VAR
FUNCTION_BLOCK Filler
VAR_OUTPUT seen : INT; END_VAR
VAR_TEMP buf : ARRAY[0..2] OF INT; END_VAR
VAR_EXTERNAL g : POINTER TO INT; END_VAR
buf[1] := 42;
g := ADR(buf[0]) + SIZEOF(buf[0]);
seen := g^;
END_FUNCTION_BLOCK
PROGRAM Producer
VAR f : Filler; END_VAR
f();
END_PROGRAM
PROGRAM Consumer
VAR x : INT; END_VAR
VAR_EXTERNAL g : POINTER TO INT; END_VAR
x := g^;
END_PROGRAM
CONFIGURATION Cell
  RESOURCE Cpu ON PLC
    TASK Cyclic (INTERVAL := T#10ms, PRIORITY := 1);
    PROGRAM P WITH Cyclic : Producer;
    PROGRAM C WITH Cyclic : Consumer;
  END_RESOURCE
END_CONFIGURATION
"""


@pytest.mark.parametrize("variant", VARIANTS)
def test_another_pou_reading_a_kept_reference_to_a_temporary_gets_the_fault(variant):
    """The FB reads its temporary through the moved pointer while its call runs (seen = buf[1] = 42); the program
    that runs after it in the same scan reads the global pointer once the FB's call returned: the fault, in that
    program, naming the pointer as moved (``ADR(buf[0]) + 2``: INT is 2 bytes, TYP-45)."""
    sim = build(SHARED, variant).simulation()
    sim.cycle(1)
    assert sim.read("P.f.seen") == 42
    fault = sim.fault
    assert fault is not None and fault.code == "dangling_reference"
    assert (fault.pou, fault.origin.line, fault.instance) == ("CONSUMER", 18, "C")
    assert fault.message == (
        "dangling reference: ADR(buf[0]) + 2 refers to a variable of a call of FUNCTION_BLOCK FILLER that has returned"
    )
    assert sim.read("C.x") == 0


def test_writing_through_a_dangling_reference_to_a_program_temporary_is_the_fault_too():
    """A PROGRAM's VAR_TEMP kept in its VAR: written through in the next scan (``pm^ := 5``) is the fault; the new
    scan's tp is left alone (it holds what this scan assigned)."""
    text = """
PROGRAM Main
VAR pm : POINTER TO INT; k : INT; seen : INT; END_VAR
VAR_TEMP tp : INT; END_VAR
k := k + 1;
tp := k;
IF k = 2 THEN
  pm^ := 5;
END_IF;
pm := ADR(tp);
seen := tp;
END_PROGRAM
"""
    for variant in VARIANTS:
        sim = build(text, variant).simulation()
        sim.cycle(2)
        fault = sim.fault
        assert fault is not None and fault.code == "dangling_reference", variant
        assert (fault.pou, fault.origin.line, fault.scan) == ("MAIN", 8, 1), variant
        assert fault.message.endswith("ADR(tp) refers to a variable of a call of PROGRAM MAIN that has returned")
        assert (sim.read("Main.tp"), sim.read("Main.seen")) == (2, 1), variant


METHOD = """
FUNCTION_BLOCK Counter
VAR kept : REF_TO INT; total : INT; END_VAR
METHOD Add : INT
VAR_INPUT n : INT; END_VAR
VAR_TEMP t : INT; END_VAR
VAR r : REF_TO INT; END_VAR
r := REF(t);
r^ := n * 2;
kept := r;
total := total + t;
Add := total;
END_METHOD
METHOD Peek : INT
Peek := kept^;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR c : Counter; a : INT; p : INT; k : INT; END_VAR
k := k + 1;
a := c.Add(n := k);
IF k = 3 THEN
  p := c.Peek();
END_IF;
END_PROGRAM
"""


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_methods_temporary_lives_for_the_methods_call(variant):
    """In the method's call the reference to its VAR_TEMP writes it (t := 2n, total 2, 6, 12); kept in the
    instance, it dangles once the method returned: another method reading it is the fault."""
    sim = build(METHOD, variant).simulation()
    seen = []
    for _ in range(2):
        sim.cycle(1)
        seen.append(sim.read("Main.a"))
    assert seen == [2, 6] and sim.fault is None
    sim.cycle(1)
    fault = sim.fault
    assert fault is not None and fault.code == "dangling_reference" and sim.read("Main.a") == 12
    assert (
        fault.message
        == "dangling reference: REF(t) refers to a variable of a call of METHOD COUNTER.ADD that has returned"
    )
    assert (fault.pou, fault.origin.line) == ("COUNTER.PEEK", 15)


def test_pous_without_such_references_generate_the_code_they_have_alone():
    """Only a POU that takes REF()/ADR() of its VAR_TEMP gets a frame, ended by ``finally`` however its call ends.
    A plain FB with a VAR_TEMP in the same project generates exactly the code it has alone: no frame, no ``try``."""
    plain = (
        "FUNCTION_BLOCK Plain\nVAR_INPUT a : INT; END_VAR\nVAR_OUTPUT q : INT; END_VAR\nVAR_TEMP t : INT; END_VAR\n"
        "t := a + 1;\nq := t * 2;\nEND_FUNCTION_BLOCK\n"
    )
    alone = plain + "PROGRAM Main\nVAR p : Plain; END_VAR\np(a := 1);\nEND_PROGRAM\n"
    both = plain + KEEPER.replace("f();", "f();\np(a := 1);").replace("VAR f : Keeper;", "VAR f : Keeper; p : Plain;")
    sources = [build(text, "fast").compiled.source for text in (alone, both)]

    def code_of(source: str, pou: str) -> str:
        start = source.index(f"def ll_x_{pou}")
        return source[start : source.index(f"P_{pou}.execute = ", start)]

    assert code_of(sources[0], "PLAIN") == code_of(sources[1], "PLAIN")
    assert "ll_Frame" not in code_of(sources[1], "PLAIN") and "try:" not in code_of(sources[1], "PLAIN")
    keeper = code_of(sources[1], "KEEPER")
    assert "ll_fr = ll_Frame('KEEPER', 'FUNCTION_BLOCK')" in keeper and "finally:\n        ll_fr.end(None)" in keeper


def test_online_a_pointer_to_a_temporary_shows_its_value_and_its_target_only_while_it_lives():
    """ON-11: the pointer's own value is always shown; ``kept^`` names a variable while the call that owns it runs
    (halted inside it, the debug variant), and no variable once it returned (NoTarget, never a Python error)."""
    sim = build(KEEPER, "debug").simulation()
    sim.set_breakpoint("Keeper", line=12)  # last := kept^ + 1; kept := ADR(t) ran
    sim.cycle(1)
    assert sim.halted is not None
    assert (sim.read("Main.f.kept"), sim.read("Main.f.kept^")) == ("ADR(t)", 10)
    assert [f.pou for f in sim.call_stack()] == ["MAIN", "KEEPER"]
    sim.clear_breakpoints()
    sim.resume()
    assert sim.fault is None and sim.read("Main.f.kept") == "ADR(t)"
    with pytest.raises(NoTarget, match="KEPT\\^: dangling reference: ADR\\(t\\) refers to"):
        sim.read("Main.f.kept^")
    watched = sim.reader({"MAIN.F.KEPT": sim.location("Main.f.kept"), "MAIN.F.KEPT^": sim.location("Main.f.kept^")})
    assert watched.read() == {"MAIN.F.KEPT": "ADR(t)", "MAIN.F.KEPT^": None}


IN_OUT = """
TYPE Pair : STRUCT a : INT; b : INT; END_STRUCT; END_TYPE
VAR_GLOBAL g : POINTER TO INT; h : POINTER TO INT; m : REF_TO INT; END_VAR
FUNCTION Grab : INT
VAR_IN_OUT io : INT; arr : ARRAY[1..3] OF INT; st : Pair; END_VAR
VAR_EXTERNAL g : POINTER TO INT; h : POINTER TO INT; m : REF_TO INT; END_VAR
g := ADR(io);
g^ := g^ + 1;
h := ADR(arr[2]);
m := REF(st.b);
Grab := io;
END_FUNCTION
"""


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_functions_reference_to_its_in_out_is_the_callers_variable_after_the_call(variant):
    """VAR-51: the in-out is the caller's variable, so ADR(io) refers to it: the reference outlives the function's
    call, reading it gives the caller's variable and writing it changes that variable, scan by scan. a: +1 in the
    call, +10 after it; arr[2] and s.b: +1 after each call."""
    text = (
        IN_OUT
        + """
PROGRAM Main
VAR a, b, c : INT; arr : ARRAY[1..3] OF INT; s : Pair; END_VAR
VAR_EXTERNAL g : POINTER TO INT; h : POINTER TO INT; m : REF_TO INT; END_VAR
b := Grab(a, arr, s);
c := g^;
g^ := g^ + 10;
h^ := h^ + 1;
m^ := m^ + 1;
END_PROGRAM
"""
    )
    sim = build(text, variant).simulation()
    for scan in (1, 2, 3):
        sim.cycle(1)
        assert sim.fault is None, sim.fault.text()
        a = 11 * scan
        assert [sim.read(f"Main.{v}") for v in ("a", "b", "c")] == [a, a - 10, a - 10]
        assert (sim.read("Main.arr"), sim.read("Main.s.b")) == ([0, scan, 0], scan)


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_reference_to_an_in_out_bound_to_a_functions_local_dies_with_that_call(variant):
    """The caller's variable is Outer's local x (and its array): the reference Grab takes of its in-out works in
    Outer's call after Grab returned (x = 5 + 1, a[2] = 2: 6 * 100 + 2), and dies when Outer returns."""
    text = (
        IN_OUT
        + """
FUNCTION Outer : INT
VAR x : INT := 5; a : ARRAY[1..3] OF INT := [1, 2, 3]; s : Pair; END_VAR
VAR_EXTERNAL g : POINTER TO INT; h : POINTER TO INT; END_VAR
Grab(x, a, s);
Outer := g^ * 100 + h^;
END_FUNCTION
PROGRAM Main
VAR b, c : INT; END_VAR
VAR_EXTERNAL g : POINTER TO INT; END_VAR
b := Outer();
c := g^;
END_PROGRAM
"""
    )
    sim = build(text, variant).simulation()
    sim.cycle(1)
    assert sim.read("Main.b") == 602
    fault = sim.fault
    assert fault is not None and fault.code == "dangling_reference" and (fault.pou, fault.origin.line) == ("MAIN", 24)
    assert (
        fault.message
        == "dangling reference: ADR(io) refers to a variable of a call of FUNCTION OUTER that has returned"
    )


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_reference_to_an_in_out_bound_to_a_temporary_dies_with_the_fbs_call(variant):
    """The caller's variable is an FB's VAR_TEMP: within the FB's call the reference reads it (o = 9 + 1); the next
    scan, through the global, it is the fault, not the new call's t."""
    text = (
        IN_OUT
        + """
FUNCTION_BLOCK User
VAR_OUTPUT o : INT; END_VAR
VAR_TEMP t : INT; ta : ARRAY[1..3] OF INT; ts : Pair; END_VAR
VAR_EXTERNAL g : POINTER TO INT; END_VAR
t := 9;
Grab(t, ta, ts);
o := g^;
END_FUNCTION_BLOCK
PROGRAM Main
VAR u : User; k, late : INT; END_VAR
VAR_EXTERNAL m : REF_TO INT; END_VAR
k := k + 1;
IF k = 2 THEN
  late := m^;
END_IF;
u();
END_PROGRAM
"""
    )
    sim = build(text, variant).simulation()
    sim.cycle(1)
    assert (sim.fault, sim.read("Main.u.o")) == (None, 10)
    sim.cycle(1)
    fault = sim.fault
    assert fault is not None and fault.code == "dangling_reference" and (fault.pou, fault.origin.line) == ("MAIN", 27)
    assert fault.message == (
        "dangling reference: REF(st.b) refers to a variable of a call of FUNCTION_BLOCK USER that has returned"
    )


def test_a_reference_through_a_pointer_to_a_temporary_dies_with_it():
    """``ADR(p^)`` is the variable p points to: the VAR_TEMP, so it dies with the call as p does."""
    text = """
FUNCTION_BLOCK Twice
VAR q : POINTER TO INT; k, seen : INT; END_VAR
VAR_TEMP t : INT; p : POINTER TO INT; END_VAR
k := k + 1;
t := k;
IF k = 2 THEN
  seen := q^;
END_IF;
p := ADR(t);
q := ADR(p^);
seen := q^;
END_FUNCTION_BLOCK
PROGRAM Main
VAR f : Twice; END_VAR
f();
END_PROGRAM
"""
    for variant in VARIANTS:
        sim = build(text, variant).simulation()
        sim.cycle(1)
        assert (sim.fault, sim.read("Main.f.seen")) == (None, 1), variant
        sim.cycle(1)
        fault = sim.fault
        assert fault is not None and (fault.code, fault.origin.line) == ("dangling_reference", 8), variant
        assert fault.message.startswith("dangling reference: ADR(p^) refers to a variable of a call of FUNCTION_BLOCK")


HOLDER = """
FUNCTION_BLOCK Holder
VAR_IN_OUT io : INT; END_VAR
VAR_OUTPUT o : INT; END_VAR
VAR p : POINTER TO INT; END_VAR
p := ADR(io);
p^ := p^ + 1;
o := p^;
END_FUNCTION_BLOCK
PROGRAM Main
VAR h : Holder; k : INT; END_VAR
VAR_TEMP t : INT; END_VAR
k := k + 1;
t := k * 10;
IF k = 2 THEN
  RETURN;
END_IF;
h(io := t);
END_PROGRAM
"""


@pytest.mark.parametrize("variant", VARIANTS)
def test_an_fb_in_out_bound_to_a_temporary_and_a_captured_state(variant):
    """An FB's in-out bound to the program's VAR_TEMP: through ADR(io) the FB writes the program's t (t = 10k + 1,
    o = t). A state captured between scans (the in-out's reference is left out, docs/runtime.md) pickles and
    restores; the FB's p then refers to a gone t. Scan 2 leaves by RETURN before the call: its frame ends too."""
    sim = build(HOLDER, variant).simulation()
    sim.cycle(1)
    assert (sim.fault, sim.read("Main.t"), sim.read("Main.h.o"), sim.read("Main.h.p")) == (None, 11, 11, "ADR(io)")
    sim.cycle(1)
    assert (sim.fault, sim.read("Main.t"), sim.read("Main.h.o")) == (None, 20, 11)  # RETURN: h not called
    with pytest.raises(
        NoTarget, match="dangling reference: ADR\\(io\\) refers to a variable of a call of PROGRAM MAIN"
    ):
        sim.read("Main.h.p^")
    restored = build(HOLDER, variant).simulation()
    restored.restore(pickle.loads(pickle.dumps(sim.state())))
    restored.cycle(1)
    assert (restored.fault, restored.read("Main.t"), restored.read("Main.h.o")) == (None, 31, 31)


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_codesys_reference_bound_to_a_temporary_with_ref_assign(variant):
    """CODESYS ``REFERENCE TO`` bound with ``REF=`` to a VAR_TEMP: read and written without ``^`` in the call (t := 3k
    through r, out = t + 1); kept in the FB's VAR, read in the next call, it is the fault."""
    text = """
FUNCTION_BLOCK Bound
VAR_OUTPUT out : INT; END_VAR
VAR kept : REFERENCE TO INT; k : INT; END_VAR
VAR_TEMP t : INT; r : REFERENCE TO INT; END_VAR
k := k + 1;
IF k = 3 THEN
  out := kept;
END_IF;
r REF= t;
r := k * 3;
out := t + 1;
kept REF= t;
END_FUNCTION_BLOCK
PROGRAM Main
VAR b : Bound; END_VAR
b();
END_PROGRAM
"""
    sim = build(text, variant).simulation()
    for k in (1, 2):
        sim.cycle(1)
        assert (sim.fault, sim.read("Main.b.out")) == (None, 3 * k + 1)
    sim.cycle(1)
    fault = sim.fault
    assert fault is not None and (fault.code, fault.origin.line) == ("dangling_reference", 8)
    assert (
        fault.message
        == "dangling reference: REF(t) refers to a variable of a call of FUNCTION_BLOCK BOUND that has returned"
    )


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_derived_blocks_temporaries_outlive_its_call_of_the_base_body(variant):
    """SUPER^() runs the base's body, which has a frame of its own (its VAR_TEMP t): when that call returns, the
    derived body's reference to its own u still works (u := 7, then + 1 after SUPER^(); b = 4; d = 8 + 4)."""
    text = """
FUNCTION_BLOCK Base
VAR_OUTPUT b : INT; END_VAR
VAR_TEMP t : INT; p : POINTER TO INT; END_VAR
p := ADR(t);
p^ := 4;
b := t;
END_FUNCTION_BLOCK
FUNCTION_BLOCK Derived EXTENDS Base
VAR_OUTPUT d : INT; END_VAR
VAR_TEMP u : INT; q : POINTER TO INT; END_VAR
q := ADR(u);
q^ := 7;
SUPER^();
q^ := q^ + 1;
d := u + b;
END_FUNCTION_BLOCK
PROGRAM Main
VAR x : Derived; END_VAR
x();
END_PROGRAM
"""
    sim = build(text, variant).simulation()
    for _ in range(2):
        sim.cycle(1)
        assert (sim.fault, sim.read("Main.x.b"), sim.read("Main.x.d")) == (None, 4, 12)
