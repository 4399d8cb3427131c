"""An SFC chart as the graph the engine runs, and a graph (from PLCopen or textual SFC) back as a chart.

``chart_graph(chart)`` walks a structured chart (model/sfc.py) and gives every step, and every
transition with the steps it leaves and the steps it activates (IEC 61131-3's ``TRANSITION FROM
(a, b) TO (c)``), in drawing order, plus the problems of its structure located at the element:
an element out of order (a step after a step), a transition that leads nowhere, a step nothing
reaches (after a jump), a branch of a simultaneous divergence that does not end with a step (the
join would wait for it forever), a jump into or out of a simultaneous branch (unsafe), a jump to
no step. ``graph_chart(steps, transitions)`` rebuilds the chart of a graph: alternative and
simultaneous divergences where the graph branches, their convergences where the branches meet,
and jumps to named steps for loops; a graph no chart can draw is refused with the reason.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field

from .sfc import SfcAlternative, SfcChart, SfcElement, SfcJump, SfcParallel, SfcStep, SfcTransition, walk


@dataclass(frozen=True)
class ChartProblem:
    element: str  # the id of the element it is about
    code: str
    message: str
    severity: str = "error"


@dataclass
class GraphStep:
    step: SfcStep
    initial: bool = False
    context: tuple[tuple[str, int], ...] = ()  # the simultaneous branches (divergence id, branch) it lies in


@dataclass
class GraphTransition:
    transition: SfcTransition
    sources: list[str]  # step names, upper case
    targets: list[str] = field(default_factory=list)
    order: int = 0  # drawing order (top to bottom, left to right)


@dataclass
class ChartGraph:
    steps: dict[str, GraphStep]  # upper-case name -> step, in drawing order
    transitions: list[GraphTransition]
    problems: list[ChartProblem]

    @property
    def initial(self) -> GraphStep | None:
        return next((s for s in self.steps.values() if s.initial), None)

    def evaluation_order(self) -> list[GraphTransition]:
        """Transitions in the order the engine tries them: explicit priorities first (lower first), then the
        others, each in drawing order, so among the transitions after one step the left-most TRUE one wins."""
        return sorted(
            self.transitions,
            key=lambda t: (t.transition.priority is None, t.transition.priority or 0, t.order),
        )


# ------------------------------------------------------------------------------------------ chart -> graph


@dataclass
class _State:
    """Where a sequence stands: after step-like elements (``steps``: the transitions' sources), after
    transition-like ones (``open``: transitions still to be given targets), or nowhere (after a jump)."""

    steps: list[str] | None = None
    open: list[GraphTransition] | None = None

    @property
    def dead(self) -> bool:
        return self.steps is None and self.open is None


class _ChartWalker:
    def __init__(self) -> None:
        self.steps: dict[str, GraphStep] = {}
        self.transitions: list[GraphTransition] = []
        self.problems: list[ChartProblem] = []
        self.jumps: list[tuple[SfcJump, list[GraphTransition], tuple[tuple[str, int], ...]]] = []
        self.context: tuple[tuple[str, int], ...] = ()

    def report(self, element: str, code: str, message: str, severity: str = "error") -> None:
        self.problems.append(ChartProblem(element, code, message, severity))

    def sequence(self, elements: list[SfcElement], state: _State, where: str) -> _State:
        for element in elements:
            if state.dead:
                self.report(element.id, "SFC-UNREACHABLE", f"nothing reaches this {_kind(element)}: {where}")
                where = "it follows an element nothing reaches"
                continue
            state = self.element(element, state)
            if state.dead:
                where = "it follows a jump" if isinstance(element, SfcJump) else "every branch before it ends in a jump"
        return state

    def element(self, element: SfcElement, state: _State) -> _State:
        if isinstance(element, SfcStep):
            if state.open is None:
                self.report(
                    element.id, "SFC-ORDER", f"step {element.name} follows a step: put a transition between them"
                )
            return self.step(element, state.open or [])
        if isinstance(element, SfcTransition):
            if state.steps is None:
                self.report(element.id, "SFC-ORDER", "this transition follows a transition: put a step between them")
                return _State(open=[])
            return _State(open=[self.transition(element, state.steps)])
        if isinstance(element, SfcJump):
            if state.open is None:
                self.report(element.id, "SFC-ORDER", "a jump follows a transition, not a step")
            else:
                self.jumps.append((element, state.open, self.context))
            return _State()
        if isinstance(element, SfcAlternative):
            return self.alternative(element, state)
        return self.parallel(element, state)

    def step(self, step: SfcStep, incoming: list[GraphTransition]) -> _State:
        key = step.name.upper()
        if key in self.steps:
            self.report(step.id, "SFC-DUPLICATE", f"there is already a step called {step.name}")
        else:
            self.steps[key] = GraphStep(step, initial=not self.steps, context=self.context)
        for transition in incoming:
            transition.targets.append(key)
        return _State(steps=[key])

    def transition(self, element: SfcTransition, sources: list[str]) -> GraphTransition:
        made = GraphTransition(element, list(sources), order=len(self.transitions))
        self.transitions.append(made)
        return made

    def alternative(self, element: SfcAlternative, state: _State) -> _State:
        if state.steps is None:
            self.report(element.id, "SFC-ORDER", "an alternative divergence follows a step, not a transition")
            return _State(open=[])
        if len(element.branches) < 2:
            self.report(element.id, "SFC-BRANCHES", "an alternative divergence needs two branches or more")
        joined: list[GraphTransition] = []
        for number, branch in enumerate(element.branches, 1):
            if not branch or not isinstance(branch[0], (SfcTransition, SfcAlternative)):
                self.report(element.id, "SFC-ORDER", f"branch {number} of an alternative must start with a transition")
                continue
            end = self.sequence(branch, _State(steps=list(state.steps)), "")
            if end.steps is not None:
                self.report(
                    _last_id(branch),
                    "SFC-BRANCH-END",
                    f"branch {number} of the alternative ends with a step, so the chart stops there when it takes "
                    "this branch: end it with a transition (the branches join) or a jump to go on",
                    "warning",
                )
            joined += end.open or []
        return _State(open=joined) if joined else _State()

    def parallel(self, element: SfcParallel, state: _State) -> _State:
        if state.open is None:
            self.report(element.id, "SFC-ORDER", "a simultaneous divergence follows a transition, not a step")
            return _State(steps=[])
        if len(element.branches) < 2:
            self.report(element.id, "SFC-BRANCHES", "a simultaneous divergence needs two branches or more")
        last: list[str] = []
        outer = self.context
        for number, branch in enumerate(element.branches, 1):
            self.context = (*outer, (element.id, number))
            if not branch or not isinstance(branch[0], (SfcStep, SfcParallel)):
                self.report(
                    element.id, "SFC-ORDER", f"branch {number} of a simultaneous divergence must start with a step"
                )
                continue
            end = self.sequence(branch, _State(open=state.open), "")
            if end.steps is None:
                self.report(
                    _last_id(branch),
                    "SFC-UNSAFE",
                    f"branch {number} of the simultaneous divergence must end with a step: the join waits for every "
                    "branch, so a branch that ends in a jump or a transition would hold it forever",
                )
            last += end.steps or []
        self.context = outer
        return _State(steps=last)

    def resolve_jumps(self) -> None:
        for jump, incoming, context in self.jumps:
            target = self.steps.get(jump.target.upper())
            if target is None:
                known = ", ".join(s.step.name for s in self.steps.values()) or "none"
                self.report(jump.id, "SFC-JUMP", f"the jump goes to {jump.target!r}, which is no step (steps: {known})")
                continue
            if target.context != context:
                self.report(
                    jump.id,
                    "SFC-UNSAFE",
                    f"the jump to {target.step.name} goes into or out of a branch of a simultaneous divergence: only "
                    "jumps within the same branch are safe",
                )
            for transition in incoming:
                transition.targets.append(target.step.name.upper())


def chart_graph(chart: SfcChart) -> ChartGraph:
    walker = _ChartWalker()
    elements = chart.elements
    if not elements:
        return ChartGraph({}, [], [ChartProblem("", "SFC-EMPTY", "the chart has no step: add the initial step")])
    if not isinstance(elements[0], SfcStep):
        walker.report(elements[0].id, "SFC-ORDER", "a chart starts with its initial step")
    end = walker.sequence(elements, _State(open=[]), "")
    walker.resolve_jumps()
    for transition in end.open or []:
        walker.report(
            transition.transition.id,
            "SFC-DANGLING",
            "this transition leads nowhere: add a step or a jump after it",
        )
    _check_ids(chart, walker)
    return ChartGraph(walker.steps, walker.transitions, walker.problems)


def _check_ids(chart: SfcChart, walker: _ChartWalker) -> None:
    seen: set[str] = set()
    for element in walk(chart.elements):
        ids = [element.id] + ([a.id for a in element.actions] if isinstance(element, SfcStep) else [])
        for item in ids:
            if item in seen:
                walker.report(item, "SFC-DUPLICATE", f"the id {item!r} is used twice in the chart")
            seen.add(item)


def _kind(element: SfcElement) -> str:
    if isinstance(element, SfcStep):
        return f"step ({element.name})"
    return {"transition": "transition", "jump": "jump", "alternative": "divergence", "parallel": "divergence"}[
        element.type
    ]


def _last_id(branch: list[SfcElement]) -> str:
    return branch[-1].id if branch else ""


# ------------------------------------------------------------------------------------------ graph -> chart


class UnstructuredChart(ValueError):
    """The graph cannot be drawn as a chart (e.g. branches that cross); the message says where."""


@dataclass
class ImportedStep:
    step: SfcStep
    initial: bool = False


@dataclass
class ImportedTransition:
    transition: SfcTransition
    sources: list[str]
    targets: list[str]


@dataclass
class _End:
    """How a branch being rebuilt ended: at a join (``join``: the transitions after the simultaneous
    convergence), at the convergence of its alternative (``converge``: the steps the branches lead to), or for good
    (a jump, a last step)."""

    join: tuple[int, ...] | None = None
    converge: frozenset[str] | None = None
    last: frozenset[str] = frozenset()


class _Rebuilder:
    def __init__(self, steps: list[ImportedStep], transitions: list[ImportedTransition]):
        self.steps = {s.step.name.upper(): s for s in steps}
        if len(self.steps) != len(steps):
            raise UnstructuredChart("two steps have the same name")
        self.transitions = transitions
        for t in transitions:
            t.sources = [s.upper() for s in t.sources]
            t.targets = [s.upper() for s in t.targets]
            for name in (*t.sources, *t.targets):
                if name not in self.steps:
                    raise UnstructuredChart(f"a transition connects step {name!r}, which does not exist")
            if not t.sources or not t.targets:
                raise UnstructuredChart(f"transition {t.transition.id} must come from a step and lead to a step")
        self.placed: set[str] = set()
        self.used_transitions: set[int] = set()
        self.simultaneous = False  # the sequence being built is a simultaneous branch (it must end with a step)
        taken = {s.step.id for s in steps} | {t.transition.id for t in transitions}
        self.ids = _IdMaker(taken)

    def run(self) -> SfcChart:
        initials = [name for name, s in self.steps.items() if s.initial]
        if len(initials) > 1:
            names = ", ".join(self.steps[n].step.name for n in initials)
            raise UnstructuredChart(f"the chart has several initial steps ({names}); LadderLab charts have one")
        if not initials:
            if not self.steps:
                return SfcChart()
            raise UnstructuredChart("the chart has no initial step")
        elements, _ = self.from_steps_position([initials[0]], frozenset())
        return SfcChart(elements=elements)

    @contextmanager
    def branches_of(self, simultaneous: bool) -> Iterator[None]:
        """While the branches of a divergence are built (simultaneous or alternative ones)."""
        outer, self.simultaneous = self.simultaneous, simultaneous
        try:
            yield
        finally:
            self.simultaneous = outer

    def unreachable(self) -> list[str]:
        return [s.step.name for name, s in self.steps.items() if name not in self.placed]

    # a step-like position: after a transition (or at the start), with the steps it activates
    def from_steps_position(
        self, targets: list[str], reserved: frozenset[str], converge: frozenset[str] | None = None
    ) -> tuple[list[SfcElement], _End]:
        if converge is not None and frozenset(targets) == converge:
            return [], _End(converge=converge)
        if len(targets) == 1:
            name = targets[0]
            if name in self.placed or name in reserved:
                return [SfcJump(id=self.ids.new("J"), target=self.steps[name].step.name)], _End()
            self.placed.add(name)
            rest, end = self.after_steps(frozenset([name]), reserved, converge)
            return [self.steps[name].step, *rest], end
        for name in targets:
            if name in self.placed or name in reserved:
                raise UnstructuredChart(
                    f"a simultaneous divergence activates step {self.steps[name].step.name}, which is also reached "
                    "another way"
                )
        branches, ends = [], []
        with self.branches_of(simultaneous=True):
            for name in targets:
                branch, end = self.from_steps_position([name], reserved)
                branches.append(branch)
                ends.append(end)
        parallel = SfcParallel(id=self.ids.new("P"), branches=branches)
        joins = {end.join for end in ends}
        if joins == {None} and all(end.converge is None for end in ends):
            return [parallel], _End()  # the chart ends in these branches
        names = ", ".join(self.steps[n].step.name for n in targets)
        if len(joins) != 1 or None in joins:
            raise UnstructuredChart(
                f"the simultaneous branches starting at steps {names} do not join at one transition"
            )
        (join,) = joins
        assert join is not None
        last = frozenset().union(*(end.last for end in ends))
        sources = {frozenset(self.transitions[index].sources) for index in join}
        if sources == {last}:
            rest, end = self.transition_position([self.transitions[i] for i in join], reserved, converge)
            return [parallel, *rest], end
        if len(sources) == 1 and sources.pop() > last:  # the join of an enclosing divergence: this branch ends here
            return [parallel], _End(join=join, last=last)
        raise UnstructuredChart(
            f"a transition joins some, but not all, of the simultaneous branches starting at {names}"
        )

    # after step-like elements whose last steps are ``sources``
    def after_steps(
        self, sources: frozenset[str], reserved: frozenset[str], converge: frozenset[str] | None
    ) -> tuple[list[SfcElement], _End]:
        exact, wider = [], []
        for index, t in enumerate(self.transitions):
            mine = frozenset(t.sources)
            if mine == sources:
                exact.append(index)
            elif mine > sources:
                wider.append(index)
            elif mine & sources:
                raise UnstructuredChart(f"transition {t.transition.id} takes part of a simultaneous branch's steps")
        if wider and exact:
            raise UnstructuredChart("a step both leaves its simultaneous branch alone and joins it with the others")
        if wider:
            return [], _End(join=tuple(wider), last=sources)
        if not exact:
            return [], _End(last=sources)
        return self.transition_position([self.transitions[i] for i in exact], reserved, converge)

    # a transition-like position: the transitions leaving the same steps, left to right
    def transition_position(
        self, outs: list[ImportedTransition], reserved: frozenset[str], converge: frozenset[str] | None
    ) -> tuple[list[SfcElement], _End]:
        for t in outs:
            self.used_transitions.add(id(t))
        if len(outs) == 1:
            t = outs[0]
            rest, end = self.from_steps_position(t.targets, reserved, converge)
            return [t.transition, *rest], end
        failure: UnstructuredChart | None = None
        options = self.meeting_points(outs, reserved, converge)
        for number, meet in enumerate(options):
            saved = (set(self.placed), set(self.used_transitions), set(self.ids.taken))
            try:
                built = self.alternative(outs, reserved, converge, meet, last=number == len(options) - 1)
                if built is not None:
                    return built
            except UnstructuredChart as error:
                failure = failure or error
            self.placed, self.used_transitions, self.ids.taken = saved
        raise failure or UnstructuredChart("the branches of an alternative divergence cannot be drawn")

    def alternative(
        self,
        outs: list[ImportedTransition],
        reserved: frozenset[str],
        converge: frozenset[str] | None,
        meet: frozenset[str] | None,
        last: bool,
    ) -> tuple[list[SfcElement], _End] | None:
        """The alternative divergence of ``outs`` meeting at ``meet``; None when a branch would end with a step (a
        chart's alternative branches end with a transition or a jump), no branch reaches ``meet`` (nothing would
        place the steps kept for after it) or the simultaneous branch it lies in would not end with a step, and
        another meeting point may be tried."""
        inner = reserved | (self._downstream(meet, reserved) if meet else frozenset())
        branches, joined = [], False
        with self.branches_of(simultaneous=False):
            for t in outs:
                rest, end = self.from_steps_position(t.targets, inner, meet)
                if end.join is not None:
                    raise UnstructuredChart(
                        f"the alternative branch of transition {t.transition.id} ends a simultaneous branch the "
                        "others do not"
                    )
                if rest and isinstance(rest[-1], (SfcStep, SfcParallel)) and not last:
                    return None
                joined = joined or end.converge is not None
                branches.append([t.transition, *rest])
        alternative = SfcAlternative(id=self.ids.new("A"), branches=branches)
        if meet is None:
            return [alternative], _End()
        if not joined:
            return None
        rest, end = self.from_steps_position(sorted(meet, key=list(self.steps).index), reserved, converge)
        final = end.join is None and end.converge is None  # (else what comes after is placed further out)
        if final and not last and not (inner - reserved) <= self.placed:
            return None  # a branch jumped to a step after the meeting point that the chart after it never places
        drawn: list[SfcElement] = [alternative, *rest]
        if final and not last and self.simultaneous and not isinstance(drawn[-1], (SfcStep, SfcParallel)):
            return None  # the simultaneous branch would end with a jump: its join would wait for ever
        return drawn, end

    def meeting_points(
        self, outs: list[ImportedTransition], reserved: frozenset[str], converge: frozenset[str] | None
    ) -> list[frozenset[str] | None]:
        """Where the alternative branches may meet, best first: the steps (one, or the first steps of a
        simultaneous divergence) that two transitions or more of different branches lead to, not placed yet or
        where the enclosing alternative meets (nearest first: the one the farthest branch reaches soonest, then
        the one most branches reach); where the only branch that does not come back goes; nowhere (None)."""
        reach = [self._reachable(t.targets, reserved, converge) for t in outs]
        counts: dict[frozenset[str], int] = {}
        for found in reach:
            for target in found:
                counts[target] = counts.get(target, 0) + 1
        candidates: list[frozenset[str] | None] = []
        for found in reach:
            for target in found:
                into = sum(frozenset(t.targets) == target for t in self.transitions)
                if counts[target] >= 2 and (target == converge or into >= 2) and target not in candidates:
                    candidates.append(target)
        far = {c: max(found.index(c) for found in reach if c in found) for c in candidates if c is not None}
        candidates.sort(key=lambda c: (far[c], -counts[c]) if c is not None else (0, 0))
        if converge is not None and converge not in candidates and any(converge in found for found in reach):
            candidates.append(converge)  # a branch leads to where the enclosing alternative meets: meet there too
        going_on = [i for i, found in enumerate(reach) if found]
        if len(going_on) > 1:  # of the branches that go on, the one that does not come back
            going_on = [i for i in going_on if self._escapes(outs[i].targets, reserved, converge)]
        if len(going_on) == 1 and reach[going_on[0]][0] not in candidates:
            candidates.append(reach[going_on[0]][0])
        return [*candidates, None]

    def _fresh_steps(self, start: Iterable[str], reserved: frozenset[str]) -> list[str]:
        """The steps reachable from ``start`` (included) without passing placed or reserved ones."""
        blocked = self.placed | reserved
        order: list[str] = []
        todo = [name for name in start if name not in blocked]
        while todo:
            name = todo.pop(0)
            if name in order:
                continue
            order.append(name)
            for t in self.transitions:
                if name in t.sources:
                    todo += [n for n in t.targets if n not in blocked]
        return order

    def _downstream(self, meet: frozenset[str], reserved: frozenset[str]) -> frozenset[str]:
        """The steps after an alternative's meeting point, which a branch reaching one jumps to (they are placed
        after the alternative); not those that lead back to the meeting point (a loop), nor those reached from the
        meeting point only through such a step: a branch places them (after the loop's step)."""
        after = self._fresh_steps(meet, reserved - meet)
        loops = frozenset(name for name in after if name not in meet and self._leads_to(name, meet, reserved))
        return meet | frozenset(self._fresh_steps(meet, (reserved - meet) | loops))

    def _leads_to(self, name: str, meet: frozenset[str], reserved: frozenset[str]) -> bool:
        blocked = (self.placed | reserved) - meet
        seen, todo = set(), [name]
        while todo:
            here = todo.pop()
            if here in seen:
                continue
            seen.add(here)
            for t in self.transitions:
                if here in t.sources:
                    if frozenset(t.targets) == meet or set(t.targets) & meet:
                        return True
                    todo += [n for n in t.targets if n not in blocked]
        return False

    def _escapes(self, start: list[str], reserved: frozenset[str], converge: frozenset[str] | None) -> bool:
        """Does a branch lead somewhere new (a last step, where its enclosing alternative meets, the join of an
        enclosing simultaneous divergence) rather than only back to steps already placed? (The join of a
        simultaneous divergence the branch itself opens, all of whose steps it reaches, is no way out.)"""
        if frozenset(start) == converge:
            return True
        fresh = self._fresh_steps(start, reserved)
        for name in fresh:
            leaving = [t for t in self.transitions if name in t.sources]
            if not leaving or any(
                frozenset(t.targets) == converge or not set(t.sources) <= set(fresh) for t in leaving
            ):
                return True  # a last step, the enclosing meeting point, the join of an enclosing divergence
        return False

    def _reachable(
        self, start: list[str], reserved: frozenset[str], converge: frozenset[str] | None
    ) -> list[frozenset[str]]:
        """The target sets reachable from ``start`` (itself first) without passing placed or reserved steps (the
        enclosing alternative's meeting steps are reached, not passed)."""
        order: list[frozenset[str]] = []
        seen: set[str] = set()
        todo = [frozenset(start)]
        while todo:
            target = todo.pop(0)
            if target in order:
                continue
            if target == converge:
                order.append(target)
                continue
            if target & (self.placed | reserved):
                continue
            order.append(target)
            for name in target - seen:
                seen.add(name)
                todo += [frozenset(t.targets) for t in self.transitions if name in t.sources]
        return order


class _IdMaker:
    def __init__(self, taken: set[str]):
        self.taken = set(taken)

    def new(self, prefix: str) -> str:
        number = 1
        while f"{prefix}{number}" in self.taken:
            number += 1
        made = f"{prefix}{number}"
        self.taken.add(made)
        return made


def graph_chart(steps: list[ImportedStep], transitions: list[ImportedTransition]) -> tuple[SfcChart, list[str]]:
    """The chart of a step/transition graph (transitions in left-to-right order) and the names of the steps nothing
    reaches from the initial step (left out); raises ``UnstructuredChart`` when no chart can draw the graph."""
    rebuilder = _Rebuilder(steps, transitions)
    chart = rebuilder.run()
    lost = [t.transition.id for t in rebuilder.transitions if id(t) not in rebuilder.used_transitions]
    unreachable = rebuilder.unreachable()
    if lost and not unreachable:
        raise UnstructuredChart(f"transition {lost[0]} could not be placed in the chart")
    return chart, unreachable
