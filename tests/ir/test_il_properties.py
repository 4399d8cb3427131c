"""Random IL programs against an independent IL interpreter written here from the spec (IL-05, IL-10..IL-14,
IL-20..IL-22), and against their own ST export (issue 26).

The interpreter below follows the spec's words, not the implementation: the accumulator takes the loaded
value, ``OP x`` is ``acc := acc OP x``, N negates the operand, ``OP(`` pushes (OP, acc) and ``)`` computes
``acc := saved OP acc`` (ANDN( negates the bracket), comparisons give a BOOL, ST/STN/S/R leave the accumulator,
S/R act only on a TRUE accumulator, JMPC jumps on TRUE.
"""

from __future__ import annotations

import operator

from hypothesis import given
from hypothesis import strategies as st

from ladderlab.engine.simulation import Simulation
from ladderlab.st.project_text import source_to_project
from tests.interchange.st_support import same_traces
from tests.ir.helpers import lower_ok
from tests.support import fuzz_settings

BOOLS = ["a", "b", "c", "x", "y"]
INTS = ["i", "j", "k"]
DECLARATIONS = "a, b, c, x, y : BOOL; i, j, k : INT;"

_BOOL_OPS = {"AND": operator.and_, "OR": operator.or_, "XOR": operator.xor}
_INT_OPS = {"ADD": operator.add, "SUB": operator.sub, "MUL": operator.mul}
_COMPARE = {
    "GT": operator.gt,
    "GE": operator.ge,
    "EQ": operator.eq,
    "NE": operator.ne,
    "LE": operator.le,
    "LT": operator.lt,
}


@st.composite
def bool_chunk(draw) -> list[str]:
    lines = [f"{draw(st.sampled_from(['LD', 'LDN']))} {draw(st.sampled_from(BOOLS))}"]
    for _ in range(draw(st.integers(0, 4))):
        op = draw(st.sampled_from(["AND", "OR", "XOR"])) + draw(st.sampled_from(["", "N"]))
        if draw(st.booleans()):
            lines.append(f"{op} {draw(st.sampled_from(BOOLS + ['TRUE', 'FALSE']))}")
        elif draw(st.booleans()):
            lines.append("NOT")
        else:  # a deferred operation with one or two inner operations
            lines.append(f"{op}( {draw(st.sampled_from(BOOLS))}")
            for _ in range(draw(st.integers(1, 2))):
                lines.append(f"{draw(st.sampled_from(['AND', 'OR', 'XOR']))} {draw(st.sampled_from(BOOLS))}")
            lines.append(")")
    return lines


@st.composite
def int_chunk(draw) -> list[str]:
    lines = [f"LD {draw(st.sampled_from(INTS))}"]
    multiplied = False
    for _ in range(draw(st.integers(0, 3))):
        op = draw(st.sampled_from(["ADD", "SUB"] if multiplied else ["ADD", "SUB", "MUL"]))
        multiplied = multiplied or op == "MUL"
        lines.append(f"{op} {draw(st.sampled_from(INTS + ['2', '3']))}")
    if draw(st.booleans()):
        lines.append(f"{draw(st.sampled_from(list(_COMPARE)))} {draw(st.sampled_from(INTS + ['5']))}")
    return lines


@st.composite
def programs(draw) -> list[str]:
    """Chunks that load, operate and store; some jump forward over the next chunk when the CR is TRUE."""
    body: list[str] = []
    for index in range(draw(st.integers(1, 5))):
        chunk = draw(st.one_of(bool_chunk(), int_chunk()))
        boolean = not chunk[0].startswith("LD ") or chunk[0].split()[1] in BOOLS or chunk[-1].split()[0] in _COMPARE
        stores = draw(st.lists(st.sampled_from(["ST", "STN", "S", "R"] if boolean else ["ST"]), min_size=1, max_size=2))
        targets = BOOLS if boolean else INTS
        body += chunk + [f"{store} {draw(st.sampled_from(targets))}" for store in stores]
        if boolean and draw(st.booleans()):
            label = f"L{index}"
            body += [f"JMP{draw(st.sampled_from(['C', 'CN']))} {label}"]
            body += draw(bool_chunk()) + [f"ST {draw(st.sampled_from(BOOLS))}", f"{label}:"]
    return body


def interpret(lines: list[str], memory: dict[str, object]) -> None:
    """One scan of the IL ``lines`` on ``memory``, by the spec's rules (see the module docstring)."""

    def value(operand: str) -> object:
        if operand in ("TRUE", "FALSE"):
            return operand == "TRUE"
        return int(operand) if operand.isdigit() else memory[operand]

    acc: object = None
    stack: list[tuple[str, object]] = []
    labels = {line[:-1]: n for n, line in enumerate(lines) if line.endswith(":")}
    pc = 0
    while pc < len(lines):
        word, _, operand = lines[pc].partition(" ")
        pc += 1
        if word.endswith(":"):
            continue
        if word == "LD":
            acc = value(operand)
        elif word == "LDN":
            acc = not value(operand)
        elif word in ("ST", "STN"):
            memory[operand] = acc if word == "ST" else not acc
        elif word in ("S", "R"):
            if acc:
                memory[operand] = word == "S"
        elif word == "NOT":
            acc = not acc
        elif word.endswith("("):
            stack.append((word[:-1], acc))
            acc = value(operand)
        elif word == ")":
            op, saved = stack.pop()
            inner = not acc if op.endswith("N") else acc
            acc = _BOOL_OPS[op.removesuffix("N")](saved, inner)
        elif word.removesuffix("N") in _BOOL_OPS:
            right = value(operand)
            acc = _BOOL_OPS[word.removesuffix("N")](acc, (not right) if word.endswith("N") else right)
        elif word in _INT_OPS:  # INT arithmetic wraps around (the engine's value model, iec/values.py)
            acc = (_INT_OPS[word](acc, value(operand)) + 32768) % 65536 - 32768
        elif word in _COMPARE:
            acc = _COMPARE[word](acc, value(operand))
        elif word in ("JMPC", "JMPCN"):
            if bool(acc) == (word == "JMPC"):
                pc = labels[operand]
        else:
            raise AssertionError(f"the generator made an instruction this interpreter does not know: {word}")


@st.composite
def inputs(draw) -> dict[str, object]:
    return {**{n: draw(st.booleans()) for n in BOOLS}, **{n: draw(st.integers(0, 12)) for n in INTS}}


def _text(lines: list[str]) -> str:
    return f"PROGRAM P\nVAR {DECLARATIONS} END_VAR\n" + "\n".join(lines) + "\nEND_PROGRAM\n"


@fuzz_settings(fast=30)
@given(programs(), st.lists(inputs(), min_size=1, max_size=3))
def test_random_il_runs_as_the_spec_says_il05_il10(lines, scans):
    sim = Simulation(lower_ok(_text(lines)))
    for memory in scans:
        for name, v in memory.items():
            sim.write(f"P.{name}", v)
        expected = dict(memory)
        interpret(lines, expected)
        sim.cycle()
        assert sim.fault is None
        assert {name: sim.read(f"P.{name}") for name in expected} == expected, "\n".join(lines)


@fuzz_settings(fast=10)
@given(programs())
def test_random_il_and_its_st_export_give_the_same_trace(lines):
    project, diagnostics = source_to_project(_text(lines), "il")
    assert project is not None, diagnostics
    same_traces(project, scans=20)
