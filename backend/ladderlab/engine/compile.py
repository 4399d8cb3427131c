"""IR Program -> compiled, runnable module (and its inspectable Python source).

    compiled = compile_program(program, variant="fast")   # CompileError with diagnostics on failure
    emit_python(program, variant="debug")                  # the source, for `ladderlab compile --emit-python`

A ``CompiledProgram`` is immutable and may back any number of simulations: each
one executes the code objects in a fresh namespace, so instances, globals and
the scan clock are never shared.

The module is compiled piece by piece (codegen.Source.breaks: classes, chunk
functions, functions), so CPython's syntax tree exists for one piece at a time,
never for a whole 10,000-network POU (that alone took ~270 MB). Each piece is
compiled with its line numbers in the whole module, so tracebacks and fault
locations name lines of ``source``.

The monitor variant's chunk functions with probes (``Generated.lazy``: each has a
twin without probes that runs while none of its networks is viewed) are compiled
when first called: a simulation nobody views never compiles them (two thirds of
the monitor source), and a view compiles only the chunks holding viewed networks.
Until then the namespace holds a ``_CompiledAtFirstCall`` under the function's name.
"""

from __future__ import annotations

import hashlib
import itertools
from dataclasses import dataclass, field, replace
from functools import cached_property
from types import CodeType

from ..collector import collector_paused
from ..deep import deep_call
from ..ir import nodes as ir
from ..model.diagnostics import Diagnostic
from .codegen import Generated, generate
from .codegen.context import diagnostic
from .codegen.runtime import Watchdog, namespace
from .tasks import validate_tasks

_serial = itertools.count(1)


class CompileError(ValueError):
    """The program cannot be compiled; ``diagnostics`` says where and why."""

    def __init__(self, diagnostics: list[Diagnostic]) -> None:
        self.diagnostics = diagnostics
        errors = [d for d in diagnostics if d.severity == "error"]
        lines = [f"{d.location()}: {d.message}" if d.location() else d.message for d in errors]
        super().__init__("cannot compile the program:\n" + "\n".join(lines))


@dataclass(frozen=True)
class CompiledProgram:
    program: ir.Program
    generated: Generated
    pieces: tuple[CodeType | None, ...]  # None: a piece compiled at first call (``Generated.lazy``, ``code``)
    filename: str
    compiled_later: dict[int, CodeType] = field(default_factory=dict, repr=False, compare=False)

    @property
    def source(self) -> str:
        return self.generated.source

    @property
    def variant(self) -> str:
        return self.generated.variant

    @property
    def declarations(self) -> str:
        """The variant-independent part of the source (classes, globals, probe lists)."""
        return self.generated.source[: self.generated.pieces[self.generated.code_from][1]]

    @cached_property
    def declarations_digest(self) -> str:
        """A digest of ``declarations``: what a captured state (engine/state.py) keeps of them, so a state only
        restores into a simulation of the same program without carrying a large program's whole text."""
        return hashlib.sha256(self.declarations.encode()).hexdigest()

    @cached_property
    def watched(self) -> bool:
        """Whether the code checks the watchdog anywhere (a loop or a backward jump calls ``ll_wd``): without,
        no scan can overrun it, and the engine does not read the CPU clock to arm it. A piece not compiled yet has
        the same loops as its twin, which is."""
        return any(_calls_watchdog(code) for code in self.pieces if code is not None)

    def own_code(self) -> CompiledProgram:
        """This program with code objects of its own, for a simulation that runs in turns with another of it.

        CPython specialises a code object's bytecode for the classes and globals it meets (the inline caches of
        3.11), and each simulation has classes of its own (``namespace``): two simulations running the same code
        objects in turns undo each other's specialisation. A scan history's replay did that to the live scan,
        which ran several times slower for a while after each seek."""
        pieces = tuple(None if code is None else _own_code(code) for code in self.pieces)
        return replace(self, pieces=pieces, compiled_later={})

    def code(self, index: int) -> CodeType:
        """Piece ``index``'s code, compiled now when it is compiled at first call and was not yet."""
        code = self.pieces[index] or self.compiled_later.get(index)
        if code is None:  # two threads may both compile it: the same code, one kept
            first, start, end = self.generated.pieces[index]
            code = deep_call(_compile_piece, self.generated.source[start:end], first, self.filename)
            code = self.compiled_later.setdefault(index, code)
        return code

    def namespace(self) -> dict[str, object]:
        """Execute the module in fresh globals: classes, functions and (uninitialised) globals objects."""
        ns = namespace()
        for code in self.pieces[: self.generated.code_from]:
            exec(code, ns)
        self.install(ns)
        return ns

    def install(self, ns: dict[str, object]) -> None:
        """Put this variant's code into ``ns``, replacing another variant's (same declarations) between scans."""
        ns.update(self.generated.bound)
        ns["ll_halt"] = [False] * len(self.generated.pauses)
        for index in range(self.generated.code_from, len(self.pieces)):
            code = self.pieces[index] or self.compiled_later.get(index)
            if code is None:
                ns[self.generated.lazy[index].function] = _CompiledAtFirstCall(self, index, ns)
            else:
                exec(code, ns)

    def compile_viewed(self, ns: dict[str, object], pou: str, flags: list[bool]) -> None:
        """Compile now, between scans, the chunks of ``pou`` (upper case) that its runs viewed (``flags``, its
        ``ll_v``) make the next scan call, so no scan pays for a compile (nor its watchdog)."""
        for piece in self.generated.lazy.values():
            if piece.pou == pou and True in flags[piece.runs.start : piece.runs.stop]:
                stand_in = ns.get(piece.function)
                if isinstance(stand_in, _CompiledAtFirstCall) and stand_in.program is self:
                    stand_in.define()


