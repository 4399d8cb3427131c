"""A project's configuration in PLCopen XML (``instances/configurations``), both ways.

``<configuration name>`` holds ``<resource name>``s; a resource its ``<globalVars>``, its ``<task name
interval single priority>``s with the ``<pouInstance name typeName>``s they run, and the program instances
of no task. What the TC6 schema has no element for travels in LadderLab's addData (``<ll:info>``): a
program instance's RETAIN and parameter bindings (JSON), a configuration's own VAR_GLOBAL, VAR_ACCESS and
VAR_CONFIG texts, a resource's processor (ON), globals text as typed, or that it was written without a name.
Another tool's document reads with the elements only; CODESYS's with its GVLs that mix qualifiers
(``global_lists``), its intervals written as XML durations and its program calls with an empty typeName.

A project's own tasks (no configuration) are written as configuration ``config`` with resource
``resource`` whose instances are named after their programs; a document whose configuration runs nothing
and holds only globals reads back as the project's globals.

Named global variable lists (``Project.gvls``) are written as CODESYS writes a GVL, in the (first) resource: one
``<globalVars name>`` holding every variable under its first block's qualifiers, its blocks in a
``mixedattrsvarlist`` entry when they are several, ``{attribute 'qualified_only'}`` in its ``attributes`` entry.
A ``<globalVars>`` with a name, in a configuration or a resource, reads back as a list of that name. A resource
written only to hold the lists (a project without tasks) is marked ``lists`` and reads back as none.
"""

from __future__ import annotations

import json
import re
import xml.etree.ElementTree as ET
from collections.abc import Callable
from decimal import Decimal

from ...model.diagnostics import Diagnostic
from ...model.project import Configuration, GlobalVariableList, ProgramInstance, Project, Resource, Task
from ...st import ast
from ...st.parser import parse_declarations
from .vars import ATTRIBUTES_DATA
from .xml_io import Reader, data_entries, info, info_text, ladderlab_data, sub

CONFIGURATION = "config"
RESOURCE = "resource"
MIXED_DATA = "http://www.3s-software.com/plcopenxml/mixedattrsvarlist"
_DURATION = re.compile(r"P(?:(\d+)D)?(?:T(?:(\d+)H)?(?:(\d+)M)?(?:(\d+(?:\.\d+)?)S)?)?")

QUALIFIED_ONLY = "qualified_only"

VarBlocks = Callable[[str, str], list[ast.VarBlock]]  # (text, file) -> parsed VAR blocks
WriteList = Callable[[ET.Element, ast.VarBlock], ET.Element]
ReadList = Callable[[list[ET.Element], str | None], str]  # (<globalVars> elements, carried text) -> VAR_GLOBAL text


# ---------------------------------------------------------------- export


def write_instances(
    project: Project, parent: ET.Element, var_blocks: VarBlocks, write_list: WriteList, problems: list[Diagnostic]
) -> None:
    """``<configurations>`` of ``project`` under ``parent`` (``<instances>``)."""
    configurations = sub(parent, "configurations")
    globals_ = var_blocks(project.globals, "globals.st")
    config = project.configuration
    lists_only = config is None and not project.tasks and bool(project.gvls)  # a resource only to hold the lists
    if config is None:
        if not globals_ and not project.tasks and not project.gvls:
            return
        resources = [Resource(name=RESOURCE, tasks=project.tasks)] if project.tasks or project.gvls else []
        config = Configuration(name=CONFIGURATION, resources=resources)
    node = sub(configurations, "configuration", {"name": config.name})
    for r, resource in enumerate(config.resources):
        holder = sub(node, "resource", {"name": resource.name or RESOURCE})
        for t, task in enumerate(resource.tasks):  # TC6's order: tasks, globalVars, pouInstances
            where = f"$.configuration.resources[{r}].tasks[{t}]" if project.configuration else f"$.tasks[{t}]"
            _task(holder, task, where, problems)
        if r == 0:
            _write_gvls(holder, project, var_blocks, write_list)
        for block in var_blocks(resource.globals, f"configuration/{resource.name}/globals"):
            write_list(holder, block)
        for program in resource.programs:
            _instance(holder, program)
        if resource.name is None or resource.on is not None or resource.globals or lists_only:
            texts = {"globals": resource.globals} if resource.globals else None
            attributes = {"unnamed": resource.name is None or None, "on": resource.on, "lists": lists_only or None}
            ladderlab_data(holder, attributes, texts)
    if not config.resources:
        _write_gvls(node, project, var_blocks, write_list)
    for block in globals_ + var_blocks(config.globals, "configuration/globals"):
        write_list(node, block)
    if project.configuration is not None:
        texts = {"globals": config.globals, "access": config.access, "config": config.config}
        ladderlab_data(node, None, {name: text for name, text in texts.items() if text})
    elif project.tasks:
        ladderlab_data(node, {"tasks": True})  # the project's own tasks: they read back as tasks


