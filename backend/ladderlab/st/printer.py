"""AST -> readable IEC 61131-3 ST text (4-space indentation, upper-case keywords).

Parentheses are inserted only where the precedence table (ST-02) needs them, so
``parse(print(ast)) == ast`` holds for every AST the parser can produce. The ST
exporter prints through this module.
"""

from __future__ import annotations

from ..iec.literals import encode_string, encode_time_literal
from . import ast
from .pragmas import pack_mode_pragma

INDENT = "    "

# Binding strength, loosest first (ST-02): OR < XOR < AND < = <> < comparisons < + - < * / MOD < unary < **.
_PRECEDENCE = {
    "OR": 1,
    "OR_ELSE": 1,
    "XOR": 2,
    "AND": 3,
    "AND_THEN": 3,
    "=": 4,
    "<>": 4,
    "<": 5,
    ">": 5,
    "<=": 5,
    ">=": 5,
    "+": 6,
    "-": 6,
    "*": 7,
    "/": 7,
    "MOD": 7,
    "**": 9,
}
_UNARY = 8
_PRIMARY = 10


# ---------------------------------------------------------------- expressions


def print_expression(expr: ast.Expr) -> str:
    return _expr(expr, 0)


def _precedence(expr: ast.Expr) -> int:
    if isinstance(expr, ast.Fit):  # printed as the operation it checks
        return _precedence(expr.operand)
    if isinstance(expr, ast.Binary):
        return _PRECEDENCE[expr.op]
    if isinstance(expr, ast.Unary):
        return _UNARY
    return _PRIMARY


def _expr(expr: ast.Expr, minimum: int) -> str:
    text = _bare(expr)
    return f"({text})" if _precedence(expr) < minimum else text


def _bare(expr: ast.Expr) -> str:
    if isinstance(expr, ast.Fit):
        return _bare(expr.operand)
    if isinstance(expr, ast.Binary):
        level = _PRECEDENCE[expr.op]
        right = _power_operand(expr.right) if expr.op == "**" else _expr(expr.right, level + 1)
        return f"{_expr(expr.left, level)} {expr.op} {right}"
    if isinstance(expr, ast.Unary):
        return _unary(expr, in_power=False)
    if isinstance(expr, ast.Name):
        return expr.name
    if isinstance(expr, ast.DirectAddr):
        return expr.address
    if isinstance(expr, ast.Member):
        return f"{_expr(expr.base, _PRIMARY)}.{expr.name}"
    if isinstance(expr, ast.Index):
        return f"{_expr(expr.base, _PRIMARY)}[{', '.join(_expr(i, 0) for i in expr.indices)}]"
    if isinstance(expr, ast.Deref):
        return f"{_expr(expr.base, _PRIMARY)}^"
    if isinstance(expr, ast.Call):
        return f"{_expr(expr.callee, _PRIMARY)}({print_args(expr.args)})"
    return _literal(expr)


def _unary(expr: ast.Unary, in_power: bool) -> str:
    separator = " " if expr.op == "NOT" else ""
    operand = _power_operand(expr.operand) if in_power else _expr(expr.operand, _UNARY)
    return f"{expr.op}{separator}{operand}"


def _power_operand(expr: ast.Expr) -> str:
    """Right of ``**``: a primary, or a sign/NOT applied to one (``2 ** -1``)."""
    if isinstance(expr, ast.Unary):
        return _unary(expr, in_power=True)
    return _expr(expr, _PRIMARY)


def print_args(args: list[ast.Arg]) -> str:
    return ", ".join(_arg(a) for a in args)


def _arg(arg: ast.Arg) -> str:
    value = _expr(arg.value, 0)
    if arg.name is None:
        return value
    if arg.output:
        return f"{'NOT ' if arg.negated else ''}{arg.name} => {value}"
    return f"{arg.name} := {value}"


