"""Project -> runnable Simulation: check, lower to the IR, compile, in one call.

The CLI (``run``, ``compile``) and the server build simulations the same way, so
a project that runs in one runs identically in the other.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..engine.compile import CompiledProgram, CompileError, compile_program
from ..engine.simulation import Simulation
from ..engine.state import SimState
from ..ir.lower_project import lower_project
from ..model import Diagnostic, Project


@dataclass
class Build:
    """``compiled`` is None when the diagnostics hold an error."""

    compiled: CompiledProgram | None
    diagnostics: list[Diagnostic]

    def simulation(self, **options) -> Simulation:
        if self.compiled is None:
            raise CompileError(self.diagnostics)
        return Simulation(self.compiled, **options)


def build_project(project: Project, variant: str = "fast") -> Build:
    """Check, lower and compile ``project`` (variant ``fast``, ``monitor`` or ``debug``).

    Never raises for project content: problems are diagnostics."""
    lowered = lower_project(project)
    diagnostics = list(lowered.diagnostics)
    if lowered.program is None:  # the lowering withholds the program whenever a diagnostic is an error
        return Build(None, diagnostics)
    try:
        return Build(compile_program(lowered.program, variant), diagnostics)
    except CompileError as error:
        return Build(None, diagnostics + error.diagnostics)


def simulation_from_state(compiled: CompiledProgram, state: SimState, **options) -> Simulation:
    """A simulation of ``compiled`` as it stood when ``state`` was captured (a failed test opened online)."""
    sim = Simulation(compiled, **options)
    sim.restore(state)
    return sim
