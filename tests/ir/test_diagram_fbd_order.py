"""FBD network structure and evaluation order (ir/fbd_order.py): GR-05, GR-06, GR-30, GR-02, CFC-02."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from ladderlab.ir.fbd_order import Analyses, analyse
from tests.ir.diagram_support import blk, connector, continuation, fjump, fret, inp, net, out


class Collect:
    def __init__(self):
        self.messages: list[str] = []

    def __call__(self, code, message, *, network=None, element=None, pin=None, severity="error"):
        self.messages.append(f"{code} {element}.{pin}: {message}")


def order(network) -> list[str]:
    report = Collect()
    graph = analyse(network, report)
    assert report.messages == []
    return graph.order


def test_gr05_data_flow_beats_position():
    """A block runs after everything feeding it, even when drawn above and left of its source."""
    network = net(
        "n",
        [
            inp("a", "x", 0, 100),
            blk("late", "NOT", x=0, y=0),
            blk("early", "NOT", x=50, y=100),
            out("o", "y", x=100, y=0),
        ],
        [("a.OUT", "early.IN"), ("early.OUT", "late.IN"), ("late.OUT", "o.IN")],
    )
    assert order(network) == ["a", "early", "late", "o"]


def test_independent_nodes_by_position_top_to_bottom_then_left_to_right():
    nodes = [
        inp("i1", "a"),
        inp("i2", "b"),
        inp("i3", "c"),
        blk("low", "NOT", x=0, y=50),
        blk("right", "NOT", x=80, y=10),
        blk("left", "NOT", x=10, y=10),
    ]
    wires = [("i1.OUT", "low.IN"), ("i2.OUT", "right.IN"), ("i3.OUT", "left.IN")]
    assert order(net("n", nodes, wires)) == ["i3", "left", "i2", "right", "i1", "low"]


def test_explicit_order_list_decides_among_independent_nodes_then_ids():
    nodes = [blk("b", "NOT"), blk("a", "NOT"), blk("c", "NOT", x=0, y=0), inp("x", "TRUE")]
    wires = [("x.OUT", "a.IN"), ("x.OUT", "b.IN"), ("x.OUT", "c.IN")]
    assert order(net("n", nodes, wires, order=["b"])) == ["x", "b", "c", "a"]  # listed, positioned, by id
    assert order(net("n", nodes, wires)) == ["x", "c", "a", "b"]


def test_order_list_cannot_break_data_flow():
    nodes = [inp("x", "TRUE"), blk("a", "NOT"), blk("b", "NOT")]
    assert order(net("n", nodes, [("x.OUT", "a.IN"), ("a.OUT", "b.IN")], order=["b", "a"])) == ["x", "a", "b"]


def test_input_nodes_are_read_just_before_their_first_consumer_and_controls_run_last():
    """GR-05 c: a jump or return acts only when every other node of the network is evaluated."""
    nodes = [
        fjump("j", "L"),
        inp("c", "go", 0, 0),
        inp("v", "x", 0, 0),
        blk("n1", "NOT", x=0, y=10),
        blk("n2", "NOT", x=0, y=20),
        inp("w", "y", 0, 0),
        out("o", "z", x=0, y=30),
        inp("unused", "q", 0, 5),
        fret("r"),
    ]
    wires = [("c.OUT", "j.IN"), ("v.OUT", "n1.IN"), ("w.OUT", "n2.IN"), ("n2.OUT", "o.IN")]
    assert order(net("n", nodes, wires)) == ["v", "n1", "w", "n2", "o", "unused", "c", "j", "r"]


def test_gr30_wired_or_names_both_wires():
    report = Collect()
    network = net("n", [inp("a", "x"), inp("b", "y"), out("o", "z")], [("a.OUT", "o.IN"), ("b.OUT", "o.IN")])
    analyse(network, report)
    assert report.messages == [
        "FBD-WIRED-OR o.IN: 2 wires lead into it (from input x and from input y): FBD has no wired OR, use an OR block"
    ]


def test_bad_wire_ends_are_reported():
    report = Collect()
    network = net(
        "n",
        [inp("a", "x"), out("o", "z"), blk("b", "NOT")],
        [("a.Q", "b.IN"), ("ghost.OUT", "b.IN"), ("o.OUT", "b.IN"), ("b.OUT", "a.IN"), ("b.OUT", "o.X")],
    )
    analyse(network, report)
    assert report.messages == [
        "FBD-BAD-WIRE a.Q: the wire from input x to NOT.IN: an input has no output pin Q",
        "FBD-BAD-WIRE ghost.OUT: the wire from 'ghost' to NOT.IN ends at a node this network does not have",
        "FBD-BAD-WIRE o.OUT: the wire from output z to NOT.IN: an output has no output pin",
        "FBD-BAD-WIRE a.IN: the wire from NOT.OUT to input x: an input has no input pin",
        "FBD-BAD-WIRE o.X: the wire from NOT.OUT to output z: an output has no input pin X",
        "FBD-DANGLING o.IN: the output has no input wire",
    ]


def test_connectors_carry_a_wire_to_its_continuations():
    network = net(
        "n",
        [
            blk("a", "NOT", x=0, y=0),
            connector("k", "Mid"),
            continuation("c", "MID"),
            blk("b", "NOT", x=0, y=-10),
            inp("i", "x"),
        ],
        [("i.OUT", "a.IN"), ("a.OUT", "k.IN"), ("c.OUT", "b.IN")],
    )
    graph = analyse(network, Collect())
    assert graph.inputs["b"]["IN"].node == "a" and graph.order == ["i", "a", "b"]


def test_gr02_connector_errors():
    report = Collect()
    network = net(
        "n",
        [
            connector("k1", "X"),
            connector("k2", "x"),
            continuation("c1", "nowhere"),
            connector("k3", "loop"),
            continuation("c3", "loop"),
            out("o1", "a"),
            out("o2", "b"),
        ],
        [("c1.OUT", "o1.IN"), ("c3.OUT", "k3.IN"), ("c3.OUT", "o2.IN")],
    )
    graph = analyse(network, report)
    assert report.messages == [
        "FBD-CONNECTOR k2.None: this network has another connector 'x'",
        "FBD-CONNECTOR c1.None: this network has no connector 'nowhere' for the continuation to continue",
        "FBD-DANGLING k1.IN: the connector has no input wire",
        "FBD-DANGLING k2.IN: the connector has no input wire",
        "FBD-CONNECTOR k3.None: the connector is fed only through its own continuations",
    ]
    assert graph.broken == {("o1", "IN"), ("o2", "IN")}


def test_gr06_cycle_is_broken_at_its_first_node_by_position_or_explicit_order():
    nodes = [inp("x", "a"), blk("f", "AND", x=0, y=0), blk("g", "OR", x=0, y=50), out("o", "q")]
    wires = [("x.OUT", "f.IN1"), ("g.OUT", "f.IN2"), ("f.OUT", "g.IN1"), ("x.OUT", "g.IN2"), ("g.OUT", "o.IN")]
    graph = analyse(net("n", nodes, wires), Collect())
    assert graph.order == ["x", "f", "g", "o"] and graph.feedback == {("f", "IN2")}
    graph = analyse(net("n", nodes, wires, order=["g"]), Collect())
    assert graph.order == ["x", "g", "f", "o"] and graph.feedback == {("g", "IN1")}


def test_self_loop_is_feedback():
    graph = analyse(net("n", [blk("c", "ADD"), inp("one", "1")], [("c.OUT", "c.IN1"), ("one.OUT", "c.IN2")]), Collect())
    assert graph.order == ["one", "c"] and graph.feedback == {("c", "IN1")}


def test_a_cycle_fed_by_another_cycle_waits_for_it():
    """d is drawn first, but its loop (c, d) is fed by the loop (a, b), which must run before it."""
    nodes = [blk(name, "OR", x=0, y=y) for name, y in (("d", 0), ("c", 10), ("b", 20), ("a", 30))]
    wires = [("a.OUT", "b.IN1"), ("b.OUT", "a.IN1"), ("b.OUT", "c.IN1"), ("c.OUT", "d.IN1"), ("d.OUT", "c.IN2")]
    graph = analyse(net("n", nodes, wires), Collect())
    assert graph.order == ["b", "a", "d", "c"] and graph.feedback == {("b", "IN1"), ("d", "IN1")}


@st.composite
def graphs(draw):
    """Random networks of NOT/AND blocks with random wiring (cycles included) and positions."""
    count = draw(st.integers(1, 8))
    names = [f"b{i}" for i in range(count)]
    nodes = [blk(n, "AND", x=draw(st.integers(0, 3)), y=draw(st.integers(0, 3))) for n in names]
    wires = []
    for n in names:
        for pin in ("IN1", "IN2"):
            source = draw(st.sampled_from(names + ["input"]))
            if source != "input":
                wires.append((f"{source}.OUT", f"{n}.{pin}"))
    order = draw(st.lists(st.sampled_from(names), unique=True))
    return net("n", nodes, wires, order=order or None)


@given(graphs())
def test_property_order_is_complete_and_every_non_feedback_wire_runs_forward(network):
    graph = analyse(network, Collect())
    assert sorted(graph.order) == sorted(n.id for n in network.nodes)
    position = {n: i for i, n in enumerate(graph.order)}
    for consumer, sources in graph.inputs.items():
        for pin, source in sources.items():
            forward = position[source.node] < position[consumer]
            assert forward != ((consumer, pin) in graph.feedback)


@st.composite
def alike_networks(draw):
    """Two networks drawn alike (node kinds, wiring, positions, order list) whose ids are drawn apart: random
    blocks, input, output, jump nodes and a connector/continuation pair, wires to missing nodes and wired ORs
    now and then, so some structures report problems."""
    kinds = draw(
        st.lists(st.sampled_from(["block", "block", "input", "output", "jump", "pair"]), min_size=1, max_size=7)
    )

    def drawn(prefix: str) -> tuple[list, list, list | None]:
        nodes, producers, consumers = [], [], []
        for i, kind in enumerate(kinds):
            name, place = f"{prefix}{i}", {"x": float(i % 3), "y": float(i // 3)}
            if kind == "block":
                nodes.append(blk(name, "AND", **place))
                producers.append(f"{name}.OUT")
                consumers += [f"{name}.IN1", f"{name}.IN2"]
            elif kind == "input":
                nodes.append(inp(name, "x", **place))
                producers.append(f"{name}.OUT")
            elif kind == "output":
                nodes.append(out(name, "y", **place))
                consumers.append(f"{name}.IN")
            elif kind == "jump":
                nodes.append(fjump(name, "L1"))
                consumers.append(f"{name}.IN")
            else:
                nodes += [connector(f"{name}c", "C"), continuation(f"{name}k", "C")]
                producers.append(f"{name}k.OUT")
                consumers.append(f"{name}c.IN")
        return nodes, producers, consumers

    first = drawn("a")
    choices = draw(st.lists(st.tuples(st.integers(0, 20), st.integers(0, 20)), max_size=10))
    ranks = draw(st.lists(st.integers(0, len(first[0]) - 1), unique=True, max_size=3))
    prefixes = draw(st.sampled_from(["b", "zz", "a_"]))

    def network(nodes, producers, consumers):
        wires = [
            (producers[p % len(producers)] if producers and p < 18 else "ghost.OUT", consumers[c % len(consumers)])
            for p, c in choices
            if consumers
        ]
        return net("n", nodes, wires, order=[nodes[r].id for r in ranks] or None)

    return network(*first), network(*drawn(prefixes))


@given(alike_networks())
def test_property_networks_drawn_alike_get_the_graph_and_diagnostics_of_their_own_analysis(pair):
    analyses = Analyses()
    for network in (*pair, *pair):
        shared, own = Collect(), Collect()
        assert analyses.analyse(network, shared) == analyse(network, own)
        assert shared.messages == own.messages