def _literal(expr: ast.Expr) -> str:
    if isinstance(expr, ast.IntLit):
        return _integer(expr.value, expr.base)
    if isinstance(expr, ast.RealLit):
        return repr(expr.value)
    if isinstance(expr, ast.BoolLit):
        return "TRUE" if expr.value else "FALSE"
    if isinstance(expr, ast.StringLit):
        return encode_string(expr.value, expr.wide)
    if isinstance(expr, ast.TimeLit):
        return encode_time_literal(expr.kind, expr.value)
    if isinstance(expr, ast.TypedLit):
        return f"{expr.type_name}#{_bare(expr.value)}"
    raise TypeError(f"not an ST expression node: {expr!r}")


def _integer(value: int, base: int) -> str:
    sign = "-" if value < 0 else ""
    magnitude = abs(value)
    if base == 16:
        return f"{sign}16#{magnitude:X}"
    if base == 8:
        return f"{sign}8#{magnitude:o}"
    if base == 2:
        return f"{sign}2#{magnitude:b}"
    return f"{sign}{magnitude}"


# ---------------------------------------------------------------- statements


def print_statements(statements: list[ast.Stmt], level: int = 0) -> str:
    return "".join(_statement(s, level) for s in statements)


def _statement(stmt: ast.Stmt, level: int) -> str:
    pad = INDENT * level
    if isinstance(stmt, ast.RefAssign):
        return f"{pad}{_expr(stmt.target, 0)} REF= {_expr(stmt.value, 0)};\n"
    if isinstance(stmt, ast.Assign):
        return f"{pad}{_expr(stmt.target, 0)} {'?=' if stmt.attempt else ':='} {_expr(stmt.value, 0)};\n"
    if isinstance(stmt, ast.CallStmt):
        return f"{pad}{_expr(stmt.call, 0)};\n"
    if isinstance(stmt, ast.If):
        text = ""
        for i, (cond, body) in enumerate(stmt.branches):
            text += f"{pad}{'IF' if i == 0 else 'ELSIF'} {_expr(cond, 0)} THEN\n{print_statements(body, level + 1)}"
        if stmt.else_body is not None:
            text += f"{pad}ELSE\n{print_statements(stmt.else_body, level + 1)}"
        return text + f"{pad}END_IF;\n"
    if isinstance(stmt, ast.Case):
        text = f"{pad}CASE {_expr(stmt.selector, 0)} OF\n"
        for branch in stmt.branches:
            labels = ", ".join(_case_label(label) for label in branch.labels)
            text += f"{pad}{INDENT}{labels}:\n{print_statements(branch.body, level + 2)}"
        if stmt.else_body is not None:
            text += f"{pad}ELSE\n{print_statements(stmt.else_body, level + 1)}"
        return text + f"{pad}END_CASE;\n"
    if isinstance(stmt, ast.For):
        step = f" BY {_expr(stmt.step, 0)}" if stmt.step is not None else ""
        head = f"FOR {stmt.var.name} := {_expr(stmt.start, 0)} TO {_expr(stmt.end, 0)}{step} DO"
        return f"{pad}{head}\n{print_statements(stmt.body, level + 1)}{pad}END_FOR;\n"
    if isinstance(stmt, ast.While):
        return f"{pad}WHILE {_expr(stmt.cond, 0)} DO\n{print_statements(stmt.body, level + 1)}{pad}END_WHILE;\n"
    if isinstance(stmt, ast.Repeat):
        body = print_statements(stmt.body, level + 1)
        return f"{pad}REPEAT\n{body}{pad}UNTIL {_expr(stmt.until, 0)}\n{pad}END_REPEAT;\n"
    if isinstance(stmt, ast.Exit):
        return f"{pad}EXIT;\n"
    if isinstance(stmt, ast.Continue):
        return f"{pad}CONTINUE;\n"
    if isinstance(stmt, ast.Return):
        return f"{pad}RETURN;\n"
    if isinstance(stmt, ast.Empty):
        return f"{pad};\n"
    raise TypeError(f"not an ST statement node: {stmt!r}")


def _case_label(label: ast.Expr | ast.CaseRange) -> str:
    if isinstance(label, ast.CaseRange):
        return f"{_expr(label.low, 0)}..{_expr(label.high, 0)}"
    return _expr(label, 0)


