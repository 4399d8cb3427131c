"""Project-wide rename refactoring and "what refers to this name" for POUs, types, globals.

A project-level name (a POU, a user type, a global variable) is used by ST texts (declarations,
bodies, globals, types, test files, a function block's methods and properties), by its EXTENDS and IMPLEMENTS,
by LD/FBD operands (contacts, coils, compares, box calls,
instances and pin operands, FBD blocks and nodes), by tasks (the programs they run) and by operator panels (a
widget's variable path starts with a global or a program: ``Start``, ``Main.Level``). Renaming
finds every use as an ST identifier token: comments, strings, literals (``T#5s``, ``16#FF``),
direct addresses (``%IX0.1``) and member names after a ``.`` are never touched, so ``x.Main`` or
``'Main'`` keep their text. IEC names are case-insensitive; the new spelling replaces every use.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any, TypeAlias

from ..model.api import Reference
from ..model.hmi import MOTION_FIELDS, PATH_FIELDS
from ..model.names import pou_name_problem
from ..model.project import Project
from . import ast
from .comments import blank_nested_comments
from .gvls import gvl_file
from .member_types import ProjectTypes, declared_types
from .parser import parse_source

#: Tokens that are never a name: strings, comments, pragmas, typed literal values, numbers, addresses.
_TOKEN = re.compile(
    r"""(?P<skip>'(?:[^'$\n]|\$.)*'|"(?:[^"$\n]|\$.)*"|//[^\n]*|\{[^}]*\}"""
    r"""|\#[A-Za-z0-9_.:+\-]*|\d[A-Za-z0-9_.]*|%[A-Za-z0-9_.*]+)"""
    r"""|(?P<name>[A-Za-z_][A-Za-z0-9_]*)"""
)
_MEMBER = re.compile(r"\.\s*$")
#: ``GVL_IO.`` right before a name: the name of a list as its qualifier (not itself a member)
_LIST_QUALIFIER = re.compile(r"(?<![.\w])([A-Za-z_][A-Za-z0-9_]*)\s*\.\s*$")
#: The first name of a variable path (``Main`` of ``Main.T1.Q``, ``Arr`` of ``Arr[2]``): a global or a program.
_PATH_HEAD = re.compile(r"^\s*([A-Za-z_][A-Za-z0-9_]*)(?=\s*(?:$|[.\[]))")

#: Keys of LD/FBD element objects whose value is ST operand text (a name, an expression, a call).
_OPERAND_KEYS = ("var", "left", "right", "call", "instance", "expr")


def name_spans(text: str, name: str, lists: frozenset[str] = frozenset()) -> list[tuple[int, int]]:
    """Start and end offsets of ``name`` used as an identifier in ST ``text`` (not as a member after ``.``, except
    after the name of one of the global variable lists ``lists`` (upper case), ``GVL.name``)."""
    key = name.upper()
    scanned = blank_nested_comments(text)  # same length: offsets stay those of ``text``
    spans = []
    for match in _TOKEN.finditer(scanned):
        if match.group("name") is None or match.group("name").upper() != key:
            continue
        if _MEMBER.search(scanned, 0, match.start()):
            before = _LIST_QUALIFIER.search(scanned, 0, match.start()) if lists else None
            if before is None or before.group(1).upper() not in lists:
                continue
        spans.append((match.start(), match.end()))
    return spans


class ListedName(str):
    """A global variable declared in the global variable lists ``lists`` (upper case): renamed bare and as
    ``GVL.name`` (st/gvls.py)."""

    lists: frozenset[str]

    @classmethod
    def of(cls, name: str, lists: frozenset[str]) -> ListedName:
        listed = cls(name)
        listed.lists = lists
        return listed


def rename_in_text(text: str, old: str, new: str) -> str:
    """``text`` with every identifier use of ``old`` spelt ``new``."""
    return _replaced(text, name_spans(text, old), new)


