"""EXTENDS between function blocks (IEC 61131-3 ed. 3, 6.6.3; CODESYS): the base's variables and methods are the
derived FB's too, a method of the same name overrides the base's (same parameters and result), FINAL and ABSTRACT.

A derived FB's symbols are its base's (first, in their order) then its own, so an instance of it has the base's
variables where an instance of the base has them: a method of the base runs on it unchanged (ir/context.py).
Which method a call runs is decided when it runs, by the instance's own FB (ir/lower_project.py dispatch tables).
"""

from __future__ import annotations

from typing import Any

from ..iec.spelling import did_you_mean
from . import types as t
from .symbols import PouInfo


def link_bases(checker: Any, project: Any) -> None:
    """Each FB's base (the FB it EXTENDS); then the base's variables for each derived one."""
    pous = checker.result.pous
    for pou in project.pous:
        info = pous.get(pou.name.upper())
        if info is None or info.name != pou.name:
            continue
        report = checker._reporter(f"{pou.name}/declarations", pou.name)
        if (pou.abstract or pou.final or pou.extends) and info.kind != "FUNCTION_BLOCK":
            report("ST-DECL", f"EXTENDS, ABSTRACT and FINAL belong to function blocks, not to a {pou.kind}", None)
            continue
        if pou.abstract and pou.final:
            report("ST-DECL", f"{pou.name} cannot be both ABSTRACT and FINAL", None)
        if pou.extends is None:
            continue
        base = pous.get(pou.extends.upper())
        if base is None or base.kind != "FUNCTION_BLOCK" or base.plant:
            blocks = [p.name for p in pous.values() if p.kind == "FUNCTION_BLOCK" and p is not info]
            report(
                "ST-UNKNOWN-TYPE",
                f"{pou.name} EXTENDS '{pou.extends}', which is not a function block"
                + did_you_mean(pou.extends, blocks),
                None,
            )
            continue
        if base.final:
            report("ST-DECL", f"{base.name} is FINAL: no function block can extend it", None)
        info.base = base
    for info in pous.values():
        if info.base is not None and any(pou is info for pou in info.base.lineage()):
            cycle = " -> ".join(pou.name for pou in [info, *info.base.lineage()][: len(info.lineage()) + 1])
            checker._reporter(f"{info.name}/declarations", info.name)(
                "ST-RECURSION", f"{cycle}: a function block cannot extend itself", None
            )
            info.base = None
    merged: set[int] = set()
    for info in list(pous.values()):
        _inherit(checker, info, merged)


def _inherit(checker: Any, info: PouInfo, merged: set[int]) -> None:
    if id(info) in merged:
        return
    merged.add(id(info))
    base = info.base
    if base is None:
        return
    _inherit(checker, base, merged)
    symbols = dict(base.symbols)
    report = checker._reporter(f"{info.name}/declarations", info.name)
    for key, symbol in info.symbols.items():
        if key in symbols:
            report(
                "ST-DUPLICATE",
                f"'{symbol.name}' is already a variable of {symbols[key].pou}, which {info.name} extends",
                symbol,
            )
            continue
        symbols[key] = symbol
    info.symbols = symbols
    info.calls |= base.calls | {base.name.upper()}


def check_overrides(checker: Any, fbs: list[PouInfo]) -> None:
    """After every method is declared: overriding methods match what they override, FINAL ones are not
    overridden, ABSTRACT ones only exist in ABSTRACT FBs and every other FB implements the ones it inherits."""
    for fb in fbs:
        report = checker._reporter(f"{fb.name}/declarations", fb.name)
        for method in fb.methods.values():
            info = method.method
            where = checker._reporter(f"{method.name}/declarations", method.name)
            if info.abstract and not fb.abstract:
                where("ST-DECL", f"{fb.name} has the ABSTRACT method {info.name}, so it must be ABSTRACT too", None)
            inherited = fb.base.find_method(info.key) if fb.base is not None else None
            if inherited is None:
                continue
            if inherited.method.final:
                where("ST-DECL", f"{inherited.name} is FINAL: {fb.name} cannot override it", None)
            difference = signature_difference(inherited, method) if info.key != "FB_INIT" else None  # (fb_init.py)
            if difference:
                where("ST-DECL", f"{method.name} overrides {inherited.name} but {difference}", None)
        if fb.abstract:
            continue
        names = {name for pou in fb.lineage() for name in pou.methods}
        for name in sorted(names):
            found = fb.find_method(name)
            if found is not None and found.method.abstract and found.method.owner is not fb:
                report(
                    "ST-DECL",
                    f"{fb.name} must implement the ABSTRACT method {found.name} (or be ABSTRACT itself)",
                    None,
                )


def signature_difference(base: PouInfo, method: PouInfo) -> str | None:
    """What makes ``method`` unfit to override ``base`` (its parameters and result must be the same)."""
    mine, theirs = method.parameters(), base.parameters()
    if [(s.name.upper(), s.var_class) for s in mine] != [(s.name.upper(), s.var_class) for s in theirs]:
        listed = ", ".join(f"{s.var_class} {s.name}" for s in theirs) or "no parameters"
        return f"its parameters differ (it takes {listed})"
    for a, b in zip(mine, theirs):
        if not t.same(a.type, b.type):
            return f"its parameter {a.name} is {a.type}, not {b.type}"
    if (method.return_type is None) != (base.return_type is None) or (
        method.return_type is not None and not t.same(method.return_type, base.return_type)
    ):
        return f"its result type is {method.return_type or 'none'}, not {base.return_type or 'none'}"
    return None


def abstract_instance(ty: Any, var_class: str) -> str | None:
    """Why a variable of type ``ty`` cannot be declared (an instance of an ABSTRACT FB), or None."""
    if isinstance(ty, t.FbType) and ty.pou is not None and ty.pou.abstract and var_class != "VAR_IN_OUT":
        return f"{ty.pou.name} is ABSTRACT: declare an instance of a function block derived from it"
    return None