# ---------------------------------------------------------------- types and declarations


def print_type(spec: ast.TypeSpec, level: int = 0) -> str:
    if isinstance(spec, ast.NamedType):
        return spec.name
    if isinstance(spec, ast.SizedType):
        return f"{spec.name}[{_expr(spec.size, 0)}]"
    if isinstance(spec, ast.SubrangeType):
        return f"{spec.base} ({_expr(spec.low, 0)}..{_expr(spec.high, 0)})"
    if isinstance(spec, ast.ArrayType):
        ranges = ", ".join("*" if r is None else f"{_expr(r[0], 0)}..{_expr(r[1], 0)}" for r in spec.ranges)
        return f"ARRAY [{ranges}] OF {print_type(spec.element, level)}"
    if isinstance(spec, ast.PointerType):
        return f"{spec.kind} {print_type(spec.target, level)}"
    if isinstance(spec, ast.PositionalArgsType):
        return f"{spec.name}({', '.join(_expr(a, 0) for a in spec.args)})"
    if isinstance(spec, ast.InstanceArgsType):
        return f"{spec.name}[{', '.join(print_initializer(e) for e in spec.elements)}]"
    if isinstance(spec, ast.EnumType):
        values = ", ".join(v.name + (f" := {_expr(v.value, 0)}" if v.value is not None else "") for v in spec.values)
        if spec.base and spec.values and spec.values[0].value is None:  # IEC's `INT (A := 0, B)` needs the first :=
            return f"({values}) {spec.base}"  # CODESYS's form
        return f"{spec.base} ({values})" if spec.base else f"({values})"
    if isinstance(spec, ast.StructType):
        members = "".join(_var_decl(m, level + 1) for m in spec.members)
        return f"STRUCT\n{members}{INDENT * level}END_STRUCT"
    raise TypeError(f"not an ST type node: {spec!r}")


def print_initializer(init: ast.Init) -> str:
    if isinstance(init, ast.ArrayInit):
        return "[" + ", ".join(_array_item(item) for item in init.items) + "]"
    if isinstance(init, ast.StructInit):
        return "(" + ", ".join(f"{name} := {print_initializer(value)}" for name, value in init.fields) + ")"
    return _expr(init, 0)


def _array_item(item: ast.Init | ast.RepeatInit) -> str:
    if isinstance(item, ast.RepeatInit):
        return f"{item.count}({print_initializer(item.value) if item.value is not None else ''})"
    return print_initializer(item)


def _decl_name(name: ast.DeclName) -> str:
    if name.name is None:
        return f"AT {name.address}"
    return name.name + (f" AT {name.address}" if name.address else "")


def _var_decl(decl: ast.VarDecl, level: int) -> str:
    text = INDENT * level + ", ".join(_decl_name(n) for n in decl.names) + " : " + print_type(decl.type, level)
    if decl.edge:
        text += " " + decl.edge
    if decl.init is not None:
        text += " := " + print_initializer(decl.init)
    text += ";"
    if decl.comment:
        text += (
            f" (* {decl.comment} *)" if "*)" not in decl.comment and "(*" not in decl.comment else f" // {decl.comment}"
        )
    return text + "\n"


def print_varprint_statements(block: ast.VarBlock, level: int = 0) -> str:
    head = " ".join([block.kind, *block.qualifiers])
    decls = "".join(_var_decl(d, level + 1) for d in block.decls)
    return f"{INDENT * level}{head}\n{decls}{INDENT * level}END_VAR\n"


def print_declarations(blocks: list[ast.VarBlock]) -> str:
    return "".join(print_varprint_statements(b) for b in blocks)


def _typeprint_statements(block: ast.TypeBlock) -> str:
    lines = []
    for decl in block.decls:
        init = f" := {print_initializer(decl.init)}" if decl.init is not None else ""
        if decl.pack_mode is not None:  # above the declaration it packs (st/pragmas.py)
            lines.append(f"{INDENT}{pack_mode_pragma(decl.pack_mode)}\n")
        lines.append(f"{INDENT}{decl.name} : {print_type(decl.type, 1)}{init};\n")
    return "TYPE\n" + "".join(lines) + "END_TYPE\n"


