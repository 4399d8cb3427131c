"""What the project runs (st/configuration.py's checked result) -> IR program instances, tasks, access paths.

Every task gets a body: the FB calls of its program instances in order (``PROGRAM inst WITH task : Type
(in := expr, out => var)`` is ``inst(in := expr, out => var)`` in the global scope), which the engine runs
as one generated function. Instances without a task (a configuration's ``PROGRAM inst : Type;``, CFG-06)
run in a cyclic task ``DEFAULT`` of 10 ms after every other task; a project without a configuration or tasks
runs every PROGRAM in it (issue 4). A configuration with no instance runs nothing. The plants' instances run
in the plant task (``TaskSpec.plant``, ``PLANT_TASK``), which the engine runs first in every scan (issue 21).
"""

from __future__ import annotations

from ..iec.literals import decode_duration
from ..model.diagnostics import Diagnostic
from ..model.validate import PLANT_TASK
from ..st import ast
from ..st.configuration import ConfigurationInfo, InstanceInfo
from ..st.printer import print_expression
from ..st.symbols import CheckResult
from .context import PouContext
from .lower_expr import convert, lower_access, lower_to, value_type
from .lower_types import LoweringError
from .nodes import Assign, Const, FbCall, Member, Origin, ProgramInstance, Slot, Stmt, TaskSpec, Var
from .types import FbInstance

#: The task of a project without a task configuration, and of a configuration's instances without a task.
DEFAULT_TASK = "DEFAULT"
DEFAULT_INTERVAL_MS = 10


def lower_configuration(
    checked: CheckResult, diagnostics: list[Diagnostic], image: dict[str, Slot] | None = None
) -> tuple[list[ProgramInstance], list[TaskSpec], dict[str, tuple[str, bool]]]:
    """(instances, tasks, access paths) of the checked project; problems go to ``diagnostics``, addresses the
    bindings use without a declaration to ``image``."""
    info: ConfigurationInfo = checked.configuration
    ctx = PouContext(checked, None, diagnostics, image)  # the global scope
    instances = {name: ProgramInstance(name, i.pou.name.upper(), i.retain) for name, i in info.instances.items()}
    for entry in info.entries:
        _config_entry(entry, instances, ctx)
    tasks = []
    for task in info.tasks:
        try:
            interval = decode_duration(task.interval.replace(" ", "")) if task.interval else None
        except (ValueError, IndexError):  # validate_project reported BAD-INTERVAL
            continue
        single = print_expression(task.single) if task.single is not None else None
        body = [s for name in task.instances for s in _run(info.instances[name], ctx)]
        tasks.append(TaskSpec(task.name.upper(), interval, task.priority, list(task.instances), single, body))
    if info.name is None and not info.tasks and info.unscheduled:  # no tasks: every PROGRAM, every 10 ms
        tasks.append(_default_task(info, info.unscheduled, 0, ctx))
    elif info.name is not None and info.unscheduled:
        lowest = max((task.priority for task in tasks), default=-1) + 1
        tasks.append(_default_task(info, info.unscheduled, lowest, ctx))
    if info.plants:
        body = [s for name in info.plants for s in _run(info.instances[name], ctx)]
        tasks.append(TaskSpec(PLANT_TASK, DEFAULT_INTERVAL_MS, 0, list(info.plants), None, body, plant=True))
    access = {name: (print_expression(a.path), a.read_only) for name, a in info.access.items()}
    return list(instances.values()), tasks, access


def _default_task(info: ConfigurationInfo, names: list[str], priority: int, ctx: PouContext) -> TaskSpec:
    body = [s for name in names for s in _run(info.instances[name], ctx)]
    return TaskSpec(DEFAULT_TASK, DEFAULT_INTERVAL_MS, priority, list(names), None, body)


def _run(instance: InstanceInfo, ctx: PouContext) -> list[Stmt]:
    """One run of a program instance: its input bindings, the call, its output bindings."""
    name = instance.name.upper()
    fb = FbInstance(instance.pou.name.upper())
    origin = Origin(instance.pou.name.upper())
    pins = ctx.types_for(instance.pou.name)
    call = FbCall(Var("global", name, fb), [], [], origin)
    after: list[Stmt] = []
    try:
        for symbol, node in instance.inputs:
            call.inputs.append((symbol.name.upper(), lower_to(node, ctx, pins.type_of(symbol.type, symbol.type_spec))))
        for symbol, node in instance.outputs:
            target = lower_access(node, ctx)
            pin_type = pins.type_of(symbol.type, symbol.type_spec)
            if value_type(pin_type) == value_type(target.type):
                call.outputs.append((symbol.name.upper(), target))
            else:  # a widening output: copied after the call, as ST's ``out => var`` is
                pin = Var("global", name, pin_type, (Member(symbol.name.upper()),))
                after.append(Assign(target, convert(pin, target.type), origin))
    except LoweringError as error:
        ctx.report_error(error, file="configuration")
        return []
    return [call, *after]


def _config_entry(entry, instances: dict[str, ProgramInstance], ctx: PouContext) -> None:
    """A VAR_CONFIG initial value (the instance's variable starts with it); an address is not supported yet."""
    root = entry.path
    while isinstance(root, (ast.Member, ast.Index)):
        root = root.base
    instance = instances.get(root.name.upper()) if isinstance(root, ast.Name) else None
    try:
        if instance is None:
            raise LoweringError("VAR_CONFIG sets variables of program instances: start the path with one", entry.path)
        target = lower_access(entry.path, ctx)
        if entry.address is not None:
            raise LoweringError("VAR_CONFIG addresses are not supported yet", entry.path)
        if entry.init is not None:
            value = ctx.types.initial(entry.type, entry.type_spec, entry.init)
            if isinstance(value, tuple):
                raise LoweringError(
                    "VAR_CONFIG initial values of arrays and structures are not supported yet", entry.path
                )
            instance.init.append((target, Const(value, target.type), entry.retain or instance.retain))
    except LoweringError as error:
        ctx.report_error(error, file="configuration/config")
