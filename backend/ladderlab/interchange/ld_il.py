"""An LD network as Instruction List (issue 26 item 4, "View as IL": a read-only teaching aid).

Networks of contacts (NO, NC), compare contacts, series and parallel branches, coils (normal, negated,
set, reset), jumps and returns have an IL equivalent; the current result (CR) carries the rung's power:

* a series list is ``LD`` its first element then ``AND`` the others (``LDN``/``ANDN`` for an NC contact);
  a parallel is its first branch, then ``OR(`` each further branch ``)``; a parallel after something is
  ``AND(`` the parallel ``)``; a compare contact is ``LD left`` / ``GT right`` (in brackets after something);
* coils do not change the CR (IL-05), so coils in series or in a parallel of plain coils are ``ST``/``STN``/
  ``S``/``R`` one after the other, each seeing the rung's power, as in LD;
* jumps and returns act after the whole network in LD (GR-05 c): they come last, ``JMPC``/``RETC`` (``JMP``/
  ``RET`` straight on the rail); the network's label is the IL label of its first line.

Everything else - edge contacts and coils (their memory), boxes, coils in a branch that also holds contacts,
a coil before a contact (the contact would then see the CR, not the rail) - has no plain IL equivalent:
``network_il`` says why instead. ``tests/interchange/test_ld_il.py`` runs the IL against the LD network.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..model import ld

_COIL = {"normal": "ST", "negated": "STN", "set": "S", "reset": "R"}
_RAIL = "TRUE"


class NoIl(Exception):
    """The network has no plain IL equivalent; the message says which element and why."""


@dataclass
class IlText:
    """``text``: the IL of the network; ``reason``: why there is none (then ``text`` is None)."""

    text: str | None
    reason: str | None = None


def network_il(network: ld.LdNetwork) -> IlText:
    try:
        return IlText("\n".join(_Writer().network(network)))
    except NoIl as refused:
        return IlText(None, str(refused))


def body_il(body: ld.LdBody) -> IlText:
    """Every network's IL one after the other (an IL POU body), or the first network's reason it has none."""
    lines: list[str] = []
    for number, network in enumerate(body.networks, 1):
        made = network_il(network)
        if made.text is None:
            return IlText(None, f"network {number}: {made.reason}")
        lines += made.text.splitlines()
    return IlText("\n".join(lines))


@dataclass
class _Writer:
    lines: list[str] = field(default_factory=list)
    depth: int = 0

    def emit(self, text: str) -> None:
        self.lines.append("    " * self.depth + text)

    def network(self, network: ld.LdNetwork) -> list[str]:
        if network.label:
            self.lines.append(f"{network.label.strip()}:")
        conditions, coils, controls = _split(network.elements)
        if not coils and not controls:
            raise NoIl("the rung ends in no coil, jump or return")
        if conditions:
            self.series(conditions)
        else:
            self.emit(f"LD {_RAIL}")
        for coil in coils:
            self.emit(f"{_COIL[coil.mode]} {coil.var.strip()}")
        rail = not conditions
        for control in controls:
            if isinstance(control, ld.Jump):
                self.emit(f"{'JMP' if rail else 'JMPC'} {control.target.strip()}")
            else:
                self.emit("RET" if rail else "RETC")
        return self.lines

    def series(self, elements: list[ld.LdElement], first: bool = True) -> None:
        """The power of a series list into the CR: loaded by its first element when ``first``."""
        for element in elements:
            self.element(element, first)
            first = False

    def element(self, element: ld.LdElement, first: bool) -> None:
        if isinstance(element, ld.Contact):
            if element.mode not in ("no", "nc"):
                raise NoIl(f"the {element.mode.upper()} contact {element.var} detects an edge: IL needs an R_TRIG")
            word = ("LD" if first else "AND") + ("N" if element.mode == "nc" else "")
            self.emit(f"{word} {element.var.strip()}")
        elif isinstance(element, ld.Compare):
            self.bracketed(first, lambda: self.compare(element))
        elif isinstance(element, ld.Parallel):
            self.bracketed(first, lambda: self.parallel(element))
        else:
            raise NoIl(f"{_what(element)} stands where the rung's power is still being formed")

    def compare(self, element: ld.Compare) -> None:
        self.emit(f"LD {element.left.strip()}")
        self.emit(f"{element.op} {element.right.strip()}")

    def parallel(self, element: ld.Parallel) -> None:
        """The first branch loaded, each further one ORed in brackets (an empty branch is a short: TRUE)."""
        for index, branch in enumerate(element.branches):
            if index == 0:
                self.series(branch) if branch else self.emit(f"LD {_RAIL}")
            elif not branch:
                self.emit(f"OR {_RAIL}")
            elif len(branch) == 1 and isinstance(branch[0], ld.Contact) and branch[0].mode in ("no", "nc"):
                self.emit(f"OR{'N' if branch[0].mode == 'nc' else ''} {branch[0].var.strip()}")
            else:
                self.bracketed(False, lambda branch=branch: self.series(branch), "OR")

    def bracketed(self, first: bool, body, word: str = "AND") -> None:
        """``body`` loads the CR itself: as the first element it stands alone, else inside ``AND(`` ... ``)``."""
        if first:
            body()
            return
        opening = len(self.lines)
        self.emit(f"{word}(")
        self.depth += 1
        body()
        self.depth -= 1
        self.emit(")")
        loaded = self.lines[opening + 1].strip()
        if loaded.startswith("LD "):  # ``AND( a`` rather than ``AND(`` / ``LD a`` (IEC's own form)
            self.lines[opening : opening + 2] = [f"{self.lines[opening]} {loaded[3:]}"]


def _split(elements: list[ld.LdElement]):
    """The rung as (the contacts forming its power, its coils, its jumps and returns): the coils, jumps and
    returns stand at the end, in series or as a parallel of plain outputs."""
    outputs: list[ld.LdElement] = []
    index = len(elements)
    while index > 0 and _output_part(elements[index - 1]):
        index -= 1
    conditions, tail = elements[:index], elements[index:]
    for element in tail:
        outputs += (
            [item for branch in element.branches for item in branch] if isinstance(element, ld.Parallel) else [element]
        )
    for element in ld.walk(conditions):
        if isinstance(element, (ld.Coil, ld.Jump, ld.Return, ld.Box)):
            raise NoIl(f"{_what(element)} stands where the rung's power is still being formed")
    coils = [e for e in outputs if isinstance(e, ld.Coil)]
    for coil in coils:
        if coil.mode not in _COIL:
            raise NoIl(f"the {coil.mode.upper()} coil {coil.var} detects an edge: IL needs an R_TRIG")
    return conditions, coils, [e for e in outputs if isinstance(e, (ld.Jump, ld.Return))]


def _output_part(element: ld.LdElement) -> bool:
    """A coil, jump or return, or a parallel whose branches hold only those (one each or in series)."""
    if isinstance(element, (ld.Coil, ld.Jump, ld.Return)):
        return True
    return isinstance(element, ld.Parallel) and all(
        branch and all(isinstance(e, (ld.Coil, ld.Jump, ld.Return)) for e in branch) for branch in element.branches
    )


def _what(element: ld.LdElement) -> str:
    if isinstance(element, ld.Box):
        return f"the box {element.call}{' ' + element.instance if element.instance else ''} (IL calls it with CAL)"
    if isinstance(element, ld.Coil):
        return f"the coil {element.var}"
    if isinstance(element, ld.Jump):
        return f"the jump to {element.target}"
    return f"the {element.type}"
