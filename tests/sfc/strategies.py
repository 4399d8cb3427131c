"""Hypothesis strategies for random well-formed SFC charts (and SFC POUs around them).

A chart is a main sequence that starts with its initial step; step-like places are a step or (nested) a
simultaneous divergence whose branches start with a step and end with a step-like element; transition-like places
are a transition or an alternative divergence whose first branch joins the others (the rest may end with a jump).
Jumps go back to a step drawn before them in the same simultaneous branch (or the main sequence): loops, as charts
use jumps; every chart drawn is safe. (A forward jump is tested on its own in test_graph.py.)
Conditions are unique (``c<n>``), so a transition can be recognised after a round trip; with ``named``, a transition
may instead read the named transition ``T<n>`` (SFC-03), written in ST (``c<n>``) or IL (``LD c<n>``).
"""

from __future__ import annotations

from hypothesis import strategies as st

from ladderlab.model.sfc import QUALIFIERS, TIMED_QUALIFIERS

MAX_DEPTH = 2


class _Drawer:
    def __init__(self, draw):
        self.draw = draw
        self.count = 0
        self.steps: dict[tuple, list[str]] = {}  # parallel context -> step names in it
        self.jumps: list[tuple[dict, tuple, int]] = []
        self.actions: set[str] = set()
        self.pool = ["Act1", "Act2", "Act3"]  # the actions steps of the chart being drawn associate
        self.transitions: list[dict] = []  # every transition drawn, in all charts

    def new(self, prefix: str) -> str:
        self.count += 1
        return f"{prefix}{self.count}"

    def step(self, context: tuple) -> dict:
        name = self.new("S")
        self.steps.setdefault(context, []).append(name)
        associations = []
        for _ in range(self.draw(st.integers(0, 2))):
            qualifier = self.draw(st.sampled_from(QUALIFIERS))
            action = self.draw(st.sampled_from(self.pool))
            self.actions.add(action)
            item = {"id": self.new("a"), "qualifier": qualifier, "action": action}
            if qualifier in TIMED_QUALIFIERS:
                item["time"] = f"T#{self.draw(st.integers(1, 9)) * 10}ms"
            associations.append(item)
        return {"type": "step", "id": self.new("s"), "name": name, "actions": associations}

    def transition(self) -> dict:
        number = self.new("")
        out = {"type": "transition", "id": f"t{number}", "condition": f"c{number}"}
        if self.draw(st.integers(0, 5)) == 0:
            out["priority"] = self.draw(st.integers(0, 3))
        self.transitions.append(out)
        return out

    def step_like(self, context: tuple, depth: int, first: bool = False) -> dict:
        if first or depth >= MAX_DEPTH or self.draw(st.integers(0, 3)) != 0:
            return self.step(context)
        pid = self.new("P")
        branches = []
        for number in range(self.draw(st.integers(2, 3))):
            inner = (*context, (pid, number))
            branch = [self.step(inner)]
            for _ in range(self.draw(st.integers(0, 1))):
                branch += [self.trans_like(inner, depth + 1), self.step_like(inner, depth + 1)]
            branches.append(branch)
        return {"type": "parallel", "id": pid, "branches": branches}

    def trans_like(self, context: tuple, depth: int) -> dict:
        if depth >= MAX_DEPTH or self.draw(st.integers(0, 3)) != 0:
            return self.transition()
        branches = []
        for number in range(self.draw(st.integers(2, 3))):
            branch = [self.transition()]
            for _ in range(self.draw(st.integers(0, 1))):
                branch += [self.step_like(context, depth + 1), self.trans_like(context, depth + 1)]
            if number and self.draw(st.booleans()):
                branch.append(self.jump(context))
            branches.append(branch)
        return {"type": "alternative", "id": self.new("A"), "branches": branches}

    def jump(self, context: tuple) -> dict:
        made = {"type": "jump", "id": self.new("j"), "target": ""}
        self.jumps.append((made, context, len(self.steps.get(context, []))))
        return made

    def chart(self, root: tuple = ()) -> list:
        """``root``: the context of the chart's main sequence (an action's chart has its own, so its jumps stay in it)."""
        elements = [self.step_like(root, 0, first=True)]
        for _ in range(self.draw(st.integers(0, 3))):
            elements += [self.trans_like(root, 0), self.step_like(root, 0)]
        if self.draw(st.booleans()):
            elements += [self.trans_like(root, 0), self.jump(root)]
        for made, context, before in self.jumps:  # back to a step drawn before the jump: a loop
            made["target"] = self.draw(st.sampled_from(self.steps[context][: max(before, 1)]))
        self.jumps = []
        return elements


@st.composite
def charts(draw) -> list:
    """The elements of a random well-formed chart (model/sfc.py dicts)."""
    return _Drawer(draw).chart()


@st.composite
def sfc_bodies(draw, nested: bool = False, named: bool = False) -> dict:
    """A random SFC body: a chart, the ST or IL actions it names and the BOOL conditions it reads. ``nested``: also an
    action ``Sub`` written in SFC (a random chart whose steps associate In1, In2), associated with the initial step
    with a random qualifier (SFC-02, docs/sfc.md "Actions written in SFC"). ``named``: some transitions read a named
    transition ``T<n>`` in ST or IL that reads their condition ``c<n>``."""
    drawer = _Drawer(draw)
    chart = drawer.chart()
    actions = [_action(draw, name, "n", i + 1) for i, name in enumerate(sorted(drawer.actions))]
    if nested:
        outer = drawer.actions
        drawer.actions, drawer.pool = set(), ["In1", "In2"]
        inner = drawer.chart(root=("Sub",))
        actions += [_action(draw, name, "m", i + 1) for i, name in enumerate(sorted(drawer.actions))]
        actions.append({"name": "Sub", "language": "sfc", "body": {"elements": inner}})
        qualifier = draw(st.sampled_from(QUALIFIERS))
        association = {"id": drawer.new("a"), "qualifier": qualifier, "action": "Sub"}
        if qualifier in TIMED_QUALIFIERS:
            association["time"] = f"T#{draw(st.integers(1, 9)) * 10}ms"
        chart[0]["actions"].append(association)
        drawer.actions = outer
    transitions = []
    for transition in drawer.transitions if named else []:
        if draw(st.booleans()):
            condition = transition["condition"]
            transition["condition"] = f"T{condition[1:]}"
            il = draw(st.booleans())
            body = f"LD {condition}" if il else condition
            transitions.append({"name": transition["condition"], "language": "il" if il else "st", "body": body})
    return {"chart": {"elements": chart}, "actions": actions, "transitions": transitions}


def _action(draw, name: str, counter: str, step: int) -> dict:
    """An action adding ``step`` to ``counter``, written in ST or in IL (SFC-02) as drawn."""
    if draw(st.booleans()):
        return {"name": name, "language": "il", "body": f"LD {counter}\nADD {step}\nST {counter}"}
    return {"name": name, "language": "st", "body": f"{counter} := {counter} + {step};"}