def _replaced(text: str, spans: list[tuple[int, int]], new: str) -> str:
    pieces, copied = [], 0
    for start, end in spans:
        pieces += [text[copied:start], new]
        copied = end
    return "".join(pieces) + text[copied:]


#: What a rename looks for: a project-level name, or a method or property of a function block (``MemberUses``).
Target: TypeAlias = "str | MemberUses"


def _spans(text: str, old: Target) -> list[tuple[int, int]]:
    if isinstance(old, ListedName):
        return name_spans(text, old, old.lists)
    return name_spans(text, old) if isinstance(old, str) else old.spans(text)


#: The path before ``.M``: ``a``, ``a.b``, ``a[i].b^``, ``THIS^``, ``SUPER^`` (indices and dereferences do not
#: change which type's member ``M`` is).
_MEMBER_OF = re.compile(
    r"(?<![.\w])(?P<path>(?:THIS|SUPER)\s*\^|[A-Za-z_]\w*(?:\s*(?:\[[^\[\]]*\]\s*)?\^?\s*\.\s*[A-Za-z_]\w*)*)"
    r"\s*(?:\[[^\[\]]*\]\s*)?\^?\s*\.\s*$",
    re.IGNORECASE,
)
_INDEX = re.compile(r"\[[^\[\]]*\]|\^|\s")


@dataclass(frozen=True)
class MemberUses:
    """The uses of method or property ``name`` of the function blocks and INTERFACEs in ``group`` in one scope:
    ``path.name`` where ``path`` (``inst``, ``a.b``, ``arr[i]``, ``r^``) is typed by ``scope`` (variable -> type) and
    ``types`` as one of ``group``, and, inside a function block of the group (``own``), ``THIS^.name``,
    ``SUPER^.name`` and a bare call ``name(...)``; inside the method itself (``inside``) every bare ``name`` (its
    result variable, a recursive call)."""

    name: str
    scope: dict[str, str]
    group: frozenset[str]
    types: ProjectTypes
    own: bool
    inside: bool = False

    def spans(self, text: str) -> list[tuple[int, int]]:
        scanned = blank_nested_comments(text)
        found = []
        for match in _TOKEN.finditer(scanned):
            if match.group("name") is None or match.group("name").upper() != self.name.upper():
                continue
            if _MEMBER.search(scanned, 0, match.start()):
                before = _MEMBER_OF.search(scanned[max(0, match.start() - 300) : match.start()])
                if before is None or not self._of_group(_INDEX.sub("", before.group("path")).split(".")):
                    continue
            elif not (self.inside or (self.own and scanned[match.end() :].lstrip().startswith("("))):
                continue
            found.append((match.start(), match.end()))
        return found

    def _of_group(self, path: list[str]) -> bool:
        if path[0].upper() in ("THIS", "SUPER"):  # THIS^.a.b: ``a`` is a variable of the FB, in ``scope``
            return self.own if len(path) == 1 else self.types.resolve(self.scope, path[1:]) in self.group
        return self.types.resolve(self.scope, path) in self.group


