"""Stores of power-flow temporaries that nothing reads: left out of the code that records no probes.

The LD/FBD lowering gives every element's power flow and every box's ENO a hidden VAR_TEMP (``__P``, ``__P_1``..),
which the fast and monitor variants keep in Python locals (scope.temp_locals). Many are written only for their
probe: the OR of a network's parallel branches at its right end, the ENO of an ADD box nothing is wired to. Where
no probe is recorded (the fast variant, the monitor variant's unviewed networks and twins) such a store is dead:
nothing reads the local before it is written again or the chunk ends. ``dead_stores`` finds them with a
backward liveness pass over a chunk's blocks, so ``Statements`` can skip them.

Exact by construction: only stores into a temporary local are dropped, only when the local is not live after
them, and only when computing the value cannot fault or call anything (an assignment whose value is a plain
read or a logical / comparison operator over such reads; an ENO store, which is a constant or a comparison of
two locals). At a chunk's end every temporary is live (the next chunk takes them over), except after the last
chunk. A probe that may read a temporary a network has not assigned yet (one that reads the value of an
earlier network) keeps it live at that network's start, because a viewed network records its probes while
the networks before it ran without theirs. Loops, CASE, jumps and anything else this pass does not model make
every temporary live (nothing is dropped across them).

The same pass finds the stores a temporary needs only for the next statement (``folds``): ``ll_t___P =
self.v_A0`` followed by ``ll_t___P_1 = (ll_t___P and (not self.v_B0))``, which reads it and after which it is
dead. ``Statements`` then reads the value in its place and skips the store (a store and a load of a local: a
plain LD network costs ~15 % less). Exact: the value cannot fault or call, and nothing runs between the store and
the read but that next statement, which cannot call anything before the read either (see ``_fold``).

A network the LD lowering filled in from a template (``ir.Block.filled``) differs from the template's other
networks only in variables that are no temporaries: given the same temporaries live after it, its dead stores,
folds and the temporaries live before it are those the first of them had (``_Known``), found without the pass.
"""

from __future__ import annotations

from dataclasses import dataclass

from ...ir import nodes as ir
from .mentions import expression_nodes, walk, walk_filled

#: Operators whose result is computed without a call that could fault (boolean logic and comparisons).
_PURE_OPERATORS = frozenset({"AND", "OR", "XOR", "AND_THEN", "OR_ELSE", "EQ", "NE", "LT", "LE", "GT", "GE"})


def dead_stores(
    blocks: list[ir.Block],
    temps: frozenset[str],
    live_out: frozenset[str],
    probes: bool,
    filled: dict[int, tuple[frozenset[str], list[ir.Stmt]]] | None = None,
) -> tuple[set[int], dict[int, bool]]:
    """``id()`` of the statements of ``blocks`` whose store into a temporary (upper-case names ``temps``) is dead:
    an ``Assign`` to leave out, or an ``FnCall`` / ``FbCall`` whose ENO store to leave out; and the ``folds``:
    ``id()`` of the assignments to a temporary that only the next statement reads, mapped to whether that
    statement is an assignment reading it once (where a variable's read may take the temporary's place; other
    statements may take only a local's or a constant's). ``live_out``: the temporaries read after the blocks;
    ``probes``: the code records probes where a network is viewed. ``filled`` gets, by ``id()``, each network
    filled in from a template whose dead stores and folds are those of the first of its template with the same
    temporaries live after it (``_Known``): those temporaries and its statements in ``walk_filled``'s order."""
    dead: set[int] = set()
    folds: dict[int, bool] = {}
    if not temps:
        return dead, folds
    live = set(live_out)
    known: dict[tuple[object, frozenset[str]], _Known] = {}
    for block in reversed(blocks):
        template = block.filled
        if template is None or any([var.name in temps for var in template.variables(block.statements)]):
            live = _block(block, live, temps, probes, dead, folds)
            continue
        after = frozenset(live)
        key = (template, after)
        found = known.get(key)
        walked = walk_filled(block.statements, [])
        if filled is not None:
            filled[id(block)] = (after, walked)
        if found is None:
            own_dead: set[int] = set()
            own_folds: dict[int, bool] = {}
            live = _block(block, live, temps, probes, own_dead, own_folds)
            dead |= own_dead
            folds.update(own_folds)
            position = {id(s): i for i, s in enumerate(walked)}
            known[key] = _Known(
                frozenset(live),
                [position[s] for s in own_dead],
                [(position[s], once) for s, once in own_folds.items()],
            )
        else:
            live = set(found.live)
            dead.update([id(walked[i]) for i in found.dead])
            folds.update([(id(walked[i]), once) for i, once in found.folds])
    return dead, folds