# ---------------------------------------------------------------- POUs, configurations, files


def print_pou(pou: ast.Pou) -> str:
    head = " ".join([pou.kind, *([pou.modifier] if pou.modifier else []), pou.name])
    if pou.return_type is not None:
        head += f" : {print_type(pou.return_type)}"
    if pou.extends is not None:
        head += f" EXTENDS {pou.extends}"
    if pou.implements:
        head += f" IMPLEMENTS {', '.join(pou.implements)}"
    # Members stand between the VAR blocks and the body (the grammar's order); the tree keeps each kind in its own
    # list, so they print methods, properties, then actions, and parse back to the same lists.
    members = [*map(_method, pou.methods), *map(_property, pou.properties), *map(_action, pou.actions)]
    body = print_sfc(pou.sfc, 1) if pou.sfc is not None else print_statements(pou.body, 1)
    return f"{head}\n{print_declarations(pou.var_blocks)}{''.join(members)}{body}END_{pou.kind}\n"


def _member_head(word: str, modifiers: list[str], name: str) -> str:
    return " ".join([word, *modifiers, name])


def _method(method: ast.MethodDecl, level: int = 1) -> str:
    """``METHOD [modifiers] name [: type]``, its VAR blocks and body (none in an INTERFACE's prototype)."""
    head = _member_head("METHOD", method.modifiers, method.name)
    if method.return_type is not None:
        head += f" : {print_type(method.return_type, level)}"
    inner = _blocks_and_body(method.var_blocks, method.body, level)
    return f"{INDENT * level}{head}\n{inner}{INDENT * level}END_METHOD\n"


def _property(prop: ast.PropertyDecl, level: int = 1) -> str:
    """``PROPERTY [modifiers] name : type`` with its GET / SET accessors (bodiless in an INTERFACE)."""
    head = f"{_member_head('PROPERTY', prop.modifiers, prop.name)} : {print_type(prop.type, level)}"
    pad = INDENT * (level + 1)
    accessors = "".join(
        f"{pad}{a.kind}\n{_blocks_and_body(a.var_blocks, a.body, level + 1)}{pad}END_{a.kind}\n" for a in prop.accessors
    )
    return f"{INDENT * level}{head}\n{accessors}{INDENT * level}END_PROPERTY\n"


def _action(action: ast.ActionDecl) -> str:
    """A function block's ``ACTION name:`` outside SFC."""
    return f"{INDENT}ACTION {action.name}:\n{print_statements(action.body, 2)}{INDENT}END_ACTION\n"


def _blocks_and_body(blocks: list[ast.VarBlock], body: list[ast.Stmt], level: int) -> str:
    return "".join(print_varprint_statements(b, level) for b in blocks) + print_statements(body, level + 1)


def print_interface(interface: ast.InterfaceDecl) -> str:
    """``INTERFACE name [EXTENDS i, ...]``: its method and property prototypes."""
    extends = f" EXTENDS {', '.join(interface.extends)}" if interface.extends else ""
    members = [*map(_method, interface.methods), *map(_property, interface.properties)]
    return f"INTERFACE {interface.name}{extends}\n{''.join(members)}END_INTERFACE\n"