def rename_member(project: Project, fb: str, old: str, new: str) -> tuple[Project, list[Reference]]:
    """``project`` with method or property ``old`` of function block (program, INTERFACE) ``fb`` called ``new``: its
    declaration and that of every FB and INTERFACE sharing it (``ProjectTypes.group``: overrides, the base it
    overrides, interface methods and their implementations), and every use through a variable typed as one of them
    (``inst.Old(...)``, ``a.b.Old``, ``arr[i].Old``, ``r^.Old``, ``itf.Old()``, ``Prog.Old()``, LD/FBD boxes
    ``inst.Old``) or inside one of those FBs or programs (``THIS^.Old``, ``SUPER^.Old``, ``Old(...)``, a property's
    bare ``Old``: the value its GET assigns and its SET reads, or a use in their code); and what changed. A path
    through a property or a function's result is not followed: the check then reports the call it no longer finds."""
    data = project.model_dump(by_alias=True)
    types = ProjectTypes.of(data)
    group = types.group(fb, old)
    # a PROGRAM's name is its one instance in every POU's code (``Prog.Old()``, CODESYS), unless a variable hides it
    globals_ = {p["name"].upper(): p["name"].upper() for p in data["pous"] if p["kind"] == "program"}
    globals_ |= declared_types(data["globals"])
    changes: list[Reference] = []
    data["types"] = _interface_methods(data["types"], group, old, new, changes)
    for pou in data["pous"]:
        name, own = pou["name"], pou["name"].upper() in group
        # a property of the group's FBs is also used by its bare name in their code (where no variable hides it)
        is_property = own and any(p["name"].upper() == old.upper() for p in pou.get("properties") or [])
        scope = globals_ | types.fields.get(name.upper(), {}) | declared_types(pou["declarations"])
        pou["body"] = _body(pou["body"], MemberUses(old, scope, group, types, own, is_property), new, changes, name)
        for member in pou.get("methods") or []:  # (listed under their names as they were)
            local = declared_types(member["declarations"])
            inside = own and member["name"].upper() == old.upper()
            bare = inside or (is_property and old.upper() not in local)
            uses = MemberUses(old, scope | local, group, types, own, bare)
            where = Reference(pou=name, part="body", member=member["name"])
            if inside:
                changes.append(
                    Reference(pou=name, part="method", member=member["name"], text=f"METHOD {member['name']}")
                )
                member["name"] = new
            member["body"] = _text(member["body"], uses, new, changes, where)
        for prop in pou.get("properties") or []:
            accessors = [(kind.upper(), prop[kind]) for kind in ("get", "set") if prop.get(kind) is not None]
            for kind, accessor in accessors:
                local = declared_types(accessor["declarations"])
                uses = MemberUses(old, scope | local, group, types, own, is_property and old.upper() not in local)
                where = Reference(pou=name, part="body", member=f"{prop['name']}.{kind}")
                accessor["body"] = _text(accessor["body"], uses, new, changes, where)
            if own and prop["name"].upper() == old.upper():
                changes.append(Reference(pou=name, part="method", member=prop["name"], text=f"PROPERTY {prop['name']}"))
                prop["name"] = new
    uses = MemberUses(old, globals_, group, types, own=False)
    for test in data["tests"]:
        path = f"tests/{test['name']}.st"
        test["text"] = _text(test["text"], uses, new, changes, Reference(part="test", file=path))
    return Project.model_validate(data), changes


def _interface_methods(types: str, group: frozenset[str], old: str, new: str, found: list[Reference]) -> str:
    """The types text with the METHOD or PROPERTY ``old`` of every INTERFACE in ``group`` called ``new``."""
    parsed = parse_source(types)
    lines = types.split("\n")
    for item in parsed.ast.items if parsed.ast is not None else []:
        if not isinstance(item, ast.InterfaceDecl) or item.name.upper() not in group:
            continue
        for method in [*item.methods, *item.properties]:
            line = method.span.line - 1
            spans = name_spans(lines[line], old) if method.name.upper() == old.upper() else []
            if spans:
                where = Reference(part="types", member=f"{item.name}.{method.name}", line=line + 1)
                found.append(where.model_copy(update={"text": lines[line].strip()}))
                lines[line] = _replaced(lines[line], spans[:1], new)
    return "\n".join(lines)


def references(project: Project, name: str) -> list[Reference]:
    """Every place in ``project`` that uses ``name``, except the definition of a POU called ``name`` itself."""
    found: list[Reference] = []
    data = project.model_dump(by_alias=True)
    _visit(data, _listed(data, name), name, found, skip_pou=name)
    return found


def _listed(data: dict[str, Any], name: str) -> str:
    """``name``, as a ``ListedName`` when global variable lists of the dumped project declare it."""
    lists = frozenset(g["name"].upper() for g in data["gvls"] if name.upper() in declared_types(g["text"]))
    return ListedName.of(name, lists) if lists else name


