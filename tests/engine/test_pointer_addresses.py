"""A pointer as a number under CODESYS typing (issue 25, docs/st.md "A pointer as a number"): CODESYS's "Pointers"
page, "a pointer holds the address of the object": a POINTER is assigned to and from a DWORD on a 32-bit target
(SIZEOF of a pointer is 4 here), compared with one as an address. LadderLab gives each variable whose address is
taken a synthetic base address, aligned to 8, never 0; what is asserted is what every PLC guarantees: a number
made from a pointer leads back to the byte it pointed to, bytes of one variable are consecutive, 0 is NULL, an
aligned variable's address is a multiple of 4, and a number in no variable is a located fault when it is used.
"""

from __future__ import annotations

import functools
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.engine.codegen.views import layout
from ladderlab.ir.byte_layout import byte_layout
from ladderlab.ir.types import Array, Elementary, Struct, StructField
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project
from ladderlab.st.types import typing_rules

from .ed3_support import program

VARIANTS = ("fast", "monitor", "debug")


def _build(text: str, typing: str = "codesys", variant: str = "fast"):
    with typing_rules(typing):
        project, diagnostics = source_to_project(text, "addresses")
    assert project is not None and not [d for d in diagnostics if d.severity == "error"], diagnostics
    return build_project(project.model_copy(update={"typing": typing}), variant)


def _simulation(declarations: str, body: str, variant: str = "fast"):
    result = _build(program(declarations, body), variant=variant)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    return result.simulation()


def _errors(declarations: str, body: str, typing: str) -> list[str]:
    result = _build(program(declarations, body), typing)
    return [f"{d.code} {d.line}:{d.column} {d.message}" for d in result.diagnostics if d.severity == "error"]


@pytest.mark.parametrize("variant", VARIANTS)
def test_an_address_as_a_number_leads_back_to_its_byte_and_bytes_are_consecutive(variant):
    sim = _simulation(
        "buf : ARRAY[0..7] OF BYTE := [10, 11, 12, 13, 14, 15, 16, 17]; d : DWORD;"
        "a0, a3, whole, dd : DWORD; l : LWORD; pt : POINTER TO BYTE; pw : POINTER TO WORD; b : BYTE; w : WORD;"
        "step, aligned, lower, nul : BOOL; pn : POINTER TO BYTE; zero : DWORD;",
        "a0 := ADR(buf[0]);\na3 := ADR(buf[3]);\nwhole := ADR(buf);\nl := ADR(buf[1]);\n"
        "pt := a3 + 2;\nb := pt^;\npw := a0 + 6;\nw := pw^;\npw^ := 16#BEEF;\n"
        "step := a3 - a0 = 3;\ndd := ADR(d);\naligned := (dd AND 3) = 0 AND (a0 AND 3) = 0;\n"
        "lower := ADR(buf[1]) < a3 AND a3 > ADR(buf[1]) AND a3 <= a3;\npn := ADR(b);\npn := zero;\nnul := pn = 0;",
        variant,
    )
    sim.cycle(1)
    assert sim.fault is None, sim.fault.text()
    assert sim.read("Main.b") == 15 and sim.read("Main.w") == 0x1110  # buf[5]; buf[6..7] little-endian
    first = sim.read("Main.a0")
    sim.cycle(1)  # the addresses stay for the simulation's life: the second scan reads what the first wrote
    assert sim.fault is None and sim.read("Main.a0") == first and sim.read("Main.w") == 0xBEEF
    assert sim.read("Main.buf")[6:] == [0xEF, 0xBE]
    assert sim.read("Main.whole") == sim.read("Main.a0") != 0  # an array's address is its first element's
    assert sim.read("Main.l") == sim.read("Main.a0") + 1
    assert (sim.read("Main.step"), sim.read("Main.aligned"), sim.read("Main.lower")) == (True, True, True)
    assert sim.read("Main.nul") and sim.read("Main.pn") == "NULL"
    assert sim.read("Main.pt") == "ADR(buf) + 5"  # the online view names the variable the number lies in


