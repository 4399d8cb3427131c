"""A task's generated function and the configuration's initial values.

Program instances are objects among the globals (``G.v_INST``, module.py). A task is one function
``ll_task_N()`` running its instances in order with the scan's clock (``ll_now``) - their FB calls with
the parameter bindings the lowering put into ``TaskSpec.body`` - so a fault in a binding or a program stops
that task, and the debug variant steps into the programs (the function is then a generator). VAR_CONFIG
initial values are set by ``ll_config_init(warm)`` after the globals are initialised (a warm restart keeps
a RETAIN variable's value instead). ``ll_fb_init(warm)`` and ``ll_fb_exit(warm)`` run the FB_init and FB_exit
calls of every instance (ir/fb_init.py) when a program has any.
"""

from __future__ import annotations

from ...ir import nodes as ir
from ...ir import types as t
from ...ir.fb_init import exit_statements, init_statements
from .chunks import plan as chunk_plan
from .context import ModuleContext
from .scope import Scope
from .source import Source
from .statements import Statements


def task_function(index: int) -> str:
    """The generated function that runs the task at ``index`` of ``ModuleContext.tasks``."""
    return f"ll_task_{index}"


def task_body(module: ModuleContext, spec: ir.TaskSpec) -> list[ir.Stmt]:
    """The task's statements: its body, or the plain FB calls of its instances (IR built without bindings)."""
    if spec.body is not None:
        return spec.body
    calls = []
    for name in spec.programs:
        instance = module.instance(name)
        if instance is not None:
            fb = t.FbInstance(instance.pou)
            calls.append(ir.FbCall(ir.Var("global", instance.name, fb), [], [], ir.Origin(instance.pou)))
    return calls


def emit_tasks(module: ModuleContext, code: Source) -> None:
    """``ll_task_N()`` for every task, and ``ll_config_init(warm)``."""
    for index, spec in enumerate(module.tasks):
        code.piece()
        code.line(f"def {task_function(index)}():")
        with code.indent():
            code.line(f"# TASK {spec.name}: {', '.join(spec.programs) or 'no program'}")
            _statements(module, f"__TASK{index}", task_body(module, spec), code)
            if module.debug:
                code.line("return")
                code.line("yield  # a generator even when no pause point is reached")
        code.line()
    code.piece()
    code.line("def ll_config_init(warm):")
    with code.indent():
        code.line("# VAR_CONFIG initial values")
        entries = [entry for instance in module.instances for entry in instance.init]
        kept = [ir.Assign(var, value, ir.Origin("CONFIGURATION")) for var, value, retain in entries if retain]
        fresh = [ir.Assign(var, value, ir.Origin("CONFIGURATION")) for var, value, retain in entries if not retain]
        if kept:
            code.line("if not warm:")
            with code.indent():
                _statements(module, "__CONFIG", kept, code)
        _statements(module, "__CONFIG", fresh, code)
    code.line()
    _implicit(module, code, "ll_fb_init", "FB_init of every instance: bInitRetains is TRUE on a cold start", True)
    _implicit(module, code, "ll_fb_exit", "FB_exit of every instance before a restart", False)


def _implicit(module: ModuleContext, code: Source, function: str, comment: str, init: bool) -> None:
    """``function(warm)`` running the FB_init (``init``) or FB_exit calls of ir/fb_init.py; left out when a program has
    none (the engine then calls nothing)."""
    cold = init_statements(module.program, retains=True) if init else exit_statements(module.program)
    if not cold:
        return
    code.piece()
    code.line(f"def {function}(warm):")
    with code.indent():
        code.line(f"# {comment} (ir/fb_init.py)")
        if init:
            code.line("if warm:")
            with code.indent():
                _statements(module, "__INIT", init_statements(module.program, retains=False), code)
            code.line("else:")
            with code.indent():
                _statements(module, "__INIT", cold, code)
        else:
            _statements(module, "__EXIT", cold, code)
        if module.debug:
            code.line("return")
            code.line("yield  # a generator even when no pause point is reached")
    code.line()


def _statements(module: ModuleContext, name: str, statements: list[ir.Stmt], code: Source) -> None:
    """``statements`` in the global scope (a function-like scope without variables of its own)."""
    block = ir.Block(statements, ir.Origin(name))
    scope = Scope(module, ir.Pou(name, "function", [], [block]))
    body = Source()
    body.depth = code.depth
    Statements(scope, body, chunk_plan([block], chunked=False)).statements(statements)
    code.extend(body)
