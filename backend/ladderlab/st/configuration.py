"""What a project runs: its program instances, tasks, parameter bindings, VAR_ACCESS and VAR_CONFIG, checked.

Plants (issue 21) have an instance each, named after the plant, which the plant task runs; no task
may list one. Two forms (docs/st.md, "Configurations"): a project without a configuration runs its ``tasks`` (a task's
program named by its POU is one instance named after it; every PROGRAM is instantiated, those in no task
never run); a project with a ``configuration`` runs exactly the instances its resources declare
(``PROGRAM inst WITH task : Type (in := expr, out => var)``, IEC 61131-3 2.7.1, CFG-01..08). Program
instances live in the global namespace (the engine keeps them among the globals), so watch paths start with
the instance name and an instance may not share a name with a global variable.

Bindings, SINGLE variables and access paths are ST read in the global scope. VAR_ACCESS and VAR_CONFIG
paths reach every variable of an instance (``inst.x``, ``inst.fb.y``; a leading resource name is allowed),
internal ones too.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from ..iec.addresses import partial_access
from ..iec.spelling import did_you_mean
from ..model.diagnostics import Diagnostic
from ..model.project import ProgramInstance, Project, Task
from . import ast
from . import types as t
from .body import BodyChecker
from .parser import parse_config_blocks, parse_expression
from .rules import assignable_or_report
from .symbols import CheckResult, PouInfo, Symbol
from .types import ERROR, Type


@dataclass
class InstanceInfo:
    """A program instance: its PROGRAM, RETAIN, and its checked parameter bindings."""

    name: str
    pou: PouInfo
    retain: bool = False
    inputs: list[tuple[Symbol, ast.Expr]] = field(default_factory=list)  # VAR_INPUT <- expression, before a run
    outputs: list[tuple[Symbol, ast.Expr]] = field(default_factory=list)  # VAR_OUTPUT -> variable, after a run


@dataclass
class TaskInfo:
    name: str
    interval: str | None  # TIME literal text (the model checked its form), None: SINGLE only
    priority: int
    single: ast.Expr | None  # a checked BOOL variable
    instances: list[str]  # upper-case instance names, in run order


@dataclass
class AccessInfo:
    """``VAR_ACCESS name : path : type READ_ONLY | READ_WRITE`` (CFG-08)."""

    name: str
    path: ast.Expr
    type: Type
    read_only: bool


@dataclass
class ConfigEntry:
    """``VAR_CONFIG path [AT address] : type [:= init]``: an instance variable's initial value or address."""

    path: ast.Expr
    type: Type
    type_spec: ast.TypeSpec
    address: str | None
    init: ast.Init | None
    retain: bool  # the variable keeps its value on a warm restart: the initial value then does not apply


@dataclass
class ConfigurationInfo:
    name: str | None  # the CONFIGURATION's name; None: the project's own tasks
    instances: dict[str, InstanceInfo] = field(default_factory=dict)  # upper-case name -> instance
    tasks: list[TaskInfo] = field(default_factory=list)
    unscheduled: list[str] = field(default_factory=list)  # instances of no task
    plants: list[str] = field(default_factory=list)  # the plants' instances (named after them): the plant task
    access: dict[str, AccessInfo] = field(default_factory=dict)
    entries: list[ConfigEntry] = field(default_factory=list)


def configuration_globals(project: Project) -> list[tuple[str, str]]:
    """(VAR_GLOBAL text, diagnostics file) of the configuration and of each of its resources."""
    config = project.configuration
    if config is None:
        return []
    texts = [(config.globals, "configuration/globals")]
    for index, resource in enumerate(config.resources):
        texts.append((resource.globals, f"configuration/{resource.name or f'resource{index}'}/globals"))
    return texts