def print_sfc(sfc: ast.Sfc, level: int = 0) -> str:
    """A textual SFC body (IEC 61131-3 B.1.6): steps with their action associations, transitions, actions."""
    pad = INDENT * level
    out = []
    for item in sfc.items:
        if isinstance(item, ast.SfcStep):
            lines = [f"{pad}{'INITIAL_STEP' if item.initial else 'STEP'} {item.name}:\n"]
            for association in item.associations:
                args = [association.qualifier] if association.qualifier else []
                args += [_expr(arg, 0) for arg in association.args]
                lines.append(f"{pad}{INDENT}{association.action}({', '.join(args)});\n")
            out.append("".join(lines) + f"{pad}END_STEP\n")
        elif isinstance(item, ast.SfcTransition):
            name = f" {item.name}" if item.name else ""
            priority = f" (PRIORITY := {item.priority})" if item.priority is not None else ""
            head = f"{pad}TRANSITION{name}{priority} FROM {_step_list(item.sources)} TO {_step_list(item.targets)}"
            if item.condition is None:  # IL: the tree has no instructions (blanked), as an IL action's body
                out.append(f"{head}:\n{pad}END_TRANSITION\n")
            else:
                out.append(f"{head}\n{pad}{INDENT}:= {_expr(item.condition, 0)};\n{pad}END_TRANSITION\n")
        else:
            body = (
                print_sfc(item.body, level + 1)
                if isinstance(item.body, ast.Sfc)
                else print_statements(item.body, level + 1)
            )
            out.append(f"{pad}ACTION {item.name}:\n{body}{pad}END_ACTION\n")
    return "".join(out)


def _step_list(names: list[str]) -> str:
    return names[0] if len(names) == 1 else "(" + ", ".join(names) + ")"


def _task(task: ast.TaskConfig, level: int) -> str:
    props = ", ".join(f"{name} := {_expr(value, 0)}" for name, value in task.properties)
    return f"{INDENT * level}TASK {task.name}({props});\n"


def _program_config(prog: ast.ProgramConfig, level: int) -> str:
    text = "PROGRAM " + (f"{prog.retain} " if prog.retain else "") + prog.name
    if prog.task:
        text += f" WITH {prog.task}"
    text += f" : {prog.type_name}"
    if prog.args:
        text += f"({print_args(prog.args)})"
    return f"{INDENT * level}{text};\n"


def _access_block(block: ast.AccessBlock, level: int) -> str:
    lines = [f"{INDENT * level}VAR_ACCESS\n"]
    for d in block.decls:
        direction = f" {d.direction}" if d.direction else ""
        path, ty = _expr(d.path, 0), print_type(d.type, level + 1)
        lines.append(f"{INDENT * (level + 1)}{d.name} : {path} : {ty}{direction};\n")
    return "".join(lines) + f"{INDENT * level}END_VAR\n"


def _config_block(block: ast.ConfigBlock, level: int) -> str:
    lines = [f"{INDENT * level}VAR_CONFIG\n"]
    for d in block.decls:
        at = f" AT {d.address}" if d.address else ""
        init = f" := {print_initializer(d.init)}" if d.init is not None else ""
        path, ty = _expr(d.path, 0), print_type(d.type, level + 1)
        lines.append(f"{INDENT * (level + 1)}{path}{at} : {ty}{init};\n")
    return "".join(lines) + f"{INDENT * level}END_VAR\n"


def _config_item(item, level: int) -> str:
    if isinstance(item, ast.TaskConfig):
        return _task(item, level)
    if isinstance(item, ast.AccessBlock):
        return _access_block(item, level)
    if isinstance(item, ast.ConfigBlock):
        return _config_block(item, level)
    if isinstance(item, ast.ProgramConfig):
        return _program_config(item, level)
    if isinstance(item, ast.VarBlock):
        return print_varprint_statements(item, level)
    on = f" ON {item.on}" if item.on else ""
    body = "".join(_config_item(i, level + 1) for i in item.items)
    return f"{INDENT * level}RESOURCE {item.name}{on}\n{body}{INDENT * level}END_RESOURCE\n"


def print_configuration(config: ast.Configuration) -> str:
    body = "".join(_config_item(item, 1) for item in config.items)
    return f"CONFIGURATION {config.name}\n{body}END_CONFIGURATION\n"


def print_source(source: ast.Source) -> str:
    parts = []
    for item in source.items:
        if isinstance(item, ast.Pou):
            parts.append(print_pou(item))
        elif isinstance(item, ast.TypeBlock):
            parts.append(_typeprint_statements(item))
        elif isinstance(item, ast.VarBlock):
            parts.append(print_varprint_statements(item))
        elif isinstance(item, ast.InterfaceDecl):
            parts.append(print_interface(item))
        else:
            parts.append(print_configuration(item))
    return "\n".join(parts)
