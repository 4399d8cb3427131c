"""Project -> runnable Simulation: check, lower to the IR, compile, in one call.

The CLI (``run``, ``compile``) and the server build simulations the same way, so
a project that runs in one runs identically in the other.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from ..engine.compile import CompiledProgram, CompileError, compile_program
from ..engine.paths import Resolver
from ..engine.simulation import Simulation
from ..engine.tasks import DEFAULT_WATCHDOG_S
from ..ir.lower_project import lower_project
from ..model import Diagnostic, Project


@dataclass
class Build:
    """``compiled`` is None when the diagnostics hold an error; ``watchdogs``: the tasks' own budgets (s)."""

    compiled: CompiledProgram | None
    diagnostics: list[Diagnostic]
    watchdogs: dict[str, float] = field(default_factory=dict)

    def simulation(self, watchdog_s: float = DEFAULT_WATCHDOG_S, **options: Any) -> Simulation:
        """A simulation of the program; ``watchdog_s`` is the budget of tasks that do not set their own."""
        if self.compiled is None:
            raise CompileError(self.diagnostics)
        tasks = self.compiled.program.tasks
        limits = {task.name: self.watchdogs.get(task.name.upper(), watchdog_s) for task in tasks} if tasks else {}
        return Simulation(self.compiled, watchdog_s=limits or watchdog_s, **options)


def build_project(project: Project, variant: str = "fast") -> Build:
    """Check, lower and compile ``project`` (variant ``fast``, ``monitor`` or ``debug``).

    Never raises for project content: problems are diagnostics."""
    lowered = lower_project(project)
    diagnostics = list(lowered.diagnostics)
    if lowered.program is None:  # the lowering withholds the program whenever a diagnostic is an error
        return Build(None, diagnostics)
    watchdogs = task_watchdogs(project)
    try:
        compiled = compile_program(lowered.program, variant)
    except CompileError as error:
        return Build(None, diagnostics + error.diagnostics)
    unbound = panel_diagnostics(project, compiled)
    return Build(None if unbound else compiled, diagnostics + unbound, watchdogs)


def panel_diagnostics(project: Project, compiled: CompiledProgram) -> list[Diagnostic]:
    """A panel's widget bound to a variable the program does not have is an error of the build (as in CODESYS
    visualisations), located at the panel file and the widget: online, the panel could not show it."""
    resolver = Resolver(compiled.generated.context)
    found: list[Diagnostic] = []
    for panel in project.panels:
        for index, widget in enumerate(panel.widgets):
            for where, path in widget.bindings():
                try:
                    resolver.resolve(path)
                except (KeyError, ValueError) as error:
                    reason = str(error.args[0]) if error.args else str(error)
                    found.append(
                        Diagnostic(
                            code="PANEL-BINDING",
                            message=f"panel {panel.name}, widget {widget.id} ({where}): {reason}",
                            file=f"hmi/{panel.name}.json",
                            json_path=f"widgets[{index}].{where}",
                            element=widget.id,
                        )
                    )
    return found


def task_watchdogs(project: Project) -> dict[str, float]:
    """The tasks' own watchdog budgets in seconds, by upper-case task name (``Build.watchdogs``)."""
    return {task.name.upper(): task.watchdog_ms / 1000.0 for task in project.tasks if task.watchdog_ms}