#: The round trip: a pointer into a ten-byte buffer at element 2, moved by k as a pointer (q) and as a number (dw).
_ROUND_TRIP = program(
    "buf : ARRAY[0..9] OF BYTE := [100, 101, 102, 103, 104, 105, 106, 107, 108, 109]; k : DINT;"
    "pt, q, back : POINTER TO BYTE; dw, again : DWORD; direct, via : BYTE;",
    "pt := ADR(buf[2]);\nq := pt + k;\ndw := q;\nback := dw;\nvia := back^;\ndirect := q^;\nagain := back;",
)


@functools.cache
def _round_trip(variant: str):
    result = _build(_ROUND_TRIP, variant=variant)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    return result


@settings(max_examples=40, deadline=None)
@given(k=st.integers(-12, 12), variant=st.sampled_from(VARIANTS))
def test_a_pointer_made_from_the_number_of_pt_plus_k_reaches_the_byte_pt_plus_k_does(k, variant):
    sim = _round_trip(variant).simulation()
    sim.write("Main.k", k)
    sim.cycle(1)
    if 0 <= 2 + k < 10:  # inside the buffer: the same byte either way
        assert sim.fault is None, sim.fault.text()
        assert sim.read("Main.via") == sim.read("Main.direct") == 102 + k
        assert sim.read("Main.back") == "ADR(buf)" + (f" + {2 + k}" if k != -2 else "")  # named from its variable
        assert sim.read("Main.again") == sim.read("Main.dw")
    else:  # outside (one past its end included: nothing to read there) it is a located fault, never a value
        assert sim.fault is not None and sim.fault.code == "index_out_of_range"
        assert sim.fault.pou == "MAIN" and sim.fault.origin.line in (7, 10)  # q := pt + k; via := back^;
        assert sim.read("Main.via") == sim.read("Main.direct") == 0


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_number_in_no_variable_is_a_located_fault_when_read_through(variant):
    sim = _simulation(
        "x : DINT := 7; dw : DWORD; p : POINTER TO DINT; y : DINT;",
        "dw := ADR(x);\np := dw + 4;\ny := p^;",  # one past x's end: x's own, nothing to read
        variant,
    )
    sim.cycle(1)
    assert sim.fault is not None and (sim.fault.code, sim.fault.origin.line) == ("index_out_of_range", 8)
    assert sim.fault.message == "the pointer ADR(x) + 4 reaches bytes 4..7 of a 4-byte variable: outside it"
    sim = _simulation(
        "x : DINT := 7; dw : DWORD := 16#40; p : POINTER TO DINT; y : DINT;", "p := dw;\ny := p^;", variant
    )
    sim.cycle(1)
    assert sim.fault is not None and (sim.fault.code, sim.fault.origin.line) == ("index_out_of_range", 7)
    assert sim.fault.message == "the pointer 16#40 reaches the address 64, which lies in no variable"
    assert sim.read("Main.y") == 0


def test_an_address_is_a_number_under_codesys_typing_only_and_in_32_bits_or_more():
    declarations = "x : DINT; pt : POINTER TO DINT; dw : DWORD; w : WORD; di : DINT; ok : BOOL;"
    assert _errors(declarations, "dw := ADR(x);\npt := dw;\nok := pt < dw;", "codesys") == []
    assert _errors(declarations, "pt := ADR(x);\ndw := pt;\nok := pt < dw;", "iec") == [
        "ST-TYPE-MISMATCH 7:7 cannot assign REF_TO DINT to DWORD",
        "ST-TYPE-MISMATCH 8:7 '<' needs operands of the same type: REF_TO DINT and DWORD; convert one of them "
        "(e.g. a *_TO_* conversion)",
    ]
    assert _errors(declarations, "pt := ADR(x);\nw := pt;\ndi := pt;", "codesys") == [
        "ST-TYPE-MISMATCH 7:6 cannot assign REF_TO DINT to WORD",
        "ST-TYPE-MISMATCH 8:7 cannot assign REF_TO DINT to DINT",
    ]