@dataclass(slots=True)
class _Known:
    """What the pass found for a network filled in from a lowering template (``ir.Filled``) given the temporaries
    live after it: the same for every network of that template whose variables are no temporaries (they differ
    from the template's first network in nothing else the pass reads). The statements by their position in
    ``walk_filled``'s order."""

    live: frozenset[str]  # before the network
    dead: list[int]
    folds: list[tuple[int, bool]]


def _block(
    block: ir.Block, live: set[str], temps: frozenset[str], probes: bool, dead: set[int], folds: dict[int, bool]
) -> set[str]:
    """The temporaries live before ``block`` given those live after it (``dead_stores``)."""
    live = _backward(block.statements, live, temps, dead, folds)
    if probes:
        live |= _exposed_probe_reads(block.statements, temps)
    return live


def _backward(
    statements: list[ir.Stmt], live: set[str], temps: frozenset[str], dead: set[int], folds: dict[int, bool]
) -> set[str]:
    """The temporaries live before ``statements`` given those live after; records dead stores in ``dead`` and the
    stores only the next statement reads in ``folds``."""
    #: the next statement that runs where no probe is recorded, and the temporaries live after and before it
    following: tuple[ir.Stmt, set[str], set[str]] | None = None
    for s in reversed(statements):
        kind = type(s)
        if kind is ir.Probe:
            continue  # (read only where recorded: see _exposed_probe_reads)
        after = live
        if kind is ir.Assign:
            target = _temp(s.target, temps)
            if target is not None and not s.target.path:
                pure = _pure(s.value)
                if pure and target not in live:
                    dead.add(id(s))
                    continue
                if pure and following is not None:
                    once = _fold(target, *following, temps)
                    if once is not None:
                        folds[id(s)] = once
                live = set(live)
                live.discard(target)
                _add_reads(s.value, temps, live)
            else:
                live = set(live)
                _add_reads(s.target, temps, live)
                _add_reads(s.value, temps, live)
        elif kind is ir.If:
            after = live
            live = set()
            for cond, body in s.branches:
                live |= _backward(body, set(after), temps, dead, folds) | _reads(cond, temps)
            live |= _backward(s.orelse, set(after), temps, dead, folds)
        elif kind is ir.FnCall or kind is ir.FbCall:
            eno = _temp(s.eno, temps) if s.eno is not None and not s.eno.path else None
            live = set(live)
            if eno is not None:
                if eno not in live:
                    dead.add(id(s))
                live.discard(eno)  # written on every path: TRUE when the call ran, FALSE when EN was FALSE
            if kind is ir.FnCall:
                expressions = (s.en, s.call, s.target)
            else:
                expressions = (s.en, s.instance, *(e for _, e in s.inputs), *(v for _, v in s.outputs))
            for e in expressions:
                _add_reads(e, temps, live)
        else:  # loops, CASE, RETURN, EXIT, jumps: nothing is dropped across them
            return set(temps)
        following = (s, after, live)
    return live