def rename(project: Project, old: str, new: str) -> tuple[Project, list[Reference]]:
    """``project`` with ``old`` renamed to ``new`` everywhere (a POU or global variable list called ``old`` too),
    and what changed."""
    data = project.model_dump(by_alias=True)
    changes: list[Reference] = []
    _visit(data, _listed(data, old), new, changes, skip_pou=None)
    for item in [*data["pous"], *data["gvls"]]:
        if item["name"].upper() == old.upper():
            item["name"] = new
    return Project.model_validate(data), changes


def new_name_problem(project: Project, old: str, new: str) -> str | None:
    """Why ``old`` cannot become ``new`` in ``project`` (not an identifier, or another POU's name), or None."""
    problem = pou_name_problem(new)
    if problem:
        return f"{new or 'an empty name'} is no IEC name: {problem}"
    other = project.pou(new)
    if other is not None and other.name.upper() != old.upper():
        return f"there is already a POU called {other.name}"
    gvl = project.gvl(new)
    if gvl is not None and gvl.name.upper() != old.upper():
        return f"there is already a global variable list called {gvl.name}"
    return None


def member_name_problem(project: Project, fb: str, old: str, new: str) -> str | None:
    """Why method or property ``old`` of function block (or INTERFACE) ``fb`` cannot become ``new`` (no such member,
    not an identifier, the name of another member of ``fb`` or of an FB or INTERFACE renamed with it), or None."""
    pou = project.pou(fb)
    members = (
        [m.name for m in pou.methods] + [p.name for p in pou.properties] if pou else _interface_members(project, fb)
    )
    if not any(m.upper() == old.upper() for m in members):
        return f"{fb} has no method or property called {old}"
    problem = pou_name_problem(new)
    if problem:
        return f"{new or 'an empty name'} is no IEC name: {problem}"
    other = next((m for m in members if m.upper() == new.upper() and m.upper() != old.upper()), None)
    if other:
        return f"{fb} already has a member called {other}"
    data = project.model_dump(by_alias=True)
    types = ProjectTypes.of(data)
    names = {p["name"].upper(): p["name"] for p in data["pous"]}
    for kind in sorted(types.group(fb, old) - {fb.upper()}):
        if new.upper() in types.members.get(kind, set()) and new.upper() != old.upper():
            return f"{names.get(kind, kind)}, renamed with it, already has a member called {new}"
    return None


def _interface_members(project: Project, name: str) -> list[str]:
    """The methods and properties of INTERFACE ``name`` of the project's types text (none when there is no such
    INTERFACE)."""
    parsed = parse_source(project.types)
    items = parsed.ast.items if parsed.ast is not None else []
    found = next((i for i in items if isinstance(i, ast.InterfaceDecl) and i.name.upper() == name.upper()), None)
    return [m.name for m in [*found.methods, *found.properties]] if found is not None else []


def duplicate_pou(project: Project, name: str, copy: str) -> Project:
    """``project`` with a copy of POU ``name`` called ``copy`` after it (its own uses of ``name`` renamed too,
    e.g. a function's result assignment)."""
    pou = project.pou(name)
    if pou is None:
        raise KeyError(name)
    alone = Project(name=project.name, pous=[pou])
    renamed, _ = rename(alone, pou.name, copy)
    pous = list(project.pous)
    pous.insert(pous.index(pou) + 1, renamed.pous[0])
    return project.model_copy(update={"pous": pous})