def test_a_pointer_to_what_has_no_bytes_is_no_number():
    assert _errors("t : TIME; pt : POINTER TO TIME; dw : DWORD;", "pt := ADR(t);\ndw := pt;", "codesys") == [
        "IR-UNSUPPORTED 7:1 a pointer as a number needs the bytes of what it points to: a TIME (its bytes in CODESYS "
        "are not the value LadderLab keeps)"
    ]


# --- A part's address: its outermost variable's base plus its byte offset (ADR(rec.m) - ADR(rec) is m's offset).
#
# Random STRUCT / array nestings. The expected offsets come from CODESYS's layout rules as docs/st.md states them
# (CODESYS's page "Attribute: pack_mode", content.helpme-codesys.com, _cds_pragma_attribute_pack_mode): a member lies
# at the next multiple of its alignment (a number's size, 1 for BOOL and STRING[n], an array's element's, a STRUCT's
# largest capped alignment) capped by the pack_mode; a STRUCT's size is rounded up to a multiple of its largest
# capped alignment; an array's elements follow one another, the first dimension outermost (row-major). ``_model``
# works them out by those rules alone; ir/byte_layout.py must agree, and so must the engine's addresses.

#: Leaf types: (name, size); the numeric ones are read and written through the pointer made from a number.
_NUMBERS = (("BYTE", 1), ("INT", 2), ("WORD", 2), ("DINT", 4), ("REAL", 4), ("LREAL", 8))
_FILLERS = (("BOOL", 1), ("STRING[3]", 4))


def _leaves(numeric: bool):
    return st.sampled_from(_NUMBERS if numeric else _NUMBERS + _FILLERS).map(lambda leaf: ("leaf", *leaf))


def _nesting(depth: int, numeric: bool, leaf: bool = True):
    """A type whose every path ends in a leaf (``leaf`` False: no leaf itself); ``numeric``: the path ``_path``
    takes ends in a number."""
    if depth == 0:
        return _leaves(numeric)
    inner = _nesting(depth - 1, numeric)
    sizes = st.lists(st.tuples(st.integers(-1, 1), st.integers(1, 3)), min_size=1, max_size=2)
    dims = sizes.map(lambda ds: tuple((lo, lo + n - 1) for lo, n in ds))
    arrays = dims.flatmap(  # (the element ``_path`` takes: an index in each dimension)
        lambda ds: st.tuples(st.just("array"), st.just(ds), inner, st.tuples(*(st.integers(*d) for d in ds)))
    )
    others = st.lists(_nesting(depth - 1, False), min_size=0, max_size=3)
    structs = st.builds(
        lambda pack, first, rest, at: ("struct", pack, (*rest[:at], first, *rest[at:]), min(at, len(rest))),
        st.sampled_from((None, 1, 2, 4, 8)),
        inner,
        others,
        st.integers(0, 3),
    )
    return st.one_of(_leaves(numeric), arrays, structs) if leaf else st.one_of(arrays, structs)


def _eight_bytes(ty) -> bool:
    if ty[0] == "leaf":
        return ty[2] == 8
    return _eight_bytes(ty[2]) if ty[0] == "array" else any(_eight_bytes(m) for m in ty[2])


def _model(ty) -> tuple[int, int]:
    """(size, alignment) of a test type by CODESYS's rules (above); a STRUCT's pack_mode caps its members'."""
    if ty[0] == "leaf":
        return ty[2], 1 if ty[1].startswith(("STRING", "BOOL")) else ty[2]
    if ty[0] == "array":
        size, align = _model(ty[2])
        return size * math.prod(hi - lo + 1 for lo, hi in ty[1]), align
    end, largest = 0, 1
    for member in ty[2]:
        size, align = _model(member)
        align = min(align, _pack(ty))
        end += -end % align
        end += size
        largest = max(largest, align)
    return end + -end % largest, largest


def _pack(ty) -> int:
    """A STRUCT's pack_mode; one holding an 8-byte number gets 8 when it has none, written out (without it the
    target decides: docs/st.md, IR-UNSUPPORTED)."""
    return ty[1] or (8 if _eight_bytes(ty) else 4)