def _write_gvls(holder: ET.Element, project: Project, var_blocks: VarBlocks, write_list: WriteList) -> None:
    """Each GVL as CODESYS writes it (module docstring), its text carried as typed in LadderLab's addData."""
    for gvl in project.gvls:
        blocks = var_blocks(gvl.text, f"gvls/{gvl.name}.st")
        first = blocks[0].qualifiers if blocks else []
        node = write_list(holder, ast.VarBlock("VAR_GLOBAL", first, [d for b in blocks for d in b.decls]))
        node.set("name", gvl.name)
        add = ladderlab_data(node, None, {"text": gvl.text} if gvl.text else None)
        if gvl.qualified_only:
            data = sub(add, "data", {"name": ATTRIBUTES_DATA, "handleUnknown": "implementation"})
            sub(sub(data, "Attributes"), "Attribute", {"Name": QUALIFIED_ONLY, "Value": ""})
        if len(blocks) > 1:
            data = sub(add, "data", {"name": MIXED_DATA, "handleUnknown": "implementation"})
            mixed = sub(data, "MixedAttrsVarList")
            for block in blocks:
                write_list(mixed, block).set("name", gvl.name)


def _task(resource: ET.Element, task: Task, where: str, problems: list[Diagnostic]) -> None:
    if not 0 <= task.priority <= 65535:
        problems.append(
            Diagnostic(
                code="PLCOPEN-EXPORT",
                json_path=f"{where}.priority",
                message=f"task {task.name}: PLCopen priorities are 0..65535, not {task.priority}",
            )
        )
    attributes = {"name": task.name, "priority": task.priority, "interval": task.interval, "single": task.single}
    node = sub(resource, "task", {k: v for k, v in attributes.items() if v is not None})
    for program in task.programs:
        _instance(node, ProgramInstance(name=program, type=program) if isinstance(program, str) else program)


def _instance(parent: ET.Element, instance: ProgramInstance) -> None:
    node = sub(parent, "pouInstance", {"name": instance.name, "typeName": instance.type})
    if instance.retain or instance.inputs or instance.outputs:
        bindings = {"inputs": json.dumps(instance.inputs), "outputs": json.dumps(instance.outputs)}
        ladderlab_data(node, {"retain": instance.retain}, bindings)


# ---------------------------------------------------------------- import


def read_gvls(reader: Reader, configurations: list[ET.Element], read_list: ReadList) -> list[GlobalVariableList]:
    """The named lists of ``<configuration>`` elements and their resources, in document order."""
    holders = [h for c in configurations for h in [c, *reader.children(c, "resource")]]
    return [
        _read_gvl(reader, node, read_list)
        for h in holders
        for node in reader.children(h, "globalVars")
        if node.get("name")
    ]


def _read_gvl(reader: Reader, node: ET.Element, read_list: ReadList) -> GlobalVariableList:
    attributes = [
        attribute.get("Name")
        for data in data_entries(node, reader, ATTRIBUTES_DATA)
        for holder in reader.children(data, "Attributes")
        for attribute in reader.children(holder, "Attribute")
    ]
    text = read_list(_blocks(reader, node), info_text(info(node, reader), "text"))
    return GlobalVariableList(name=node.get("name", ""), qualified_only=QUALIFIED_ONLY in attributes, text=text)


def read_instances(
    reader: Reader, configurations: list[ET.Element], read_list: ReadList
) -> tuple[str, Configuration | None, list[Task]]:
    """(the project's globals text, its configuration, its own tasks) from ``<configuration>`` elements;
    ``read_list(lists, carried)`` turns ``<globalVars>`` elements into a VAR_GLOBAL text (the carried text
    when it still says the same). Named lists are GVLs (``read_gvls``), not part of these."""
    if len(configurations) > 1:
        reader.report(
            "PLCOPEN-CONFIG",
            f"{len(configurations)} configurations: a project runs one, so only the first was imported "
            "(the globals of all of them were)",
            configurations[1],
            severity="warning",
        )
    lists = [g for c in configurations for g in global_lists(reader, c)]
    if not configurations:
        return read_list(lists, None), None, []
    node = configurations[0]
    ours = info(node, reader)
    resources = [
        _resource(reader, r, read_list) for r in reader.children(node, "resource") if not _lists_only(reader, r)
    ]
    carried = info_text(ours, "globals")
    globals_ = read_list(lists, None)
    if not resources and not carried:  # a configuration that only holds globals: the project's globals
        return globals_, None, []
    if ours is not None and ours.get("tasks") == "true":  # LadderLab's project with its own tasks
        tasks = [task for resource in resources for task in resource.tasks]
        for task in tasks:
            task.programs = [_short(p) for p in task.programs]
        return globals_, None, tasks
    configuration = Configuration(
        name=node.get("name", CONFIGURATION),
        resources=resources,
        access=info_text(ours, "access") or "",
        config=info_text(ours, "config") or "",
    )
    if carried:  # LadderLab's own: its configuration's globals are the last lists, the project's the others
        own = len(parse_declarations(carried).ast or [])
        globals_, configuration.globals = read_list(lists[: len(lists) - own], None), carried
    return globals_, configuration, []


