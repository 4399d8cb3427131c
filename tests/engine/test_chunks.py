"""Long POU bodies run as chunk functions compiled one at a time (codegen/chunks.py, issue 4's memory target).

Chunking must not be observable: jumps inside and across chunks, RETURN, the watchdog on back-edges,
located faults, breakpoints and stepping, and probes behave as in a body compiled whole. The tests
shrink ``CHUNK_STATEMENTS`` so small programs get many chunks.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from types import FunctionType

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.engine.codegen import chunks
from ladderlab.engine.compile import _compile_piece, compile_program
from ladderlab.engine.simulation import Simulation

from .irbuild import BOOL, INT, add, assign, c, div, if_, jump, lt, network, pou, probe, prog, ret, slot, v

J = v("J", INT)


@contextmanager
def chunk_size(size: int) -> Iterator[None]:
    """Programs compiled inside get chunks of ``size`` IR statements."""
    saved, chunks.CHUNK_STATEMENTS = chunks.CHUNK_STATEMENTS, size
    try:
        yield
    finally:
        chunks.CHUNK_STATEMENTS = saved


# A block: (label or None, what ends it: None | ("jump", target block, input bit or None) | ("return", bit))
blocks_strategy = st.integers(2, 9).flatmap(
    lambda n: st.lists(
        st.tuples(
            st.booleans(),
            st.one_of(
                st.none(),
                st.tuples(st.just("jump"), st.integers(0, n - 1), st.one_of(st.none(), st.integers(0, 2))),
                st.tuples(st.just("return"), st.integers(0, 2)),
            ),
        ),
        min_size=n,
        max_size=n,
    )
)


def _program(spec):
    """Block i counts X<i>; a jump back is allowed three times per scan (J), so every scan ends."""
    labels = {end[1] for _, end in spec if end and end[0] == "jump"} | {i for i, (lab, _) in enumerate(spec) if lab}
    slots = [slot("J", INT), *(slot(f"IN{b}", BOOL) for b in range(3)), *(slot(f"X{i}", INT) for i in range(len(spec)))]
    blocks = [network("START", [assign(J, c(0, INT))])]  # no label: never jumped to
    for i, (_, end) in enumerate(spec):
        x = v(f"X{i}", INT)
        body = [assign(x, add(x, c(1, INT))), probe(f"E{i}", x)]
        if end and end[0] == "jump":
            target, bit = end[1], end[2]
            cond = v(f"IN{bit}", BOOL) if bit is not None else None
            if target <= i:  # backward: bounded by J
                body.append(assign(J, add(J, c(1, INT))))
                cond = lt(J, c(3, INT))
            body.append(jump(f"L{target}", cond))
        elif end:
            body.append(if_((v(f"IN{end[1]}", BOOL), [ret()])))
        blocks.append(network(f"N{i}", body, label=f"L{i}" if i in labels else None))
    return prog(pou("MAIN", slots, blocks))


def _trace(program, variant: str, inputs: list[int]) -> list[tuple]:
    sim = Simulation(program, variant=variant, watchdog_s=0.2)
    rows = []
    for mask in inputs:
        for b in range(3):
            sim.write(f"MAIN.IN{b}", bool(mask >> b & 1))
        sim.cycle()
        assert sim.fault is None, sim.fault
        names = sorted(k for k in sim.snapshot() if k.startswith("MAIN.X"))
        rows.append((tuple(sim.read(n) for n in names), sim.probes("MAIN") if variant != "fast" else None))
    return rows


@settings(max_examples=40)
@given(blocks_strategy, st.lists(st.integers(0, 7), min_size=6, max_size=6), st.integers(1, 5))
def test_property_chunked_bodies_run_like_whole_ones(spec, inputs, size):
    whole = {variant: _trace(_program(spec), variant, inputs) for variant in ("fast", "monitor", "debug")}
    with chunk_size(size):
        program = _program(spec)
        if size <= 2:  # every block (2 statements or more) its own chunk
            assert sum(1 for line in compile_program(program).source.splitlines() if line.startswith("def ll_k")) > 1
        for variant in ("fast", "monitor", "debug"):
            assert _trace(program, variant, inputs) == whole[variant], variant


class _Ticks:
    def __init__(self) -> None:
        self.now = 0.0

    def __call__(self) -> float:
        self.now += 0.001
        return self.now


def _counting(n: int, extra: dict[int, list]) -> object:
    x = v("X", INT)
    blocks = [network(f"N{i}", [assign(x, add(x, c(1, INT))), *extra.get(i, [])], label=f"L{i}") for i in range(n)]
    return prog(pou("MAIN", [slot("X", INT), slot("Z", INT)], blocks))


def test_an_endless_jump_back_across_chunks_trips_the_watchdog_at_the_jump():
    with chunk_size(2):
        sim = Simulation(_counting(6, {5: [jump("L1")]}), watchdog_s=0.05, watchdog_clock=_Ticks())
    assert len(sim.compiled.pieces) > 4
    sim.cycle()
    assert (sim.fault.kind, sim.fault.origin.network) == ("watchdog", "N5")
    # the clock is read every 256 back-edges (not at every jump): 50 readings of 1 ms, 5 increments per lap
    assert sim.read("MAIN.X") == ((1 + 5 * 50 * 256 + 32768) & 65535) - 32768


def test_a_fault_in_a_later_chunk_names_its_network_and_values():
    x, z = v("X", INT), v("Z", INT)
    with chunk_size(2):
        sim = Simulation(_counting(6, {4: [assign(z, div(x, z))]}))
    assert len(sim.compiled.pieces) > 4
    sim.cycle()
    fault = sim.fault  # located through the line numbers each piece keeps from the whole module
    assert (fault.code, fault.origin.network, fault.values) == ("division_by_zero", "N4", {"Z": 0, "X": 5})


def test_every_compiled_function_starts_at_its_def_line_in_the_source():
    """Each piece is compiled on its own and renumbered (compile._from_line), nested code objects included."""
    with chunk_size(2):
        compiled = compile_program(_counting(6, {3: [assign(v("Z", INT), c(1, INT))]}))
    assert len(compiled.pieces) > 4
    lines = compiled.source.splitlines()
    namespace = compiled.namespace()
    functions = [f for f in namespace.values() if isinstance(f, FunctionType)]
    functions += [
        f
        for cls in namespace.values()
        if isinstance(cls, type)
        for f in vars(cls).values()
        if isinstance(f, FunctionType)
    ]
    functions = [f for f in functions if f.__code__.co_filename == compiled.filename]  # not the runtime's
    assert {f.__name__ for f in functions} >= {"ll_k0_MAIN", "ll_k2_MAIN", "ll_x_MAIN", "ll_init", "__init__"}
    for f in functions:
        assert lines[f.__code__.co_firstlineno - 1].lstrip().startswith(f"def {f.__name__}("), f.__name__


def test_a_syntax_error_in_a_piece_names_the_line_of_the_module():
    with pytest.raises(SyntaxError) as raised:
        _compile_piece("x = 1\ny = (\n", 40, "<generated>")
    assert raised.value.lineno == 42


def test_breakpoints_and_network_steps_cross_chunks_in_order():
    with chunk_size(2):
        sim = Simulation(_counting(6, {}), variant="debug")
    sim.set_breakpoint("MAIN", network="N3")
    assert sim.cycle() == 0 and sim.halted.origin.network == "N3" and sim.read("MAIN.X") == 3
    seen = []
    while sim.halted is not None:
        seen.append((sim.halted.origin.network, sim.read("MAIN.X")))
        sim.step("network")
    assert seen == [("N3", 3), ("N4", 4), ("N5", 5)] and sim.read("MAIN.X") == 6