def _path(ty) -> list[tuple[str, int]]:
    """The parts the test takes, outermost first, each as (its ST selector text, its offset by ``_model``): the
    chosen member of each STRUCT, the chosen element of each array."""
    parts, offset = [], 0
    while ty[0] != "leaf":
        if ty[0] == "array":
            element, _ = _model(ty[2])
            indices, flat = ty[3], 0
            for (lo, hi), index in zip(ty[1], indices, strict=True):
                flat = flat * (hi - lo + 1) + index - lo
            offset += flat * element
            parts.append(("[" + ", ".join(map(str, indices)) + "]", offset))
            ty = ty[2]
        else:
            chosen, end = ty[3], 0
            for number, member in enumerate(ty[2]):
                size, align = _model(member)
                end += -end % min(align, _pack(ty))
                if number == chosen:
                    break
                end += size
            offset += end
            parts.append((f".m{chosen}", offset))
            ty = ty[2][chosen]
    return parts


def _leaf(ty):
    """The leaf ``_path`` ends in."""
    while ty[0] != "leaf":
        ty = ty[2] if ty[0] == "array" else ty[2][ty[3]]
    return ty


def _st_type(ty, types: list[str]) -> str:
    """The ST text of a test type; its STRUCTs' TYPE declarations go to ``types``, inner ones first."""
    if ty[0] == "leaf":
        return ty[1]
    if ty[0] == "array":
        return f"ARRAY[{', '.join(f'{lo}..{hi}' for lo, hi in ty[1])}] OF {_st_type(ty[2], types)}"
    members = " ".join(f"m{n} : {_st_type(member, types)};" for n, member in enumerate(ty[2]))
    name = f"S{len(types)}"
    pragma = f"{{attribute 'pack_mode' := '{_pack(ty)}'}}\n" if ty[1] or _eight_bytes(ty) else ""
    types.append(f"{pragma}TYPE {name} : STRUCT {members} END_STRUCT; END_TYPE")
    return name


def _ir_type(ty):
    """The same type as the lowering's (ir/types.py), for ir/byte_layout.py."""
    if ty[0] == "leaf":
        return Elementary("STRING", 3) if ty[1] == "STRING[3]" else Elementary(ty[1])
    if ty[0] == "array":
        return Array(_ir_type(ty[2]), ty[1])
    fields = tuple(StructField(f"M{n}", _ir_type(member)) for n, member in enumerate(ty[2]))
    return Struct("S", fields, _pack(ty) if ty[1] or _eight_bytes(ty) else None)


def _spec_offsets(spec, ty) -> list[int]:
    """The offsets ir/byte_layout.py's ``spec`` gives the parts ``_path`` takes."""
    found, offset = [], 0
    while ty[0] != "leaf":
        if ty[0] == "array":
            for (lo, _), index in zip(ty[1], ty[3], strict=True):  # ("array", count, element) per dimension, the
                spec = spec[2]  # first outermost
                offset += (index - lo) * layout(spec).size
            ty = ty[2]
        else:
            _, start, spec = spec[4][ty[3]]
            offset += start
            ty = ty[2][ty[3]]
        found.append(offset)
    return found