def _visit(data: dict[str, Any], old: str, new: str, found: list[Reference], skip_pou: str | None) -> None:
    """Renames ``old`` to ``new`` in the dumped project ``data`` in place, noting each use in ``found``
    (``new == old`` only finds). The POU called ``skip_pou`` is left out (its definition is no reference)."""
    for part in ("globals", "types"):
        data[part] = _text(data[part], old, new, found, Reference(part=part))
    for gvl in data["gvls"]:
        gvl["text"] = _text(gvl["text"], old, new, found, Reference(part="gvl", file=gvl_file(gvl["name"])))
    for pou in data["pous"]:
        if skip_pou is not None and pou["name"].upper() == skip_pou.upper():
            continue
        name = pou["name"]
        pou["declarations"] = _text(pou["declarations"], old, new, found, Reference(pou=name, part="declarations"))
        pou["body"] = _body(pou["body"], old, new, found, name)
        if pou.get("return_type"):
            pou["return_type"] = _text(pou["return_type"], old, new, found, Reference(pou=name, part="return type"))
        _object_orientation(pou, old, new, found)
    for task in data["tasks"]:
        _task(task, old, new, found)
    for test in data["tests"]:
        path = f"tests/{test['name']}.st"
        test["text"] = _text(test["text"], old, new, found, Reference(part="test", file=path))
    for panel in data["panels"]:
        for widget in panel["widgets"]:
            _widget(widget, old, new, found, Reference(part="panel", panel=panel["name"], element=widget["id"]))


def _object_orientation(pou: dict[str, Any], old: str, new: str, found: list[Reference]) -> None:
    """A dumped function block's EXTENDS, IMPLEMENTS, METHOD texts (declarations, result type, body) and PROPERTY
    texts (type, GET and SET) renamed in place."""
    name = pou["name"]
    if pou.get("extends") and pou["extends"].upper() == old.upper():
        found.append(Reference(pou=name, part="extends", text=f"EXTENDS {pou['extends']}"))
        pou["extends"] = new
    for i, interface in enumerate(pou.get("implements") or []):
        if interface.upper() == old.upper():
            found.append(Reference(pou=name, part="implements", text=f"IMPLEMENTS {interface}"))
            pou["implements"][i] = new
    for method in pou.get("methods") or []:
        where = Reference(pou=name, part="declarations", member=method["name"])
        method["declarations"] = _text(method["declarations"], old, new, found, where)
        if method.get("return_type"):
            where = Reference(pou=name, part="return type", member=method["name"])
            method["return_type"] = _text(method["return_type"], old, new, found, where)
        method["body"] = _text(method["body"], old, new, found, Reference(pou=name, part="body", member=method["name"]))
    for prop in pou.get("properties") or []:
        where = Reference(pou=name, part="return type", member=prop["name"])
        prop["type"] = _text(prop["type"], old, new, found, where)
        for kind in ("get", "set"):
            accessor = prop.get(kind)
            if accessor is None:
                continue
            member = f"{prop['name']}.{kind.upper()}"
            for part in ("declarations", "body"):
                accessor[part] = _text(accessor[part], old, new, found, Reference(pou=name, part=part, member=member))


def _task(task: dict[str, Any], old: str, new: str, found: list[Reference]) -> None:
    """A dumped task renamed in place: its SINGLE trigger, the programs it runs, and each program instance's
    program and parameter bindings (ST expressions over globals)."""
    where = Reference(part="task", task=task["name"])
    if task.get("single") and name_spans(task["single"], old):
        found.append(where.model_copy(update={"text": task["single"]}))
        task["single"] = rename_in_text(task["single"], old, new)
    programs = task["programs"]
    for i, program in enumerate(programs):
        if isinstance(program, str):
            if program.upper() == old.upper():
                programs[i] = new
                found.append(where.model_copy(update={"text": program}))
            continue
        if program["type"].upper() == old.upper():
            found.append(where.model_copy(update={"text": f"{program['name']} : {program['type']}"}))
            program["type"] = new
        for pins in (program["inputs"], program["outputs"]):
            for pin, value in pins.items():
                if name_spans(value, old):
                    found.append(where.model_copy(update={"text": f"{program['name']}.{pin} := {value}"}))
                    pins[pin] = rename_in_text(value, old, new)


