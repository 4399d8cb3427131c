"""A network's fast-variant code filled in from the code of an earlier network of the same shape (issue 27).

A large LD/FBD body repeats a few network shapes with other variables: ``--| A1 |--|/ B1 |--( C1 )--`` and
``--| A2 |--|/ B2 |--( C2 )--`` differ in nothing but the slots they name. ``BlockTemplates`` emits the first
network of a shape as ``Statements`` does and keeps its lines with each variable's code (``self.v_A1``) as a
hole, and each numbered temporary it made (``ll_x1``, ``Scope.temp``) as one too; a later network of that shape
gets those lines with its own variables' codes (``self.v_A2``) and temporaries made anew (``ll_x7``), its
statements' origins registered in the same order and its lines tagged as the first network's were.

The shape (``_Shape``) is everything the emitted text may depend on: each statement and expression node with all
its fields (types, constants, operators, pins, FB types, paths), which stores liveness.py drops or folds, the
indentation, and for each variable the page of its slot (``self.v_X``, ``ll_p2.v_X``) and which variables are the
same (``x AND x``, a read forwarded from the local just stored). Only the variables' names are left out. A network
is emitted as usual, and its shape never reused, when anything else could differ: a variable that is not a slot
of the POU named plainly (a global, an in-out, a located variable, an escaped name), a variable's name left in
the text outside its code (a message naming it) or its attribute (an in-out's reference ``(self, 'v_X')``), a code
of no variable of the network, a statement this module does not model (loops, jumps, returns), or a side effect
of the emission besides the origins, the pages and temporaries used and the numbered temporaries made (a
diagnostic, a bound constant, an outlined body). Only the fast variant, which records no probe, is filled in
(tests/engine/test_block_templates.py compares the module, its line origins and its origins with those of the
plain emission).

A network the LD lowering filled in from a template of its own (``ir.Block.filled``) is not walked for its shape:
the lowering's networks of one template differ only in their variables (and origins and probe names), so its shape
is that of the first of them whose variables have the same types and whose statements have the same dead stores,
folds and stored inputs (``_Filled``, ``_Twin``; tests/engine/test_filled_networks.py compares the code with that
of the same IR without ``filled``), on whichever pages its variables live: a variable's code names its page
(``ll_p2.v_X``), so the pages the code loads are those its codes name, the first network's shared variables' and
the network's own (the template is kept only where its pages are just those).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from ...ir import nodes as ir
from ...ir.nodes import node_fields
from .mentions import walk_filled

if TYPE_CHECKING:
    from .statements import Statements

#: A variable's code in a line (split out of it) and a word (a name) in what is left
_CODES = re.compile(r"(?<![\w.])((?:self|ll_p\d+|G\d*)\.v_\w+)")
_WORD = re.compile(r"[A-Za-z0-9_]+")
#: a page's local outside a variable's code (``(ll_p2, 'v_X')``): a twin on another page would need another text
_PAGE_TEXT = re.compile(r"\bll_p\d")
_PROBE = ("probe",)
_DEAD = ("dead",)


#: a template's lines to fill in (``_Template.format``): format texts of lines with holes, tuples of lines without
_Text = list[str | tuple[str, ...]]


def _escaped(code: str | int) -> str:
    """``code`` in a format text: itself (braces doubled), or the hole of the code at that position."""
    return code.replace("{", "{{").replace("}", "}}") if isinstance(code, str) else f"{{{code}}}"


class _Unshaped(Exception):
    """The block has something a template does not model: it is emitted as usual."""


@dataclass(slots=True)
class _Template:
    lines: list[tuple[str | int, ...]]  # literal parts and the indices of the block's variables' codes
    origins: list[int]  # per line: the index (in ``statements``) of the statement it comes from, -1: the block's
    statements: list[int]  # the walk positions of the statements that registered an origin, in order
    temps: frozenset[str]  # the temporaries' locals and the pages the block's code uses
    pages: frozenset[int]
    temporaries: list[str]  # the prefixes of the numbered temporaries it makes, in order (``Scope.temp``)
    text: _Text = field(init=False)  # ``lines`` to fill in with the block's codes (``format``)

    def __post_init__(self) -> None:
        self.text = self.format([])

    def format(self, codes: list[str | int]) -> _Text:
        """``lines`` to fill in (``_fill``): each run of lines with holes as one ``str.format`` text (filled in at
        once), each hole ``i`` by ``codes[i]`` (a code itself, or the position of the code filled in; ``i`` itself
        beyond ``codes``); each run of lines without as those lines, the same strings in every network filled in."""
        text: _Text = []
        for line in self.lines:
            last = text[-1] if text else None
            if len(line) == 1:  # a line without a hole (``_holes`` split nothing off)
                whole = line[0]
                assert isinstance(whole, str)
                if isinstance(last, tuple):
                    text[-1] = last + (whole,)
                else:
                    text.append((whole,))
                continue
            filled = "".join(
                _escaped(part if isinstance(part, str) else codes[part] if part < len(codes) else part) for part in line
            )
            if isinstance(last, str):
                text[-1] = f"{last}\n{filled}"
            else:
                text.append(filled)
        return text


@dataclass(slots=True)
class _Twin:
    """What the first network filled in from a lowering template found (``BlockTemplates.emit``): the template of
    its shape (None: emitted as usual); its text (``_Template.format``), with the codes of the variables of its
    statements other than the network's own written in and the network's own (``ir.Filled.variables``) as holes by
    their position among those; the positions the text fills in, and the pages the other codes name (a twin loads
    those and its own variables' pages: ``_Filled``)."""

    template: _Template | None
    text: _Text = field(default_factory=list)
    own: list[int] = field(default_factory=list)
    pages: frozenset[int] = frozenset()


class BlockTemplates:
    """The templates of one POU's network shapes (one per generated POU: its scope fixes the codes' forms)."""

    def __init__(self) -> None:
        self._found: dict[tuple, _Template | None] = {}  # None: a shape that is emitted as usual
        self._twins: dict[tuple[Any, ...], _Twin] = {}  # by a filled network's template and what its shape adds to it

    def emit(self, st: Statements, block: ir.Block, own_group: bool) -> None:
        """``st.statements(block.statements, own_group)``, from the block's template where there is one. A network
        the lowering filled in from a template of its own (``block.filled``) has the shape of the first network
        filled from that template whose variables have the same types and whose statements the same liveness and
        stored inputs (``_Filled``), whichever pages its variables live on: its shape is not computed again."""
        filled = _Filled.of(st, block) if block.filled is not None else None
        if filled is None:
            self._emit(st, block, own_group)
            return
        key = (st.src.depth, st.blocks, own_group, block.filled, filled.key)
        twin = self._twins.get(key)
        if twin is None:
            self._twins[key] = self._emit(st, block, own_group, filled)
        elif twin.template is None:
            st.statements(block.statements, own_group=own_group)
        else:
            pages = filled.pages
            used = {pages[i] for i in twin.own}
            used.discard(0)
            _fill(st, twin.template, twin.text, filled.codes, filled.walked, twin.pages.union(used))

    def _emit(self, st: Statements, block: ir.Block, own_group: bool, filled: _Filled | None = None) -> _Twin:
        """``emit`` by the block's shape; what it found, for the twins of a filled network (``filled``)."""
        shape = _Shape(st)
        try:
            key = (st.src.depth, st.blocks, own_group, shape.statements(block.statements))
            template = self._found.get(key, False)
        except (_Unshaped, TypeError):  # (TypeError: an unhashable field)
            st.statements(block.statements, own_group=own_group)
            return _Twin(None)
        if isinstance(template, _Template):
            _fill(st, template, template.text, list(shape.codes), shape.walked, template.pages)
        elif template is None:
            st.statements(block.statements, own_group=own_group)
        else:  # a new shape: emit it and learn it
            template = self._found[key] = _learn(st, block, own_group, shape)
        if filled is None or template is None:
            return _Twin(None)
        position = {code: i for i, code in enumerate(filled.codes)}
        codes = [position.get(code, code) for code in shape.codes]
        own = [code for code in codes if isinstance(code, int)]
        codes += range(len(filled.codes), len(filled.codes) + len(template.temporaries))  # (``_fill`` adds them)
        shared = frozenset(
            int(code[4 : code.index(".")]) for code in codes if isinstance(code, str) and code[:4] == "ll_p"
        )
        if template.pages != shared.union(filled.pages[i] for i in own).difference((0,)) or any(
            _PAGE_TEXT.search(part) for parts in template.lines for part in parts if isinstance(part, str)
        ):  # a page its code uses that none of its codes names: the twins' pages are not known
            return _Twin(None)
        return _Twin(template, template.format(codes), own, shared)


@dataclass(slots=True)
class _Filled:
    """A network filled in from a lowering template (``ir.Filled``): what its shape (``_Shape``) holds besides the
    template (``key``: its variables' types, its statements' liveness and stored inputs), its variables' codes and
    pages, and its statements in ``_Shape``'s order. A variable's code names its page (``ll_p2.v_X``), so the pages
    are not part of the shape: the code uses those of its variables (``_Twin``)."""

    key: tuple[Any, ...]
    codes: list[str]
    pages: list[int]
    walked: list[ir.Stmt]

    @staticmethod
    def of(st: Statements, block: ir.Block) -> _Filled | None:
        """None when a variable is not a slot of the POU named plainly (its shape is computed: ``_Shape.var``)."""
        place = st.scope.placed
        facts: list[tuple[int, int]] = []
        codes: list[str] = []
        pages: list[int] = []
        filled = block.filled
        assert filled is not None  # (asked only of filled networks)
        for var in filled.variables(block.statements):
            code, ty, page = place(var)
            if not (page or code.startswith("self.v_")) or code.startswith("v_w", code.find(".") + 1):
                return None  # (not a slot of this POU, or an escaped name: ``_Shape.var``)
            facts.append((id(var.type), id(ty)))
            codes.append(code)
            pages.append(page)
        if len(set(codes)) != len(codes):
            return None
        once = st.stored_once
        liveness = st.filled_liveness.get(id(block))
        if liveness is not None:  # its dead stores and folds: its template's for the temporaries live after it
            after, walked = liveness
            flags: tuple[Any, ...] = (after, tuple([once(s) for s in walked if type(s) is ir.FbCall]))
        else:
            walked = walk_filled(block.statements, [])  # (``_Shape``'s order)
            dead, folds = st.dead, st.folds
            flags = tuple(
                [(id(s) in dead, folds.get(id(s)), once(s) if type(s) is ir.FbCall else None) for s in walked]
            )
        return _Filled((tuple(facts), flags), codes, pages, walked)


def _learn(st: Statements, block: ir.Block, own_group: bool, shape: _Shape) -> _Template | None:
    """Emit the block as usual; its template, or None when something besides its text and origins changed."""
    src, module, scope = st.src, st.module, st.scope
    lines, origins, outer = len(src.lines), len(module.origins), src.origin
    counts = (len(module.diagnostics), len(module.bound), len(st.outlines.lines))
    made = len(scope.temp_prefixes)
    temps, pages = scope.temps_used, scope.pages_used
    scope.temps_used, scope.pages_used = set(), set()
    try:
        st.statements(block.statements, own_group=own_group)
    finally:
        used_temps, used_pages = scope.temps_used, scope.pages_used
        temps |= used_temps
        pages |= used_pages
        scope.temps_used, scope.pages_used = temps, pages
    if counts != (len(module.diagnostics), len(module.bound), len(st.outlines.lines)):
        return None
    prefixes = scope.temp_prefixes[made:]  # the numbered temporaries it made: holes too, made anew for each network
    numbered = [f"ll_{prefix}{made + i}" for i, prefix in enumerate(prefixes, 1)]
    held = st._output_line  # an inlined FB's output store that a following statement may chain onto
    if held is not None and held[0] is src and held[1] == len(src.lines) - 1:  # (Statements._chained): the last line
        return None
    position = {id(s): i for i, s in enumerate(shape.walked)}
    statements = []
    for s, origin in zip(module.origin_statements[origins:], module.origins[origins:]):
        found = position.get(id(s))
        if found is None or origin is not shape.walked[found].origin:
            return None
        statements.append(found)
    line_origins = []
    for oid in src.line_origins[lines:]:
        if oid is not None and oid >= origins:
            line_origins.append(oid - origins)
        elif oid == outer:
            line_origins.append(-1)
        else:
            return None
    template = _holes(src.lines[lines:], shape, numbered)
    if template is None:
        return None
    return _Template(template, line_origins, statements, frozenset(used_temps), frozenset(used_pages), prefixes)


def _holes(lines: list[str], shape: _Shape, numbered: list[str]) -> list[tuple[str | int, ...]] | None:
    """``lines`` with each variable's code a hole (its index) and each ``numbered`` temporary one (its index after
    the codes); None when a code of no variable of the block, or a variable's name or attribute outside its code (a
    message naming it, a reference ``(self, 'v_X')`` to it), is in them."""
    codes = shape.codes
    names = {part.upper() for code in codes for part in (code.partition(".v_")[2], code.partition(".")[2])}
    temporaries = {name: len(codes) + i for i, name in enumerate(numbered)}
    split = re.compile(rf"(?<!\w)({'|'.join(numbered)})(?!\w)") if numbered else None
    template = []
    for line in lines:
        if "\n" in line:  # (never a line of code: ``_Template.text`` is split at them)
            return None
        parts: list[str | int] = []
        for i, piece in enumerate(_CODES.split(line)):
            if i % 2:  # a code
                found = codes.get(piece)
                if found is None:
                    return None
                parts.append(found)
            elif any(word.upper() in names for word in _WORD.findall(piece)):
                return None
            elif split is None:
                parts.append(piece)
            else:
                parts += [temporaries[part] if k % 2 else part for k, part in enumerate(split.split(piece))]
        template.append(tuple(parts))
    return template


def _fill(
    st: Statements, template: _Template, text: _Text, codes: list[str], walked: list[ir.Stmt], pages: frozenset[int]
) -> None:
    """The template's lines (``text``: ``template.text`` or a twin's) with this block's ``codes``, its statements'
    origins registered in order (``walked``: its statements in ``_Shape``'s order), ``pages`` noted as used."""
    src, module, scope = st.src, st.module, st.scope
    outer = src.origin
    if template.temporaries:  # (made now: numbered as the plain emission would)
        codes = [*codes, *[scope.temp(prefix) for prefix in template.temporaries]]
    lines = src.lines
    for run in text:
        if isinstance(run, tuple):
            lines.extend(run)
        else:
            lines.extend(run.format(*codes).split("\n"))
    origin = module.origin
    oids = [origin(walked[i].origin, walked[i]) for i in template.statements]
    src.line_origins.extend([outer if k < 0 else oids[k] for k in template.origins])
    scope.temps_used |= template.temps
    scope.pages_used |= pages
    st._output_line = None  # (as its shape's first network left it: ``_learn``)


class _Shape:
    """A block's shape (``statements``), the codes of its variables by first appearance, and its statements in
    ``mentions.walk``'s order. Types and members stand in it by identity (``id``: the IR is alive meanwhile): an
    equal type that is another object only makes another shape."""

    def __init__(self, st: Statements) -> None:
        self.place = st.scope.placed
        self.dead, self.folds, self.once = st.dead, st.folds, st.stored_once
        self.codes: dict[str, int] = {}
        self.walked: list[ir.Stmt] = []

    def statements(self, statements: list[ir.Stmt]) -> tuple:
        return tuple([self.statement(s) for s in statements])

    def statement(self, s: Any) -> tuple:
        self.walked.append(s)
        kind = type(s)
        if kind is ir.Probe:  # (the fast variant records none)
            return _PROBE
        if kind is ir.Assign:
            if id(s) in self.dead:  # left out (liveness.py): its variables are not read
                return _DEAD
            return (self.folds.get(id(s)), self.var(s.target), self.value(s.value))
        if kind is ir.If:
            branches = tuple([(self.value(cond), self.statements(body)) for cond, body in s.branches])
            return (kind, branches, self.statements(s.orelse))
        value = self.value
        if kind is ir.FbCall:
            inputs = tuple([(pin, value(e)) for pin, e in s.inputs])
            outputs = tuple([(pin, self.var(v)) for pin, v in s.outputs])
            once = self.once(s)  # (by the instance's name: constant_inputs.py)
            return (
                kind,
                id(s) in self.dead,
                self.var(s.instance),
                inputs,
                outputs,
                value(s.en),
                value(s.eno),
                s.body,
                once,
            )
        if kind is ir.FnCall:
            return (kind, id(s) in self.dead, value(s.call), value(s.target), value(s.en), value(s.eno))
        raise _Unshaped

    def value(self, value: Any) -> Any:
        kind = type(value)
        if kind is ir.Var:
            return self.var(value)
        if kind is ir.Binary:
            return (value.op, self.value(value.left), self.value(value.right), id(value.type))
        if kind is ir.Unary:
            return (kind, value.op, self.value(value.operand), id(value.type))
        if kind is ir.Const:
            return (kind, self.value(value.value), id(value.type))
        if kind is str or value is None:
            return value
        if kind is int or kind is bool or kind is float:
            return (kind, value)  # (1, 1.0 and True are equal keys, not equal code)
        if kind is tuple or kind is list:
            return tuple([self.value(v) for v in value])
        if kind is ir.Member or kind is ir.Deref:
            return value
        if kind is ir.Origin:
            raise _Unshaped
        if kind.__module__ == ir.__name__:  # another expression, or an index
            return (kind, *[self.value(v) for v in node_fields(value).values()])
        return id(value)  # a type

    def var(self, var: ir.Var) -> tuple:
        code, ty, page = self.place(var)
        if page or code.startswith("self.v_"):  # a slot of this POU (on page ``page``: ``ll_p2.v_X``)
            if code.startswith("v_w", code.find(".") + 1):  # an escaped name (names.escape): not the IEC name
                raise _Unshaped
            held: Any = (page, self.codes.setdefault(code, len(self.codes)))
        elif code.startswith("ll_t_"):  # a temporary's local: the same in every network
            held = code
        else:  # a global, an in-out, a located variable ...
            raise _Unshaped
        return (id(var.type), self.value(var.path) if var.path else (), id(ty), held)