def _fold(temp: str, s: ir.Stmt, after: set[str], before: set[str], temps: frozenset[str]) -> bool | None:
    """Whether the store into ``temp`` right before ``s`` may be read in its place by ``s`` (None: not): ``temp``
    is dead after ``s`` (``after``) and read by it (live ``before``) only in expressions that cannot call anything
    (an ``Assign`` of a pure value to a variable without index, or the inputs of an FB call without EN, all pure)
    and so cannot write what the value reads before reading it. True: ``s`` is an assignment reading ``temp``
    exactly once."""
    if temp in after or temp not in before:
        return None
    if type(s) is ir.Assign:
        if any(not isinstance(selector, ir.Member) for selector in s.target.path):
            return None
        reads = _pure_reads(s.value, temp, temps)
        return None if reads is None else reads == 1
    if type(s) is ir.FbCall and s.en is None and all(_pure(e) for _, e in s.inputs):
        if temp in _reads(s.instance, temps) or any(temp in _reads(v, temps) for _, v in s.outputs):
            return None
        return False if any(temp in _reads(e, temps) for _, e in s.inputs) else None
    return None


def _exposed_probe_reads(statements: list[ir.Stmt], temps: frozenset[str]) -> set[str]:
    """Temporaries a probe of this block may read before the block's own top-level statements assign them (an
    assignment, or a call's ENO, which it writes on every path: without it, the ENO of every ADD box would stay
    live through the networks up to the next probe reading that temporary, and be computed where nothing reads it)."""
    assigned: set[str] = set()
    exposed: set[str] = set()
    for s in statements:
        for inner in walk([s]):
            if type(inner) is ir.Probe:
                exposed |= _reads(inner.value, temps) - assigned
        kind = type(s)
        target = None
        if kind is ir.Assign and not s.target.path:
            target = _temp(s.target, temps)
        elif (kind is ir.FnCall or kind is ir.FbCall) and s.eno is not None and not s.eno.path:
            target = _temp(s.eno, temps)
        if target is not None:
            assigned.add(target)
    return exposed


def _temp(var: ir.Var, temps: frozenset[str]) -> str | None:
    if var.scope != "local":
        return None
    name = var.name
    if name in temps:  # (the lowering names its temporaries in upper case: no copy of the name to make)
        return name
    name = name.upper()
    return name if name in temps else None


def _reads(e: ir.Expr | None, temps: frozenset[str]) -> set[str]:
    """The temporaries ``e`` reads."""
    found: set[str] = set()
    _add_reads(e, temps, found)
    return found


def _add_reads(e: ir.Expr | None, temps: frozenset[str], found: set[str]) -> None:
    """Add the temporaries ``e`` reads to ``found``. (Plain reads, NOT and operators are walked directly: this runs
    for every expression of a 10,000-network program, and ``expression_nodes``'s nested generators cost twice as
    much; adding to one set spares a set per node.)"""
    if type(e) is ir.Var:
        if not e.path:
            name = _temp(e, temps)
            if name is not None:
                found.add(name)
            return
    elif type(e) is ir.Const or e is None:
        return
    elif type(e) is ir.Binary:
        _add_reads(e.left, temps, found)
        _add_reads(e.right, temps, found)
        return
    elif type(e) is ir.Unary:
        _add_reads(e.operand, temps, found)
        return
    found.update(
        name for node in expression_nodes(e) if isinstance(node, ir.Var) and (name := _temp(node, temps)) is not None
    )


def _pure(e: ir.Expr) -> bool:
    """Computing ``e`` cannot fault or call anything: constants, reads without index or dereference, NOT, and
    logical / comparison operators over such operands."""
    return _pure_reads(e, None, frozenset()) is not None


def _pure_reads(e: ir.Expr, temp: str | None, temps: frozenset[str]) -> int | None:
    """How many times ``e`` reads the temporary ``temp`` when it is pure (``_pure``), else None."""
    if isinstance(e, ir.Var):
        if any(not isinstance(selector, ir.Member) for selector in e.path):
            return None
        return 1 if temp is not None and _temp(e, temps) == temp else 0
    if isinstance(e, ir.Const):
        return 0
    if isinstance(e, ir.Unary) and e.op == "NOT":
        return _pure_reads(e.operand, temp, temps)
    if isinstance(e, ir.Binary) and e.op in _PURE_OPERATORS:
        left, right = _pure_reads(e.left, temp, temps), _pure_reads(e.right, temp, temps)
        return None if left is None or right is None else left + right
    return None