class _CompiledAtFirstCall:
    """Stands in a namespace for a function whose piece is compiled at first call: compiles it, defines the function
    in its place (the callers look it up by name each time) and runs it, so that first call is the function's own."""

    __slots__ = ("index", "ns", "program")

    def __init__(self, program: CompiledProgram, index: int, ns: dict[str, object]) -> None:
        self.program, self.index, self.ns = program, index, ns

    def define(self) -> object:
        """Compile the piece and put its function in the namespace in this stand-in's place; returns it."""
        exec(self.program.code(self.index), self.ns)
        return self.ns[self.program.generated.lazy[self.index].function]

    def __call__(self, *args: object) -> object:
        watchdog = self.ns.get("ll_watchdog")  # the scan's budget (engine/simulation.py): the compile is not its time
        left = watchdog.pause() if isinstance(watchdog, Watchdog) else None
        function = self.define()
        if left is not None:
            watchdog.resume(left)  # type: ignore[union-attr]  # set with left
        return function(*args)  # type: ignore[operator]  # the namespace is untyped


def _own_code(code: CodeType) -> CodeType:
    """A copy of ``code`` and of the code objects it holds (a module's functions), not yet specialised."""
    return code.replace(co_consts=tuple(_own_code(c) if isinstance(c, CodeType) else c for c in code.co_consts))


def _calls_watchdog(code: CodeType) -> bool:
    return "ll_wd" in code.co_names or any(
        _calls_watchdog(inner) for inner in code.co_consts if isinstance(inner, CodeType)
    )


def compile_program(program: ir.Program, variant: str = "fast") -> CompiledProgram:
    # generation allocates millions of objects that live until it ends: collections would only traverse them
    with collector_paused():  # and on a deep stack: generation and compile() recurse per nesting level
        return deep_call(_compile_program, program, variant)


def _compile_program(program: ir.Program, variant: str) -> CompiledProgram:
    generated = generate(program, variant)
    diagnostics = [*validate_tasks(program), *generated.diagnostics]
    if any(d.severity == "error" for d in diagnostics):
        raise CompileError(diagnostics)
    filename = f"<ladderlab-{variant}-{next(_serial)}>"
    try:
        pieces = tuple(
            None if index in generated.lazy else _compile_piece(generated.source[start:end], first, filename)
            for index, (first, start, end) in enumerate(generated.pieces)
        )
    except (SyntaxError, RecursionError, MemoryError, ValueError) as error:  # e.g. nesting beyond CPython's limits
        raise CompileError([diagnostic(f"the generated code does not compile: {error}", None)]) from None
    return CompiledProgram(program, generated, pieces, filename)


def _compile_piece(source: str, first: int, filename: str) -> CodeType:
    """One piece of the module, whose first line is line ``first + 1`` of the module."""
    try:
        return _from_line(compile(source, filename, "exec"), first)
    except SyntaxError as error:
        if error.lineno is not None:  # the message names the module's line
            error.lineno += first
        raise


def _from_line(code: CodeType, offset: int) -> CodeType:
    """``code``, compiled from a piece as line 1 on, numbered from line ``offset + 1`` of the module.

    Line tables count from ``co_firstlineno``, so moving it moves every line of the code object (its
    nested functions and classes are code objects of their own). Cheaper than compiling the piece
    after ``offset`` blank lines: the tokenizer would read ~5 million of them for a 10,000-network POU.
    """
    if not offset:
        return code
    consts = tuple(_from_line(c, offset) if isinstance(c, CodeType) else c for c in code.co_consts)
    return code.replace(co_firstlineno=code.co_firstlineno + offset, co_consts=consts)


def emit_python(program: ir.Program, variant: str = "fast") -> str:
    """The generated module's source (raises CompileError when the program has errors)."""
    return compile_program(program, variant).source