def _widget(widget: dict[str, Any], old: str, new: str, found: list[Reference], where: Reference) -> None:
    """A dumped panel widget's variable paths renamed in place where their first name is ``old``."""

    def renamed(path: str) -> str:
        head = _PATH_HEAD.match(path)
        if head is None or head.group(1).upper() != old.upper():
            return path
        found.append(where.model_copy(update={"text": path}))
        return path[: head.start(1)] + new + path[head.end(1) :]

    for field in PATH_FIELDS:
        if widget.get(field):
            widget[field] = renamed(widget[field])
    for field in MOTION_FIELDS:
        if widget.get(field):
            widget[field]["path"] = renamed(widget[field]["path"])
    if widget.get("paths"):
        widget["paths"] = [renamed(path) for path in widget["paths"]]


def _body(body: Any, old: Target, new: str, found: list[Reference], pou: str) -> Any:
    """A dumped POU, SFC action or transition body renamed in place: ST/IL text, LD/FBD networks, an SFC chart."""
    if isinstance(body, str):
        return _text(body, old, new, found, Reference(pou=pou, part="body"))
    if "networks" in body:
        for number, network in enumerate(body["networks"], start=1):
            where = Reference(pou=pou, part="network", network=network["id"], network_number=number)
            if network.get("label"):
                where.network_label = network["label"]
            for item in network.get("elements") or network.get("nodes") or []:
                _element(item, old, new, found, where)
        return body
    if "chart" in body:  # an SFC POU: its chart, then its actions' and named transitions' bodies
        _chart(body["chart"], old, new, found, pou)
        for part in (*body.get("actions", []), *body.get("transitions", [])):
            part["body"] = _body(part["body"], old, new, found, pou)
        return body
    _chart(body, old, new, found, pou)  # an action written as an SFC chart
    return body


def _chart(chart: dict[str, Any], old: Target, new: str, found: list[Reference], pou: str) -> None:
    """An SFC chart's transition conditions and the BOOL variables its steps' associations name."""
    for element in chart.get("elements", []):
        if element.get("type") == "transition":
            where = Reference(pou=pou, part="transition", element=element.get("id"))
            element["condition"] = _text(element["condition"], old, new, found, where)
        for association in element.get("actions", []):
            if isinstance(old, str) and association["action"].upper() == old.upper():
                found.append(Reference(pou=pou, part="step", element=element.get("id"), text=association["action"]))
                association["action"] = new
        for branch in element.get("branches", []):
            _chart({"elements": branch}, old, new, found, pou)


def _text(text: str, old: Target, new: str, found: list[Reference], where: Reference) -> str:
    """ST ``text`` renamed; one reference (``where`` with the line) per line that uses ``old``, as it was."""
    spans = _spans(text, old)
    lines = text.split("\n")
    seen: set[int] = set()
    for start, _ in spans:
        line = text.count("\n", 0, start) + 1
        if line not in seen:
            seen.add(line)
            found.append(where.model_copy(update={"line": line, "text": lines[line - 1].strip()}))
    return _replaced(text, spans, new) if spans and new != old else text


def _element(item: dict[str, Any], old: Target, new: str, found: list[Reference], where: Reference) -> None:
    """One LD element or FBD node: its operands, box input operands and outputs, nested branches."""
    here = where.model_copy(update={"element": item.get("id")})
    for key in _OPERAND_KEYS:
        value = item.get(key)
        if isinstance(value, str) and (spans := _spans(value, old)):
            found.append(here.model_copy(update={"text": value}))
            item[key] = _replaced(value, spans, new)
    for pins in (item.get("inputs") or {}, item.get("outputs") or {}):
        for pin, value in pins.items():
            if isinstance(value, str):
                if spans := _spans(value, old):
                    found.append(here.model_copy(update={"text": f"{pin} := {value}"}))
                    pins[pin] = _replaced(value, spans, new)
            else:
                for nested in value:
                    _element(nested, old, new, found, where)
    for branch in item.get("branches") or []:
        for nested in branch:
            _element(nested, old, new, found, where)
