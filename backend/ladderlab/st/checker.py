"""Semantic checks of a whole project: ``check_project`` and ``check_operand``.

Order: parse every text, register the POUs, resolve user TYPEs, the globals and
each POU's declarations (LD/FBD POUs too, so ST can call them), then check the
ST bodies and the call graph. The result is the resolved program the IR lowering
consumes (``CheckResult``); problems are ``Diagnostic``s, never exceptions.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from functools import partial
from typing import Any

from ..iec import stdlib
from ..iec.addresses import incomplete, parse_address, type_problem
from ..iec.spelling import did_you_mean
from ..iec.values import article
from ..model.diagnostics import Diagnostic
from ..model.names import MAX_NAME_LENGTH, pou_name_problem
from ..model.project import Project
from . import ast
from . import types as t
from .body import BodyChecker
from .call_after_init import check_call_after_init
from .configuration import check_configuration, configuration_globals
from .fb_init import (
    check_fb_init_methods,
    check_instance_args,
    check_no_args,
    check_struct_members,
    instance_spec,
    project_blocks,
)
from .gvls import clashing_name, gvl_texts, register_lists, share, shared_use, twice_hint
from .il_check import check_il_body
from .il_parser import IlBody, parse_il
from .inheritance import abstract_instance, check_overrides, link_bases
from .interfaces import check_implementations, declare_interfaces, link_implements, register_interfaces
from .libraries import with_libraries
from .methods import check_method_body, check_method_recursion, declare_methods
from .monitoring import check_monitoring
from .parser import (
    keywords,
    parse_declarations,
    parse_expression,
    parse_source,
    parse_statements,
    parse_type,
    reserved_words,
)
from .registers import check_registers
from .rules import assignable_or_report, check_init, constant_value
from .sfc import check_actions, declare_implicit, parse_actions
from .symbols import CheckResult, PouInfo, Symbol, TypeDef
from .types import ERROR, Type

_KIND = {"program": "PROGRAM", "function_block": "FUNCTION_BLOCK", "function": "FUNCTION", "plant": "PROGRAM"}
# Table 3.11 (VAR-11): which variable classes each POU kind may declare.
_ALLOWED = {
    "PROGRAM": {"VAR", "VAR_TEMP", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_EXTERNAL"},
    "FUNCTION_BLOCK": {"VAR", "VAR_TEMP", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_EXTERNAL"},
    "FUNCTION": {"VAR", "VAR_TEMP", "VAR_INPUT", "VAR_IN_OUT", "VAR_EXTERNAL"},
}
_MAX_ARRAY_DIMENSIONS = 4


class Reporter:
    """Creates located diagnostics for one text (``file``) of one POU."""

    def __init__(self, sink: list[Diagnostic], file: str | None, pou: str | None):
        self.sink, self.file, self.pou = sink, file, pou

    def __call__(self, code: str, message: str, node: Any, severity: str = "error") -> None:
        span = getattr(node, "span", None) or ast.NO_SPAN
        self.sink.append(
            Diagnostic(
                severity=severity,
                code=code,
                message=message,
                file=self.file,
                pou=self.pou,
                line=span.line or None,
                column=span.column or None,
                end_line=span.end_line or None,
                end_column=span.end_column or None,
            )
        )


#: Type specifications that may carry an instance's FB_init arguments (st/fb_init.py)
_MAY_HOLD_ARGS = (ast.EnumType, ast.SizedType, ast.ArrayType, ast.InstanceArgsType, ast.PositionalArgsType)


class ProjectChecker:
    def __init__(self, project: Project):
        self.project = project
        self.result = CheckResult()
        self.type_decls: dict[str, ast.TypeDecl] = {}
        #: the TYPEs being resolved, outermost first; a STRUCT among them is in ``_pending`` (filled in as its members
        #: resolve) and ``_pointers`` holds the depth of ``_resolving`` at each POINTER TO / REF_TO entered
        self._resolving: list[str] = []
        self._pending: dict[str, t.StructType] = {}
        self._pointers: list[int] = []
        #: declared instances with FB_init arguments, checked once every method is declared (st/fb_init.py)
        self._written_args: list[tuple[Symbol, list | None, Any, BodyChecker, PouInfo | None]] = []
        self._args_checked = False
        #: globals with an initial value, checked once every POU's variables are declared
        self._global_inits: list[tuple[Symbol, BodyChecker]] = []

    # ------------------------------------------------------------ driver
    def run(self) -> CheckResult:
        types = self._parse(_parse_types, self.project.types, "types", None)
        texts = [(self.project.globals, "globals"), *gvl_texts(self.project), *configuration_globals(self.project)]
        globals_ = [  # the project's, each GVL's, the configuration's and each resource's VAR_GLOBAL blocks, with
            (block, file)  # their file
            for text, file in texts
            for block in self._parse(parse_declarations, text, file, None) or []
        ]
        self._gvl_files = register_lists(self.result, self.project)
        declarations, bodies, actions = {}, {}, {}
        for pou in self.project.pous:
            declarations[pou.name] = (
                self._parse(parse_declarations, pou.declarations, f"{pou.name}/declarations", pou.name) or []
            )
            if pou.language == "st":
                bodies[pou.name] = self._parse(parse_statements, pou.body, f"{pou.name}/body", pou.name)
            elif pou.language == "sfc":
                actions[pou.name] = parse_actions(pou)
                for parsed in actions[pou.name].values():
                    self.result.diagnostics += parsed.diagnostics
            elif pou.language == "il":
                parsed = parse_il(pou.body, file=f"{pou.name}/body", pou=pou.name)
                self.result.diagnostics += parsed.diagnostics
                bodies[pou.name] = parsed.body
        self._register_pous()
        interfaces = [item for item in types or [] if isinstance(item, ast.InterfaceDecl)]
        register_interfaces(self, interfaces)
        constants = [(b, f) for b, f in globals_ if b.constant and all(_elementary_decl(d) for d in b.decls)]
        self._declare_globals(constants)  # first, so array bounds in TYPEs may name them (TYP-22)
        self._register_types([item for item in types or [] if isinstance(item, ast.TypeBlock)])
        declare_interfaces(self, interfaces)
        self._declare_globals([(b, f) for b, f in globals_ if (b, f) not in constants])
        for file, gvl in self._gvl_files.items():
            clash = clashing_name(self.result, gvl)
            if clash is not None:
                message = f"the global variable list {gvl.name} has the name of {clash}: rename one"
                self._reporter(file, None)("ST-DUPLICATE", message, None)
        for pou in self.project.pous:
            self._declare_pou(pou, declarations[pou.name])
        for pou in self.project.pous:
            info = self.result.pous.get(pou.name.upper())
            if pou.language == "sfc" and info is not None and info.name == pou.name:
                declare_implicit(pou, info, self.result.diagnostics)
        link_bases(self, self.project)
        link_implements(self, self.project)
        methods = []
        for pou in self.project.pous:
            info = self.result.pous.get(pou.name.upper())
            if (pou.methods or pou.properties or pou.actions) and info is not None and info.name == pou.name:
                methods += declare_methods(self, info, pou.methods, pou.properties, pou.actions)
        check_call_after_init(self.result, self.project)
        check_monitoring(self.result, self.project)
        blocks = [info for info in self.result.pous.values() if info.kind == "FUNCTION_BLOCK"]
        check_overrides(self, blocks)
        check_implementations(self, blocks)
        check_fb_init_methods(self, blocks)
        check_struct_members(self)
        for symbol, checker in self._global_inits:
            check_init(checker, symbol.type, symbol.init)
        for pou in self.project.pous:
            self._check_initial_values(pou)
        for entry in self._written_args:  # once the FB_init methods are declared
            self._check_written(*entry)
        self._args_checked = True
        for info, method in methods:
            check_method_body(self, info, method)
        for pou in self.project.pous:
            info = self.result.pous.get(pou.name.upper())
            if info is not None and info.language in ("st", "il") and bodies.get(pou.name) is not None:
                self._check_body(info, bodies[pou.name])
            if info is not None and info.name == pou.name and pou.name in actions:
                check_actions(
                    self.result, lambda file, info=info: self._reporter(file, info.name), pou, info, actions[pou.name]
                )
        check_method_recursion(self, [info for info, _ in methods], blocks)  # the bodies' calls counted too
        self._check_recursion()
        self.result.configuration = check_configuration(self.result, self.project, self.resolve, self._reporter_for)
        return self.result

    def _check_written(
        self, symbol: Symbol, written: list | None, at: Any, checker: BodyChecker, owner: PouInfo | None, late=False
    ) -> None:
        """A declared variable's FB_init arguments, or their absence (st/fb_init.py). ``late``: a test file's
        variable, whose instance LadderLab makes without running FB_init."""
        if owner is not None and owner.kind == "FUNCTION":
            return  # a function or method holds no instance at all (ST-57, _check_decl)
        if written is None:
            check_no_args(checker, symbol, late)
            return
        if late or symbol.var_class in ("VAR_IN_OUT", "VAR_EXTERNAL"):
            where = "a test's variable" if late else article(symbol.var_class)
            checker.report(
                "ST-DECL",
                "FB_init arguments belong where an instance is made (a variable of a program or function block, or "
                f"a global), not on {where}",
                at,
            )
            return
        check_instance_args(checker, symbol, written, at)

    def _reporter_for(self, file: str) -> Reporter:
        return self._reporter(file, None)

    def _parse(self, parse, text: str, file: str, pou: str | None):
        result = parse(text, file=file, pou=pou)
        self.result.diagnostics += result.diagnostics
        return result.ast

    def _reporter(self, file: str | None, pou: str | None) -> Reporter:
        return Reporter(self.result.diagnostics, file, pou)

    # ------------------------------------------------------------ POUs and types
    def _register_pous(self) -> None:
        for pou in self.project.pous:
            upper = pou.name.upper()
            where = Reporter(self.result.diagnostics, f"{pou.name}/declarations", pou.name)
            if upper in self.result.pous:
                where("ST-DUPLICATE", f"there is already a POU called '{pou.name}'", None)
                continue
            if (stdlib.function(upper) or stdlib.function_block(upper)) and not _redefinable(upper):
                where(
                    "ST-DUPLICATE",
                    f"'{pou.name}' is a standard function or function block name and cannot be redefined",
                    None,
                )
            if upper in keywords():
                where("ST-NAME", f"'{pou.name}' is a keyword and cannot name a POU (KW-02)", None)
            info = self.result.pous[upper] = PouInfo(pou.name, _KIND[pou.kind], pou.language, None)
            info.plant = pou.kind == "plant"
            info.abstract, info.final = pou.abstract, pou.final
            if not isinstance(pou.body, str):  # LD boxes and FBD blocks: edges of the call graph (POU-02)
                info.calls |= pou.body.calls()

    def _register_types(self, blocks: list[ast.TypeBlock]) -> None:
        report = self._reporter("types", None)
        for block in blocks:
            for decl in block.decls:
                upper = decl.name.upper()
                if (
                    upper in self.type_decls
                    or t.elementary(upper)
                    or upper in self.result.pous
                    or stdlib.function_block(upper)
                ):
                    report("ST-DUPLICATE", f"the type name '{decl.name}' is already in use", decl)
                    continue
                self.type_decls[upper] = decl
                check_identifier(decl.name, decl, report)
        for upper in self.type_decls:
            self._typedef(upper)
        checker = BodyChecker(self.result, None, report)
        for typedef in self.result.types.values():
            if typedef.init is not None:
                check_init(checker, typedef.type, typedef.init)

    def _typedef(self, upper: str) -> TypeDef | None:
        if upper in self.result.types:
            return self.result.types[upper]
        decl = self.type_decls.get(upper)
        if decl is None:
            return None
        if upper in self._resolving:  # an alias cycle's initial value: the cycle is reported where it is named
            return None
        report = self._reporter("types", None)
        self._resolving.append(upper)
        resolved = self.resolve(decl.type, BodyChecker(self.result, None, report), decl.name)
        self._resolving.pop()
        self._pending.pop(upper, None)
        if decl.pack_mode is not None:
            _pack(decl, resolved, report)
        init = decl.init
        if init is None and isinstance(decl.type, ast.NamedType):  # THomeTemp : TRoomTemp inherits 20.0 (TYP-11)
            parent = self._typedef(decl.type.name.upper())
            init = parent.init if parent is not None else None
        typedef = TypeDef(decl.name, resolved, init, decl)
        self.result.types[upper] = typedef
        return typedef

    def resolve(self, spec: ast.TypeSpec, checker: BodyChecker, name: str = "") -> Type:
        """Type specification -> resolved type, reporting unknown names and bad sizes."""
        report = checker.report
        if isinstance(spec, ast.NamedType):
            return self._named(spec, report)
        if isinstance(spec, _MAY_HOLD_ARGS):
            plain, written = instance_spec(spec, project_blocks(self.result.pous))
            if written is not None:  # ``TYPE T : F(n := 1)``, a STRUCT's member: not an instance variable's declaration
                report("ST-DECL", "FB_init arguments belong to the declaration of an instance variable", spec)
                return self.resolve(plain, checker, name)
        if isinstance(spec, ast.SizedType):
            base = t.elementary(spec.name)
            length = constant_value(checker, spec.size)
            if not isinstance(base, t.StringType):
                report("ST-UNKNOWN-TYPE", f"only STRING and WSTRING take a length, not '{spec.name}'", spec)
                return ERROR
            if not isinstance(length, int) or length < 1:
                report("ST-CONST-EXPR", "a string length must be a positive constant", spec.size)
                return base
            return t.StringType(base.wide, length)
        if isinstance(spec, ast.SubrangeType):
            base = t.elementary(spec.base)
            if base is None or not t.in_family(base, "ANY_INT"):
                report("ST-UNKNOWN-TYPE", f"a subrange needs an integer base type, not '{spec.base}'", spec)
                return ERROR
            return base
        if isinstance(spec, ast.ArrayType):
            return self._array(spec, checker)
        if isinstance(spec, ast.PointerType):
            self._pointers.append(len(self._resolving))
            target = self.resolve(spec.target, checker)
            self._pointers.pop()
            return t.PointerType(target, spec.kind == "REFERENCE TO")
        if isinstance(spec, ast.EnumType):
            return self._enum(spec, checker, name or "enumeration")
        struct = t.StructType(name or "STRUCT")
        if name and self._resolving and self._resolving[-1] == name.upper():
            self._pending[name.upper()] = struct
        for member in spec.members:
            member_type = self.resolve(member.type, checker)
            for decl_name in member.names:
                if decl_name.name is None:
                    continue
                if decl_name.name.upper() in struct.fields:
                    report("ST-DUPLICATE", f"field '{decl_name.name}' is declared twice", decl_name)
                struct.fields[decl_name.name.upper()] = (decl_name.name, member_type)
        return struct

    def _named(self, spec: ast.NamedType, report) -> Type:
        upper = spec.name.upper()
        builtin = t.elementary(upper)
        if builtin is not None:
            return builtin
        if upper in self._resolving:
            return self._being_resolved(upper, spec, report)
        typedef = self._typedef(upper)
        if typedef is not None:
            return typedef.type
        if upper in self.result.interfaces:
            return t.InterfaceType(self.result.interfaces[upper].name, self.result.interfaces[upper])
        if upper in self.result.pous and self.result.pous[upper].kind != "FUNCTION":
            return t.FbType(self.result.pous[upper].name, pou=self.result.pous[upper])
        std = stdlib.function_block(upper)
        if std is not None:
            return t.FbType(std.name, std=std)
        if upper == t.EXPRESSION_RESULT:
            return t.expression_result()
        if upper.startswith("ANY"):
            report("ST-UNKNOWN-TYPE", f"'{spec.name}' is a generic type: it is only used by standard functions", spec)
            return ERROR
        known = [
            *(d.name for d in self.type_decls.values()),
            *t.ELEMENTARY,
            "STRING",
            *stdlib.FUNCTION_BLOCKS,
            *(p.name for p in self.result.pous.values() if p.kind != "FUNCTION"),
        ]
        report("ST-UNKNOWN-TYPE", f"unknown type '{spec.name}'" + did_you_mean(spec.name, known), spec)
        return ERROR

    def _being_resolved(self, upper: str, spec: ast.NamedType, report) -> Type:
        """A TYPE named inside its own definition: a STRUCT reached through a POINTER TO / REF_TO / REFERENCE TO
        since it began (a linked list's ``next : POINTER TO Node``, or two STRUCTs pointing at each other) is
        that STRUCT; anything else would contain itself (ST-RECURSION)."""
        depth = self._resolving.index(upper)
        if upper in self._pending and any(mark > depth for mark in self._pointers):
            return self._pending[upper]
        name = self.type_decls[upper].name
        report("ST-RECURSION", f"the type '{name}' is defined in terms of itself", spec)
        return ERROR

    def _array(self, spec: ast.ArrayType, checker: BodyChecker) -> Type:
        dims: list[tuple[int, int] | None] = []
        for bounds in spec.ranges:
            if bounds is None:
                dims.append(None)
                continue
            low, high = (constant_value(checker, b) for b in bounds)
            if not isinstance(low, int) or not isinstance(high, int):
                checker.report("ST-CONST-EXPR", "array bounds must be integer constants", bounds[0])
                return ERROR
            if low > high:
                checker.report("ST-INDEX", f"array range {low}..{high} is empty", bounds[0])
            dims.append((low, high))
        if len(dims) > _MAX_ARRAY_DIMENSIONS:
            checker.report("ST-INDEX", f"an array has at most {_MAX_ARRAY_DIMENSIONS} dimensions (TYP-21)", spec)
        return t.ArrayType(tuple(dims), self.resolve(spec.element, checker))

    def _enum(self, spec: ast.EnumType, checker: BodyChecker, name: str) -> Type:
        enum = t.EnumType(name)
        base = t.elementary(spec.base) if spec.base else None
        # IEC ed. 3 allows the integers; CODESYS also BYTE, WORD, DWORD and LWORD (its "Enumeration" page)
        integer = base is not None and (t.in_family(base, "ANY_INT") or base.category == "bits")
        if spec.base and not integer:
            message = f"an enumeration's base type must be an integer or BYTE/WORD/DWORD/LWORD, not {spec.base}"
            checker.report("ST-TYPE-MISMATCH", message, spec)
            base = None
        if base is not None:
            enum.base = base.name
        following = 0
        for value in spec.values:
            if value.value is not None:
                number = constant_value(checker, value.value)
                if not isinstance(number, int):
                    checker.report("ST-CONST-EXPR", "an enumeration value must be an integer constant", value.value)
                    number = following
                elif base is not None and not t.literal_fits(base, number):
                    checker.report("ST-RANGE", f"{number} does not fit the enumeration's base type {base}", value.value)
                following = number
            if value.name.upper() in enum.values:
                checker.report("ST-DUPLICATE", f"'{value.name}' appears twice in the enumeration", value)
            enum.values[value.name.upper()] = (value.name, following)
            following += 1
        return enum

    # ------------------------------------------------------------ variables
    def _declare_globals(self, blocks: list[tuple[ast.VarBlock, str]]) -> None:
        """VAR_GLOBAL blocks (with the file each is in: the project's globals, a configuration's or a resource's)."""
        for block, file in blocks:
            report = self._reporter(file, None)
            checker = BodyChecker(self.result, None, report)
            if block.kind != "VAR_GLOBAL":
                what = "it refers to a global variable from inside a POU" if block.kind == "VAR_EXTERNAL" else ""
                report(
                    "ST-DECL",
                    f"only VAR_GLOBAL blocks belong in the global variables, not {block.kind}"
                    + (f" ({what})" if what else ""),
                    block,
                )
                continue
            gvl = self._gvl_files.get(file)
            table = self.result.globals if gvl is None else gvl.members  # a list's: other lists may share a name
            before = set(table)
            twice = partial(twice_hint, self.result, in_list=gvl is not None)
            self.declare_block(block, table, checker, None, twice=twice if gvl is None else None)
            for key in [key for key in table if key not in before]:  # (in declaration order)
                symbol = table[key]
                if gvl is None and key in self.result.shared:  # a configuration's global named like lists' ones
                    del table[key]
                    checker.report("ST-DUPLICATE", f"'{symbol.name}' is declared twice" + twice(key), symbol)
                    continue
                self._check_global(symbol, checker)
                if gvl is not None and not share(self.result, gvl, key, symbol):
                    del table[key]
                    checker.report("ST-DUPLICATE", f"'{symbol.name}' is declared twice" + twice(key), symbol)

    def _check_global(self, symbol: Symbol, checker: BodyChecker) -> None:
        program = self.result.pous.get(symbol.name.upper())
        if program is not None and program.kind == "PROGRAM" and self.project.configuration is None:
            checker.report(  # ST-08: both name an instance of the resource (a configuration names its instances)
                "ST-DUPLICATE",
                f"'{symbol.name}' is the name of the program {program.name}: a global variable "
                "and a program instance cannot share a name",
                symbol,
            )
        if symbol.init is not None:  # once the POUs are declared: an FB instance's initialiser names its variables
            self._global_inits.append((symbol, checker))

    def _declare_pou(self, pou, blocks: list[ast.VarBlock]) -> None:
        info = self.result.pous.get(pou.name.upper())
        if info is None or info.name != pou.name:
            return
        report = self._reporter(f"{pou.name}/declarations", pou.name)
        checker = BodyChecker(self.result, info, report)
        if pou.return_type:
            self._declare_return_type(pou, info)
        elif info.kind == "FUNCTION":
            report("ST-DECL", f"the function {pou.name} needs a return type", None)
        checker.constants_ahead = self._constants(blocks, info)
        for block in blocks:
            if block.kind not in _ALLOWED[info.kind]:
                report(
                    "ST-DECL", f"{block.kind} is not allowed in a {info.kind.lower().replace('_', ' ')} (VAR-11)", block
                )
            self.declare_block(block, info.symbols, checker, info)
        for symbol in info.symbols.values():
            if isinstance(symbol.type, t.FbType) and symbol.type.pou is not None:
                info.calls.add(symbol.type.pou.name.upper())

    def _constants(self, blocks: list[ast.VarBlock], info: PouInfo) -> dict[str, Symbol]:
        """The POU's ``VAR CONSTANT`` variables, declared aside (their diagnostics come when they are declared in
        order), for the declarations that use one declared further down."""
        constants: dict[str, Symbol] = {}
        silent = BodyChecker(self.result, info, lambda *args, **kwargs: None)
        for block in blocks:
            if block.constant and block.kind == "VAR":
                self.declare_block(block, constants, silent, info, record=False)
        return constants

    def _declare_return_type(self, pou, info: PouInfo) -> None:
        """A function's result type: any type specification (``STRING[20]``, ``INT (0..100)``, a TYPE's name);
        its diagnostics are located in the ``<POU>/return_type`` text."""
        file = f"{pou.name}/return_type"
        parsed = parse_type(pou.return_type, file=file, pou=pou.name)
        self.result.diagnostics += parsed.diagnostics
        report = self._reporter(file, pou.name)
        if parsed.ast is None:
            info.return_type = ERROR
            return
        info.return_spec = parsed.ast
        info.return_type = self.resolve(parsed.ast, BodyChecker(self.result, info, report))
        if isinstance(info.return_type, t.FbType):
            report("ST-DECL", f"a function cannot return a function block instance ({info.return_type.name})", None)
            info.return_type = ERROR

    def _check_initial_values(self, pou) -> None:
        """After every POU is declared, so an FB instance may be initialised (``f : Fb := (n := 4)``) whatever
        the order of the POUs."""
        info = self.result.pous.get(pou.name.upper())
        if info is None or info.name != pou.name:
            return
        checker = BodyChecker(self.result, info, self._reporter(f"{pou.name}/declarations", pou.name))
        for symbol in info.symbols.values():
            if symbol.init is not None:
                check_init(checker, symbol.type, symbol.init)

    def declare_block(
        self,
        block: ast.VarBlock,
        table: dict[str, Symbol],
        checker: BodyChecker,
        pou: PouInfo | None,
        record: bool = True,
        twice: Callable[[str], str] | None = None,
    ) -> None:
        """Declare ``block``'s variables in ``table``; ``record``: check their FB_init arguments (st/fb_init.py);
        ``twice(name)`` adds to the message of a name declared twice."""
        report = checker.report
        constant, retain, owner = block.constant, block.retain, pou.name if pou else None  # (once, not per name)
        blocks = project_blocks(self.result.pous)
        for decl in block.decls:
            spec = decl.type
            if type(spec) is ast.NamedType:  # most declarations: a type by its name (no FB_init arguments in it)
                written, ty = None, self._named(spec, report)
            else:
                spec, written = instance_spec(spec, blocks)
                ty = self.resolve(spec, checker)
            plain = _nothing_to_check(ty, decl, written, constant)
            if not plain:
                self._check_decl(block, decl, ty, pou, report)
            init = decl.init
            if init is None and isinstance(spec, ast.NamedType):
                typedef = self.result.types.get(spec.name.upper())
                init = typedef.init if typedef is not None else None
            for name in decl.names:
                if name.name:
                    check_identifier(name.name, name, report)
                if name.address:
                    self._check_address(block, name, ty, pou, report)
                key = (name.name or name.address or "").upper()
                if key in table:  # (its text: ``written`` is the declaration's FB_init arguments, for every name)
                    text = name.name or name.address or ""
                    report("ST-DUPLICATE", f"'{text}' is declared twice" + (twice(key) if twice else ""), name)
                    continue
                symbol = Symbol(
                    name.name or name.address,
                    block.kind,
                    ty,
                    spec,
                    init,
                    name.address,
                    constant,
                    retain,
                    decl.edge,
                    decl.comment,
                    name.span,
                    owner,
                )
                table[key] = symbol
                if record and not plain:
                    self._written_args.append((symbol, written, decl.type, checker, pou))
                    if self._args_checked:  # a test file's variables, declared after the project's check
                        self._check_written(*self._written_args.pop(), late=True)
                if block.kind == "VAR_EXTERNAL" and pou is not None:
                    self._check_external(symbol, report, name)

    def _check_address(self, block, name: ast.DeclName, ty: Type, pou: PouInfo | None, report) -> None:
        """``AT %addr``: a valid address of the type's width (iec/addresses.py), not in a function (VAR-43). An
        incomplete address (``AT %I*``) leaves the variable an ordinary one until a configuration places it."""
        if incomplete(name.address):
            return
        try:
            address = parse_address(name.address)
        except ValueError as error:
            report("ST-ADDRESS", str(error), name)
            return
        if block.retain:
            report(
                "ST-ADDRESS",
                f"RETAIN has no effect on a variable at {address.text}: the process image is cleared on a restart",
                name,
                severity="warning",
            )
        if pou is not None and pou.kind == "FUNCTION":
            report("ST-DECL", "a function has no memory of its own: it cannot locate a variable AT an address", name)
        elif isinstance(ty, (t.Elementary, t.StringType)) and block.kind != "VAR_EXTERNAL":
            problem = type_problem(address, ty.name)
            if problem:
                report("ST-ADDRESS", problem, name)
        elif ty is not ERROR and not isinstance(ty, t.Elementary):
            where = f"cannot be located at {address.text}: only elementary types can"
            report("ST-ADDRESS", f"{article(str(ty))} {where}", name)

    def _check_decl(self, block, decl: ast.VarDecl, ty: Type, pou: PouInfo | None, report) -> None:
        if decl.edge and (block.kind != "VAR_INPUT" or not t.same(ty, t.BOOL) or pou is None or pou.kind == "FUNCTION"):
            report(
                "ST-DECL", f"{decl.edge} is only allowed on BOOL inputs of function blocks and programs (VAR-22)", decl
            )
        if decl.init is not None and block.kind in ("VAR_EXTERNAL", "VAR_IN_OUT"):
            report("ST-DECL", f"a {block.kind} variable cannot have an initial value (VAR-83)", decl.init)
        if isinstance(ty, t.FbType) and ty.pou is not None and ty.pou.plant:
            report(
                "ST-PLANT",
                f"{ty.pou.name} is a plant: it runs in the plant task before every scan and cannot be "
                "declared as a variable",
                decl,
            )
        abstract = abstract_instance(ty, block.kind)
        if abstract:
            report("ST-DECL", abstract, decl)
        if isinstance(ty, t.FbType) and pou is not None and pou.kind == "FUNCTION":
            report("ST-DECL", f"a function has no memory, so it cannot contain the instance of {ty.name} (ST-57)", decl)
        if isinstance(ty, t.PointerType) and block.retain:
            report(
                "ST-DECL",
                f"{article(str(ty))} cannot be RETAIN: a restart makes the variables it refers to anew "
                "(set it again after one)",
                decl,
            )
        if block.constant and decl.init is None and block.kind != "VAR_EXTERNAL":
            report("ST-DECL", "a CONSTANT needs an initial value", decl, severity="warning")

    def _check_external(self, symbol: Symbol, report, node) -> None:
        if symbol.address is not None and symbol.name == symbol.address:
            return  # VAR_EXTERNAL AT %X0.0 : BOOL: the address itself, global by nature (VAR-73, Ex 3.21)
        target = self.result.globals.get(symbol.name.upper())
        if target is None and shared_use(self.result, report, node, symbol.name):
            return
        if target is None:
            report(
                "ST-EXTERNAL",
                f"VAR_EXTERNAL '{symbol.name}' does not match any global variable"
                + did_you_mean(symbol.name, [g.name for g in self.result.globals.values()]),
                node,
            )
        elif not t.same(target.type, symbol.type):
            report(
                "ST-EXTERNAL", f"VAR_EXTERNAL '{symbol.name}' is {symbol.type} but the global is {target.type}", node
            )
        else:
            symbol.constant = symbol.constant or target.constant

    # ------------------------------------------------------------ bodies and the call graph
    def _check_body(self, info: PouInfo, body: list[ast.Stmt] | IlBody) -> None:
        report = self._reporter(f"{info.name}/body", info.name)
        if isinstance(body, IlBody):
            il = check_il_body(self.result, info, body, report)
            info.body, info.accumulators, assigned = il.statements, il.accumulators, il.result_assigned
            info.il_values, info.il_step_lines = il.values, il.step_lines
        else:
            checker = BodyChecker(self.result, info, report)
            checker.statements(body)
            check_registers(body, report)
            info.body, assigned = body, checker.result_assigned
        if info.kind == "FUNCTION" and not assigned and info.return_type not in (None, ERROR):
            report(
                "ST-NO-RESULT",
                f"the function {info.name} never assigns its result: it returns the default value of its type",
                None,
                severity="warning",
            )

    def _check_recursion(self) -> None:
        """POU-02: a POU must not call or instantiate itself, directly or through others."""
        state: dict[str, int] = {}
        reported: set[str] = set()
        for name in self.result.pous:
            if name not in state:
                self._visit_calls(name, [name], state, reported)

    def _visit_calls(self, name: str, path: list[str], state: dict[str, int], reported: set[str]) -> None:
        """Depth first from ``name`` (``state``: 1 on the path, 2 done), reporting each cycle once. (A method, not a
        closure calling itself: that closure was a reference cycle keeping the checker and its result alive until
        a collection; issue 27.)"""
        state[name] = 1
        for callee in sorted(self.result.pous[name].calls):
            if callee not in self.result.pous:
                continue
            if state.get(callee) == 1:
                cycle = path[path.index(callee) :] + [callee] if callee in path else [name, callee]
                if callee not in reported:
                    reported.add(callee)
                    names = " -> ".join(self.result.pous[c].name for c in cycle)
                    pou = self.result.pous[callee]
                    self._reporter(f"{pou.name}/body", pou.name)(
                        "ST-RECURSION", f"recursive call {names}: POUs must not call themselves", None
                    )
            elif callee not in state:
                self._visit_calls(callee, path + [callee], state, reported)
        state[name] = 2


_PACK_MODES = {"0": 1, "1": 1, "2": 2, "4": 4, "8": 8}  # CODESYS: 0 and 1 both pack without any padding


def _pack(decl: ast.TypeDecl, resolved: Type, report: Reporter) -> None:
    """Give the STRUCT its CODESYS ``pack_mode`` (st/pragmas.py), the largest alignment of its members."""
    if not isinstance(decl.type, ast.StructType) or not isinstance(resolved, t.StructType):
        report(
            "ST-DECL",
            f"the attribute 'pack_mode' packs a STRUCT, and the type '{decl.name}' is not one: put it above a "
            "STRUCT's TYPE declaration, or remove it",
            decl,
        )
    elif decl.pack_mode not in _PACK_MODES:
        report(
            "ST-DECL",
            f"the attribute 'pack_mode' of the STRUCT '{decl.name}' is '{decl.pack_mode}': CODESYS packs with '0' "
            "or '1' (no padding), '2', '4' or '8' (members aligned to at most that many bytes)",
            decl,
        )
    else:
        resolved.pack_mode = _PACK_MODES[decl.pack_mode]


def _redefinable(name: str) -> bool:
    """Whether a project's own POU may be named like this standard function (and is called instead of it)."""
    return name in stdlib.REDEFINABLE or (t.codesys_typing() and name in stdlib.CODESYS_REDEFINABLE)


def _nothing_to_check(ty: Type, decl: ast.VarDecl, written: list[Any] | None, constant: bool) -> bool:
    """Whether ``decl``'s variables (of type ``ty``, FB_init arguments ``written``, in a CONSTANT block or not) are
    ones ``_check_decl`` and ``_check_written`` find nothing to say about: elementary, without an edge, an initial
    value, CONSTANT or arguments. Most of a large program's are (issue 27: 200,000 variables looked at again for
    nothing; tests/st/test_declaration_checks.py compares with checking them all)."""
    return type(ty) is t.Elementary and written is None and not decl.edge and decl.init is None and not constant


def _elementary_decl(decl: ast.VarDecl) -> bool:
    return isinstance(decl.type, ast.NamedType) and t.elementary(decl.type.name) is not None


def _parse_types(text: str, *, file: str, pou: None = None):
    """The model's ``types`` text holds TYPE blocks and INTERFACEs (st/interfaces.py) only."""
    result = parse_source(text, file=file)
    if result.ast is not None:
        stray = [item for item in result.ast.items if not isinstance(item, (ast.TypeBlock, ast.InterfaceDecl))]
        for item in stray:
            result.diagnostics.append(
                Diagnostic(
                    code="ST-DECL",
                    message="only TYPE ... END_TYPE blocks and INTERFACEs belong here",
                    file=file,
                    line=item.span.line,
                    column=item.span.column,
                )
            )
        result.ast = [item for item in result.ast.items if isinstance(item, (ast.TypeBlock, ast.InterfaceDecl))]
    return result


def check_project(project: Project) -> CheckResult:
    """Parse and check every text of ``project`` and of the libraries it uses; see ``CheckResult`` for what is
    resolved."""
    with t.typing_rules(project.typing):
        return ProjectChecker(with_libraries(project)).run()


#: Names of letters and digits from a letter, at most MAX_NAME_LENGTH characters: ones ``pou_name_problem`` accepts and
#: that do not end with '_', so only the keyword check is left (most declared names; issue 27,
#: tests/st/test_declaration_checks.py compares with the full check)
_PLAIN_NAME = re.compile(rf"[A-Za-z][A-Za-z0-9]{{0,{MAX_NAME_LENGTH - 1}}}\Z")


def check_identifier(name: str, node: Any, report: Reporter) -> None:
    """A declared name: not a keyword or type name (KW-01, KW-02), no two '_' in a row, at most 64 characters
    (LEX-13, LEX-15); a trailing '_' only warns (IEC ed. 2 forbids it)."""
    if name.upper() in reserved_words():
        report("ST-NAME", f"'{name}' is a keyword or type name and cannot be declared as a name (KW-02)", node)
    elif _PLAIN_NAME.match(name):
        return
    elif problem := pou_name_problem(name):
        report("ST-NAME", f"'{name}' is not a valid identifier: {problem}", node)
    elif name.endswith("_"):
        report(
            "ST-NAME", f"'{name}' ends with '_', which IEC 61131-3 edition 2 does not allow", node, severity="warning"
        )


def check_operand(
    result_or_scope: CheckResult | Project, pou_name: str, text: str, expected_type: Type | str | None = None
) -> tuple[ast.Expr | None, list[Diagnostic]]:
    """Resolve an LD/FBD operand (``T1.Q``, ``arr[i]``, ``T#5s``) in the scope of ``pou_name``.

    Returns the typed expression (None when it does not parse) and its diagnostics;
    ``expected_type`` (a type or a type name such as ``"BOOL"``) adds an assignment-compatibility check.
    """
    result = result_or_scope if isinstance(result_or_scope, CheckResult) else check_project(result_or_scope)
    parsed = parse_expression(text, pou=pou_name)
    diagnostics = list(parsed.diagnostics)
    if parsed.ast is None:
        return None, diagnostics
    report = Reporter(diagnostics, None, pou_name)
    checker = BodyChecker(result, result.pou(pou_name), report)
    expected = _expected(result, expected_type)
    value = checker.expr(parsed.ast, expected)
    if expected is not None and value is not ERROR:
        assignable_or_report(checker, expected, value, parsed.ast, f"operand '{text.strip()}'")
    return parsed.ast, diagnostics


def _expected(result: CheckResult, expected: Type | str | None) -> Type | None:
    if expected is None or isinstance(expected, Type):
        return expected
    typedef = result.types.get(expected.upper())
    return typedef.type if typedef else t.elementary(expected)