def check_configuration(
    result: CheckResult, project: Project, resolve: Callable[[ast.TypeSpec, BodyChecker], Type], reporter: Callable
) -> ConfigurationInfo:
    """The instances and tasks ``project`` runs, every binding, SINGLE and path checked (diagnostics into
    ``result``); ``resolve`` resolves a type specification, ``reporter(file)`` reports in a text."""
    return _ConfigurationChecker(result, project, resolve, reporter).run()


class _ConfigurationChecker:
    def __init__(self, result: CheckResult, project: Project, resolve: Callable, reporter: Callable):
        self.result, self.project, self.resolve, self.reporter = result, project, resolve, reporter
        config = project.configuration
        self.info = ConfigurationInfo(config.name if config is not None else None)
        self.file = "configuration" if config is not None else "tasks"

    def run(self) -> ConfigurationInfo:
        config = self.project.configuration
        for pou in self.result.pous.values():  # every plant has its instance, first: no task may run it
            if pou.plant and self._instance(pou.name, ProgramInstance(name=pou.name, type=pou.name), "$.pous"):
                self.info.plants.append(pou.name.upper())
        if config is None:
            self._tasks(self.project.tasks, "$.tasks")
            for pou in self.result.pous.values():  # every PROGRAM has its instance (those in no task never run)
                if pou.kind == "PROGRAM" and pou.name.upper() not in self.info.instances:
                    self._instance(pou.name, ProgramInstance(name=pou.name, type=pou.name), "$.pous")
                    self.info.unscheduled.append(pou.name.upper())
            return self.info
        for r, resource in enumerate(config.resources):
            where = f"$.configuration.resources[{r}]"
            self._tasks(resource.tasks, f"{where}.tasks")
            for j, instance in enumerate(resource.programs):
                if self._instance(instance.name, instance, f"{where}.programs[{j}]") is not None:
                    self.info.unscheduled.append(instance.name.upper())
        self._access_and_config(config.access, "configuration/access")
        self._access_and_config(config.config, "configuration/config")
        return self.info

    # ------------------------------------------------------------ tasks and instances
    def _tasks(self, tasks: list[Task], where: str) -> None:
        for i, task in enumerate(tasks):
            at = f"{where}[{i}]"
            names = []
            for j, program in enumerate(task.programs):
                instance = ProgramInstance(name=program, type=program) if isinstance(program, str) else program
                if self._instance(instance.name, instance, f"{at}.programs[{j}]") is not None:
                    names.append(instance.name.upper())
            single = self._single(task.single, f"{at}.single") if task.single else None
            self.info.tasks.append(TaskInfo(task.name, task.interval, task.priority, single, names))

    def _instance(self, name: str, instance: ProgramInstance, where: str) -> InstanceInfo | None:
        """Register an instance (the model's validation reported unknown and non-PROGRAM types, and names used
        twice); None when it cannot run."""
        pou = self.result.pou(instance.type)
        if pou is None or pou.kind != "PROGRAM" or name.upper() in self.info.instances:
            return None
        clash = self.result.globals.get(name.upper())
        if clash is not None and self.project.configuration is not None:  # (else reported at the global, ST-08)
            self._report(
                "ST-DUPLICATE",
                f"'{name}' names a program instance and a global variable: instances and globals share one namespace "
                "(ST-08)",
                where,
            )
        info = InstanceInfo(name, pou, instance.retain == "RETAIN")
        self.info.instances[name.upper()] = info
        checker = self._checker()
        for symbol, node, at in self._bindings(pou, instance.inputs, "VAR_INPUT", f"{where}.inputs"):
            value = checker.at(at).expr(node, symbol.type)
            if value is not ERROR:
                assignable_or_report(checker.at(at), symbol.type, value, node, f"input {symbol.name} of {name}")
            info.inputs.append((symbol, node))
        for symbol, node, at in self._bindings(pou, instance.outputs, "VAR_OUTPUT", f"{where}.outputs"):
            target = checker.at(at).target(node)
            if target is not ERROR and t.assignable(target, symbol.type) == "error":
                self._report(
                    "ST-TYPE-MISMATCH",
                    f"output {symbol.name} of {name} is {symbol.type} and cannot be stored in {target}",
                    at,
                )
            info.outputs.append((symbol, node))
        return info

    def _bindings(
        self, pou: PouInfo, texts: dict[str, str], kind: str, where: str
    ) -> list[tuple[Symbol, ast.Expr, str]]:
        """The parameters of ``kind`` bound in ``texts`` (name -> ST text) with their parsed expressions and where
        each is written; an unknown parameter or a text that does not parse is reported and left out."""
        found = []
        for param, text in texts.items():
            symbol = pou.symbols.get(param.upper())
            at = f"{where}.{param}"
            if symbol is None or symbol.var_class != kind:
                names = [s.name for s in pou.parameters(kind)]
                message = f"the program {pou.name} has no {kind} '{param}'" + did_you_mean(param, names)
                self._report("ST-CALL-ARGS", message, at)
                continue
            node = self._expression(text, at)
            if node is not None:
                found.append((symbol, node, at))
        return found

    def _single(self, text: str, where: str) -> ast.Expr | None:
        """A task's SINGLE: a BOOL global variable or direct address (read before every scan)."""
        node = self._expression(text, where)
        if node is None:
            return None
        ty = self._checker().at(where).expr(node, t.BOOL)
        if ty is ERROR:
            return None
        if not isinstance(node, (ast.Name, ast.DirectAddr, ast.Member, ast.Index)) or not t.same(ty, t.BOOL):
            self._report("ST-TYPE-MISMATCH", f"SINGLE needs a BOOL variable, not {text.strip()!r} ({ty})", where)
            return None
        return node

    # ------------------------------------------------------------ VAR_ACCESS and VAR_CONFIG
    def _access_and_config(self, text: str, file: str) -> None:
        if not text.strip():
            return
        parsed = parse_config_blocks(text, file=file)
        self.result.diagnostics += parsed.diagnostics
        if parsed.ast is None:
            return
        checker = _PathChecker(self, file)
        for block in parsed.ast:
            if isinstance(block, ast.AccessBlock) != file.endswith("access"):
                what = "VAR_ACCESS" if isinstance(block, ast.AccessBlock) else "VAR_CONFIG"
                checker.report("ST-DECL", f"{what} blocks belong in the configuration's {what.lower()[4:]} text", block)
            for decl in block.decls:
                if isinstance(decl, ast.AccessDecl):
                    self._access(checker, decl)
                else:
                    self._config_entry(checker, decl)

    def _access(self, checker: _PathChecker, decl: ast.AccessDecl) -> None:
        path = checker.strip_resource(decl.path)
        ty = checker.expr(path)
        declared = self.resolve(decl.type, checker)
        if ty is not ERROR and declared is not ERROR and not t.same(ty, declared):
            checker.report(
                "ST-TYPE-MISMATCH", f"access path {decl.name} is declared {declared}, its variable is {ty}", decl
            )
        if decl.name.upper() in self.info.access:
            checker.report("ST-DUPLICATE", f"access path '{decl.name}' is declared twice", decl)
        elif ty is not ERROR:
            read_only = decl.direction != "READ_WRITE"
            self.info.access[decl.name.upper()] = AccessInfo(decl.name, path, ty, read_only)

    def _config_entry(self, checker: _PathChecker, decl: ast.ConfigDecl) -> None:
        path = checker.strip_resource(decl.path)
        ty = checker.expr(path)
        declared = self.resolve(decl.type, checker)
        if ty is ERROR or declared is ERROR:
            return
        if not t.same(ty, declared):
            checker.report("ST-TYPE-MISMATCH", f"VAR_CONFIG declares {declared}, the variable is {ty}", decl)
            return
        if decl.init is not None:
            value = (
                checker.expr(decl.init, declared)
                if not isinstance(decl.init, (ast.ArrayInit, ast.StructInit))
                else None
            )
            if value is not None and value is not ERROR:
                assignable_or_report(checker, declared, value, decl.init, "init")
        root = _root_symbol(path)
        self.info.entries.append(
            ConfigEntry(path, ty, decl.type, decl.address, decl.init, root is not None and root.retain)
        )

    # ------------------------------------------------------------ helpers
    def _checker(self) -> _ScopeChecker:
        return _ScopeChecker(self.result, self)

    def _expression(self, text: str, where: str) -> ast.Expr | None:
        parsed = parse_expression(text)
        for d in parsed.diagnostics:
            self.result.diagnostics.append(d.model_copy(update={"file": self.file, "json_path": where}))
        return parsed.ast if parsed.ok else None

    def _report(self, code: str, message: str, where: str, severity: str = "error") -> None:
        self.result.diagnostics.append(
            Diagnostic(severity=severity, code=code, message=message, file=self.file, json_path=where)
        )