@settings(max_examples=30, deadline=None)
@given(ty=_nesting(3, True, leaf=False), variant=st.sampled_from(VARIANTS))
def test_a_parts_address_is_its_outer_variables_plus_its_byte_offset(ty, variant):
    """``ADR(v.part) - ADR(v)`` is the part's offset for every part along a path through random STRUCTs and arrays;
    ``pt := ADR(v) + offset`` reads and writes the part; ``ADR(v)`` moved by the offset (TYP-43, bytes) and the
    number a FUNCTION makes of its POINTER parameter given ``ADR(v.part)`` are that same number."""
    types: list[str] = []
    declared = _st_type(ty, types)
    parts = _path(ty)
    offsets = [offset for _, offset in parts]
    assert _spec_offsets(byte_layout(_ir_type(ty)), ty) == offsets  # ir/byte_layout.py agrees with the rules
    leaf = _leaf(ty)
    path = "".join(text for text, _ in parts)
    names = [f"o{n}" for n in range(len(parts))]
    text = program(
        f"v : {declared}; base, n, e, f, {', '.join(names)} : DWORD; pt : POINTER TO {leaf[1]}; pb : POINTER TO BYTE;"
        f"r, w : {leaf[1]};",
        "base := ADR(v);\n"
        + "".join(f"{name} := ADR(v{''.join(t for t, _ in parts[: k + 1])});\n" for k, name in enumerate(names))
        + f"v{path} := 42;\nn := base + {offsets[-1]};\npt := n;\nr := pt^;\npt^ := 7;\nw := v{path};\n"
        f"pb := ADR(v);\npb := pb + ({names[-1]} - base);\ne := pb;\nf := AddrOf(ADR(v{path}));",
        "\n".join(types)
        + f"\nFUNCTION AddrOf : DWORD\nVAR_INPUT p : POINTER TO {leaf[1]}; END_VAR\nAddrOf := p;\nEND_FUNCTION\n",
    )
    result = _build(text, variant=variant)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    sim = result.simulation()
    sim.cycle(1)
    assert sim.fault is None, sim.fault.text()
    base = sim.read("Main.base")
    assert [sim.read(f"Main.{name}") - base for name in names] == offsets
    assert (sim.read("Main.r"), sim.read("Main.w")) == (42, 7)  # pt := base + offset reached v's part, both ways
    assert sim.read("Main.e") == sim.read("Main.f") == base + offsets[-1]  # moved from ADR(v); through a FUNCTION


_PARTS_TYPES = """TYPE Rec : STRUCT x : BYTE; m : INT; END_STRUCT END_TYPE
TYPE Timed : STRUCT t : TIME; arr : ARRAY[0..3] OF INT; END_STRUCT END_TYPE
FUNCTION OfMember : DWORD
VAR_IN_OUT io : Rec; END_VAR
OfMember := ADR(io.m);
END_FUNCTION
FUNCTION_BLOCK Holder
VAR_OUTPUT rec : Rec; inner : DWORD; END_VAR
inner := ADR(rec.m);
END_FUNCTION_BLOCK
FUNCTION_BLOCK OfHeld
VAR_IN_OUT h : Holder; END_VAR
VAR_OUTPUT place : DWORD; END_VAR
place := ADR(h.rec.m);
END_FUNCTION_BLOCK
FUNCTION OfLocal : DWORD
VAR r : Rec; base : DWORD; END_VAR
OfLocal := OfMember(r);
base := ADR(r);
OfLocal := OfLocal - base;
END_FUNCTION
"""