def _short(program: str | ProgramInstance) -> str | ProgramInstance:
    """An instance named after its program without bindings is written as the program's name."""
    if (
        isinstance(program, ProgramInstance)
        and program.name == program.type
        and program == ProgramInstance(name=program.name, type=program.type)
    ):
        return program.name
    return program


def _lists_only(reader: Reader, node: ET.Element) -> bool:
    """A resource LadderLab wrote only to hold a project's GVLs."""
    ours = info(node, reader)
    return ours is not None and ours.get("lists") == "true"


def _resource(reader: Reader, node: ET.Element, read_list: ReadList) -> Resource:
    ours = info(node, reader)
    unnamed = ours is not None and ours.get("unnamed") == "true"
    return Resource(
        name=None if unnamed else node.get("name", RESOURCE),
        on=ours.get("on") if ours is not None else None,
        globals=read_list(global_lists(reader, node), info_text(ours, "globals")),
        tasks=[_read_task(reader, t) for t in reader.children(node, "task")],
        programs=[_read_instance(reader, i) for i in reader.children(node, "pouInstance")],
    )


def global_lists(reader: Reader, holder: ET.Element) -> list[ET.Element]:
    """The unnamed ``<globalVars>`` of a configuration or resource (named ones are GVLs, ``read_gvls``), each as its
    blocks (``_blocks``)."""
    return [
        block
        for node in reader.children(holder, "globalVars")
        if not node.get("name")
        for block in _blocks(reader, node)
    ]


def _blocks(reader: Reader, node: ET.Element) -> list[ET.Element]:
    """A ``<globalVars>`` as its VAR_GLOBAL blocks. CODESYS writes a GVL that mixes qualifiers (VAR_GLOBAL CONSTANT
    and VAR_GLOBAL) as one list with the first block's qualifiers for every variable, and the blocks as they are in
    its ``.../plcopenxml/mixedattrsvarlist`` entry: those blocks are the GVL."""
    split = [
        block
        for data in data_entries(node, reader, MIXED_DATA)
        for mixed in reader.children(data, "MixedAttrsVarList")
        for block in reader.children(mixed, "globalVars")
    ]
    return split or [node]


def _duration(text: str) -> str:
    """CODESYS writes a task's interval as an XML Schema duration (``PT0.01S``); LadderLab's is an IEC TIME
    literal (``T#10ms``). Any other text is kept as it is (the build reports one that is not a TIME)."""
    found = _DURATION.fullmatch(text)
    if found is None or text in ("P", "PT") or text.endswith("T"):
        return text
    days, hours, minutes = (int(g or 0) for g in found.groups()[:3])
    seconds = Decimal(found.group(4) or 0)
    whole, fraction = int(seconds), seconds - int(seconds)
    nanoseconds = int(fraction * 1_000_000_000)
    if fraction * 1_000_000_000 != nanoseconds:
        return text  # finer than a nanosecond: no TIME literal says it; the build reports it
    parts = [
        (days, "d"),
        (hours, "h"),
        (minutes, "m"),
        (whole, "s"),
        (nanoseconds // 1_000_000, "ms"),
        (nanoseconds // 1000 % 1000, "us"),
        (nanoseconds % 1000, "ns"),
    ]
    return "T#" + ("".join(f"{value}{unit}" for value, unit in parts if value) or "0s")


def _read_task(reader: Reader, node: ET.Element) -> Task:
    name = node.get("name", "")
    interval, single = node.get("interval"), node.get("single")
    interval = _duration(interval) if interval else interval
    if not interval and not single:
        reader.report(
            "PLCOPEN-CONFIG",
            f"task {name} has neither interval nor single; it is imported as a cyclic task of T#10ms",
            node,
            severity="warning",
        )
        interval = "T#10ms"
    try:
        priority = int(node.get("priority", "0"))
    except ValueError:
        reader.report(
            "PLCOPEN-CONFIG",
            f"task {name}: priority '{node.get('priority')}' is not a number; 0 is used",
            node,
            severity="warning",
        )
        priority = 0
    programs: list[str | ProgramInstance] = [_read_instance(reader, i) for i in reader.children(node, "pouInstance")]
    return Task(name=name, interval=interval or None, single=single, priority=priority, programs=programs)


def _read_instance(reader: Reader, node: ET.Element) -> ProgramInstance:
    ours = info(node, reader)
    retain = ours.get("retain") if ours is not None else None
    bindings = {}
    for kind in ("inputs", "outputs"):
        text = info_text(ours, kind)
        try:
            value = json.loads(text) if text else {}
        except json.JSONDecodeError:
            value = None
        if not isinstance(value, dict) or not all(isinstance(v, str) for v in value.values()):
            reader.report("PLCOPEN-CONFIG", f"the {kind} of program instance {node.get('name')} are unreadable", node)
            value = {}
        bindings[kind] = value
    return ProgramInstance(
        name=node.get("name", ""),
        type=node.get("typeName") or node.get("name", ""),  # CODESYS: a task's program call, typeName empty
        retain=retain if retain in ("RETAIN", "NON_RETAIN") else None,
        **bindings,
    )