class _ScopeChecker(BodyChecker):
    """ST in the global scope (bindings, SINGLE): globals and direct addresses; reports at a JSON path."""

    def __init__(self, result: CheckResult, owner: _ConfigurationChecker, where: str | None = None):
        self.located = _Located(owner, where)
        super().__init__(result, None, self.located)

    def at(self, where: str) -> _ScopeChecker:
        self.located.where = where
        return self


class _Located:
    """A ``_ScopeChecker``'s reports, at the JSON path it checks now. (An object of its own: the checker's bound
    method was a reference cycle that kept the project's check alive until a collection; issue 27.)"""

    def __init__(self, owner: _ConfigurationChecker, where: str | None):
        self.owner, self.where = owner, where

    def __call__(self, code: str, message: str, node: Any, severity: str = "error") -> None:
        self.owner._report(code, message, self.where or "", severity)


class _PathChecker(BodyChecker):
    """Access paths and VAR_CONFIG entries: program instances by name, any variable inside them."""

    def __init__(self, owner: _ConfigurationChecker, file: str):
        super().__init__(owner.result, None, owner.reporter(file))
        self.owner = owner
        self.resources = {
            (r.name or "").upper()
            for r in (owner.project.configuration.resources if owner.project.configuration else [])
        }

    def lookup(self, name: str) -> Symbol | None:
        instance = self.owner.info.instances.get(name.upper())
        if instance is not None:
            fb = t.FbType(instance.pou.name, pou=instance.pou)
            return Symbol(instance.name, "VAR_GLOBAL", fb, ast.NamedType(instance.pou.name), retain=instance.retain)
        return super().lookup(name)

    def _fb_member(self, node: ast.Member, base: t.FbType) -> Type:
        if base.pou is None:
            return super()._fb_member(node, base)
        symbol = base.pou.symbols.get(node.name.upper())  # internal variables too (CFG-08)
        if symbol is None:
            names = [s.name for s in base.pou.symbols.values()]
            self.report(
                "ST-UNKNOWN-MEMBER", f"{base.name} has no variable '{node.name}'" + did_you_mean(node.name, names), node
            )
            return ERROR
        node.ref = symbol
        return symbol.type

    def strip_resource(self, path: ast.Expr) -> ast.Expr:
        """``resource.inst.x`` -> ``inst.x`` (IEC access paths may start with the resource)."""
        chain = []
        node = path
        while isinstance(node, (ast.Member, ast.Index)):
            chain.append(node)
            node = node.base
        if isinstance(node, ast.Name) and node.name.upper() in self.resources and chain:
            first = chain[-1]
            if isinstance(first, ast.Member) and partial_access(first.name) is None:
                replacement = ast.Name(first.name, first.span)
                if len(chain) == 1:
                    return replacement
                chain[-2].base = replacement
        return path


def _root_symbol(path: ast.Expr) -> Symbol | None:
    """The declared variable a path ends in, for its RETAIN flag (``inst.x`` -> x)."""
    ref = getattr(path, "ref", None)
    return ref if isinstance(ref, Symbol) else None