@pytest.mark.parametrize("variant", VARIANTS)
def test_the_parts_of_an_fb_instances_variable_and_of_one_passed_in_out_lie_in_it(variant):
    """An FB instance has no byte layout (CODESYS documents none): its variables are variables of their own, and a
    STRUCT among them is the outermost variable of its members (Rec: x at 0, m at 2). A VAR_IN_OUT's part lies in
    the caller's variable (the caller passing it tells the engine so), a FUNCTION's own variable's too."""
    result = _build(
        program(
            "h : Holder; hs : ARRAY[0..2] OF Holder; rec : Rec; base, m, b2, m2, via, r0, io, local : DWORD;",
            "h();\nbase := ADR(h.rec);\nm := ADR(h.rec.m);\nb2 := ADR(hs[1].rec);\nm2 := ADR(hs[1].rec.m);\n"
            "via := h.inner;\nio := OfMember(rec);\nr0 := ADR(rec);\nlocal := OfLocal();",
            _PARTS_TYPES,
        ),
        variant=variant,
    )
    sim = result.simulation()
    sim.cycle(1)
    assert sim.fault is None, sim.fault.text()
    values = {name: sim.read(f"Main.{name}") for name in ("base", "m", "b2", "m2", "via", "r0", "io")}
    assert values["m"] - values["base"] == values["m2"] - values["b2"] == values["io"] - values["r0"] == 2
    assert values["via"] == values["m"]  # the FB's own ADR(rec.m) is the one taken from outside
    assert sim.read("Main.local") == 2  # a FUNCTION's own variable passed in-out


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_part_with_no_exact_address_is_a_located_fault_as_a_number(variant):
    """A part of a STRUCT that has no byte layout (a TIME member: CODESYS's bytes are not LadderLab's value), or one
    whose variable the engine was never told of (a STRUCT inside an FB instance passed to a VAR_IN_OUT, the FB
    never run), has no exact address: taking it as a number is the fault invalid_argument at its line, never a
    made-up number."""
    sim = _build(
        program("tm : Timed; dw : DWORD;", "dw := 1;\ndw := ADR(tm.arr[1]);", _PARTS_TYPES), variant=variant
    ).simulation()
    sim.cycle(1)
    assert sim.fault is not None
    assert (sim.fault.code, sim.fault.pou, sim.fault.origin.line) == ("invalid_argument", "MAIN", 28)
    assert sim.fault.message == (
        "the pointer ADR(tm.arr[1]) as a number: it points into tm, which has no byte layout, so where it lies there "
        "is unknown: the STRUCT TIMED, whose member T is a TIME (its bytes in CODESYS are not the value LadderLab keeps)"
    )
    assert sim.read("Main.dw") == 1
    sim = _build(program("h : Holder; o : OfHeld;", "o(h := h);", _PARTS_TYPES), variant=variant).simulation()
    sim.cycle(1)
    assert sim.fault is not None
    assert (sim.fault.code, sim.fault.pou, sim.fault.origin.line) == ("invalid_argument", "OFHELD", 14)
    assert sim.fault.message == (
        "the pointer ADR(h.rec.m) as a number: the STRUCT or array it points into was reached through an FB instance "
        "passed to a VAR_IN_OUT, a pointer or a path calling a function, so which variable it is part of is unknown "
        "here (take that variable's address where it is declared first: ADR(x))"
    )
    sim = _build(
        program("h : Holder; o : OfHeld; m : DWORD;", "m := ADR(h.rec.m);\no(h := h);", _PARTS_TYPES), variant=variant
    ).simulation()
    sim.cycle(1)
    assert sim.fault is None and sim.read("Main.o.place") == sim.read("Main.m")  # told of h.rec first: exact


@pytest.mark.parametrize("variant", VARIANTS)
def test_pointers_to_one_byte_are_equal_however_they_got_there(variant):
    """``p = q`` compares what the pointers point to: ``ADR(rec) + 2`` is ``ADR(rec.m)`` (Rec: m at 2), and so is a
    pointer made from ``ADR(rec.m)``'s number; ``ADR(rec) + 1`` (padding) is not. ``p < q`` orders the bytes of one
    variable alike: ``ADR(buf) + 3`` (moved from the whole array) lies after ``ADR(buf[1])``, at ``ADR(buf[3])``."""
    sim = _build(
        program(
            "rec : Rec; pb, pm, back, pad, pe : POINTER TO BYTE; dw : DWORD; buf : ARRAY[0..7] OF BYTE;"
            "moved, made, other, differ, ordered : BOOL;",
            "pb := ADR(rec);\npb := pb + 2;\npm := ADR(rec.m);\nmoved := pb = pm;\ndw := pm;\nback := dw;\n"
            "made := back = pm AND back = pb;\npad := ADR(rec);\npad := pad + 1;\nother := pad = pm;\n"
            "differ := pad <> pm AND NOT (back <> pb);\npe := ADR(buf);\npe := pe + 3;\n"
            "ordered := pad < pm AND pb <= pm AND pe > ADR(buf[1]) AND pe >= ADR(buf[3]) AND NOT (pe < ADR(buf[3]));",
            _PARTS_TYPES,
        ),
        variant=variant,
    ).simulation()
    sim.cycle(1)
    assert sim.fault is None, sim.fault.text()
    names = ("moved", "made", "other", "differ", "ordered")
    assert [sim.read(f"Main.{name}") for name in names] == [True, True, False, True, True]
