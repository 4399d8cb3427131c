"""What the tests never executed or never energised, per POU, from the monitor variant's probes.

LD elements and FBD blocks have probes (their power flow or pin values: docs/runtime.md); ST statements
have none, so a coverage build adds one probe of the constant TRUE before the first statement of every
line of an ST POU (``instrument``: element ``line <n>``, executed when its straight run of code runs).
``Coverage.collect(sim)`` is called after every scan of a test and at every verb (so FB calls made by a
test's own code count as well): it records which elements ran and which BOOL elements were ever TRUE.
Coverages of several tests and processes ``merge``; ``report()`` is the JSON shape, ``text()`` its summary.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from ..engine.simulation import ProbeView, Simulation
from ..ir import nodes as ir
from ..ir.lower_tests import HOST
from ..ir.types import BOOL
from ..st.testfile import TEST_POU

LINE = "line {}"
_TEST_PREFIXES = (TEST_POU.format(""), HOST.format(""))


def instrument(program: ir.Program) -> None:
    """Add a line probe before the first statement of each line of every ST POU of the project (in place)."""
    for pou in program.pous.values():
        if pou.language == "st" and not pou.name.startswith(_TEST_PREFIXES):
            seen: set[int] = set()
            for block in pou.blocks:
                block.statements = _with_line_probes(block.statements, seen)


def _with_line_probes(statements: list[ir.Stmt], seen: set[int]) -> list[ir.Stmt]:
    out: list[ir.Stmt] = []
    for statement in statements:
        origin = statement.origin
        if origin.line is not None and origin.line not in seen and not isinstance(statement, ir.Probe):
            seen.add(origin.line)
            out.append(ir.Probe(LINE.format(origin.line), ir.Const(True, BOOL), origin))
        for body in _bodies(statement):
            body[:] = _with_line_probes(body, seen)
        out.append(statement)
    return out


def _bodies(statement: ir.Stmt) -> list[list[ir.Stmt]]:
    if isinstance(statement, ir.If):
        return [body for _, body in statement.branches] + [statement.orelse]
    if isinstance(statement, ir.Case):
        return [body for _, body in statement.branches] + [statement.orelse]
    if isinstance(statement, (ir.For, ir.While, ir.Repeat)):
        return [statement.body]
    return []


@dataclass
class PouCoverage:
    language: str
    elements: list[str]  # every probed element (LD/FBD ids, ST "line <n>"), in probe order
    executed: set[str] = field(default_factory=set)
    energised: set[str] = field(default_factory=set)
    booleans: set[str] = field(default_factory=set)  # elements whose value is a BOOL (power flow)


class Coverage:
    """Accumulated over tests: per POU (upper-case name) which probed elements ran and were TRUE."""

    def __init__(self) -> None:
        self.pous: dict[str, PouCoverage] = {}

    def collect(self, sim: Simulation) -> None:
        context = sim.compiled.generated.context
        program = sim.compiled.program
        for pou_name, paths in sim.instances().items():
            for path in paths:
                self._add(program.pous[pou_name], context.probes_of(pou_name).elements, sim.probes(path))
        for pou in program.pous.values():
            if pou.kind == "function" and not pou.name.startswith(_TEST_PREFIXES):
                self._add(pou, context.probes_of(pou.name).elements, sim.probes(pou.name))

    def _add(self, pou: ir.Pou, elements: list[str], view: ProbeView) -> None:
        if pou.name.startswith(_TEST_PREFIXES) or not elements:
            return
        entry = self.pous.get(pou.name.upper())
        if entry is None:
            entry = self.pous[pou.name.upper()] = PouCoverage(pou.language, list(elements))
        for element, value in view.values.items():
            entry.executed.add(element)
            if value is True or value is False:
                entry.booleans.add(element)
                if value:
                    entry.energised.add(element)

    def merge(self, other: Coverage) -> None:
        for key, theirs in other.pous.items():
            mine = self.pous.setdefault(key, PouCoverage(theirs.language, list(theirs.elements)))
            mine.executed |= theirs.executed
            mine.energised |= theirs.energised
            mine.booleans |= theirs.booleans

    def report(self, names: dict[str, str] | None = None) -> dict[str, dict[str, Any]]:
        """``{POU: {language, elements, executed, never_executed, never_energised}}`` (ST: ``lines`` too)."""
        out: dict[str, dict[str, Any]] = {}
        for key in sorted(self.pous):
            entry = self.pous[key]
            never = [e for e in entry.elements if e not in entry.executed]
            item: dict[str, object] = {
                "language": entry.language,
                "elements": len(entry.elements),
                "executed": len(entry.elements) - len(never),
            }
            if entry.language == "st":
                item["never_executed_lines"] = [int(e.split()[1]) for e in never if e.startswith("line ")]
            else:
                item["never_executed"] = never
                item["never_energised"] = [
                    e
                    for e in entry.elements
                    if e in entry.booleans and e in entry.executed and e not in entry.energised
                ]
            out[(names or {}).get(key, key)] = item
        return out

    def text(self, names: dict[str, str] | None = None) -> str:
        lines = ["coverage:"]
        for pou, item in self.report(names).items():
            share = f"{item['executed']}/{item['elements']}"
            if item["language"] == "st":
                missing = item["never_executed_lines"]
                detail = f"lines never executed: {', '.join(map(str, missing))}" if missing else "every line executed"
                lines.append(f"  {pou} (ST): {share} lines executed; {detail}")
            else:
                lines.append(f"  {pou} ({item['language'].upper()}): {share} elements executed")
                if item["never_executed"]:
                    lines.append(f"    never executed: {', '.join(item['never_executed'])}")
                if item["never_energised"]:
                    lines.append(f"    never energised: {', '.join(item['never_energised'])}")
        return "\n".join(lines)
