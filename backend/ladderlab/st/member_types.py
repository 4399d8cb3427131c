"""What renaming a method or property needs to know about types, read from the project's texts alone (it runs on
the browser's unsaved copy, which need not check): the type every variable is declared with, the members of every
function block and structure (so ``a.b.Old`` can be followed to the type of ``a.b``), and which function blocks and
INTERFACEs share the renamed member (an override, the FBs implementing an interface method and the interfaces an FB's
method implements are one member: renaming one renames them all, or the project would stop building).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from . import ast
from .parser import parse_declarations, parse_source


def declared_types(declarations: str) -> dict[str, str]:
    """Each variable of ``declarations`` with the name of its type (upper case; an array's element type, a
    reference's or pointer's target); nothing when the text does not parse (the check reports it)."""
    found: dict[str, str] = {}
    for block in parse_declarations(declarations).ast or []:
        for decl in block.decls:
            found.update((n.name.upper(), kind) for n in decl.names if n.name and (kind := _type_name(decl.type)))
    return found


def _type_name(spec: ast.TypeSpec) -> str | None:
    while isinstance(spec, (ast.ArrayType, ast.PointerType)):
        spec = spec.element if isinstance(spec, ast.ArrayType) else spec.target
    if isinstance(spec, ast.EnumType):  # ``F(n := 1)``: an instance with its FB_init arguments (st/fb_init.py)
        return spec.base.upper() if spec.base else None
    if isinstance(spec, (ast.NamedType, ast.SizedType, ast.InstanceArgsType, ast.PositionalArgsType)):
        return spec.name.upper()
    return None


@dataclass
class ProjectTypes:
    """The function blocks, programs, structures and INTERFACEs of a dumped project, by upper-case name."""

    fields: dict[str, dict[str, str]] = field(default_factory=dict)  # FB (inherited too), PROGRAM, STRUCT: var -> type
    bases: dict[str, str] = field(default_factory=dict)  # FB -> the FB it EXTENDS
    implements: dict[str, list[str]] = field(default_factory=dict)  # FB -> its INTERFACEs
    interface_bases: dict[str, list[str]] = field(default_factory=dict)  # INTERFACE -> those it EXTENDS
    members: dict[str, set[str]] = field(default_factory=dict)  # FB or INTERFACE -> its own methods and properties

    @classmethod
    def of(cls, data: dict[str, Any]) -> ProjectTypes:
        types = cls()
        parsed = parse_source(data.get("types") or "")
        for item in parsed.ast.items if parsed.ast is not None else []:
            if isinstance(item, ast.InterfaceDecl):
                types.interface_bases[item.name.upper()] = [e.upper() for e in item.extends]
                types.members[item.name.upper()] = {m.name.upper() for m in [*item.methods, *item.properties]}
            elif isinstance(item, ast.TypeBlock):
                for decl in item.decls:
                    if isinstance(decl.type, ast.StructType):
                        members = decl.type.members
                        types.fields[decl.name.upper()] = {
                            n.name.upper(): kind
                            for d in members
                            if (kind := _type_name(d.type))
                            for n in d.names
                            if n.name
                        }
        own: dict[str, dict[str, str]] = {}
        for pou in data["pous"]:
            if pou["kind"] not in ("function_block", "program"):  # (a PROGRAM's methods, CODESYS: ``Prog.M()``)
                continue
            name = pou["name"].upper()
            own[name] = declared_types(pou["declarations"])
            if pou.get("extends"):
                types.bases[name] = pou["extends"].upper()
            types.implements[name] = [i.upper() for i in pou.get("implements") or []]
            listed = [*(pou.get("methods") or []), *(pou.get("properties") or [])]
            types.members[name] = {m["name"].upper() for m in listed}
        for name in own:
            types.fields[name] = {k: v for fb in reversed(types.lineage(name)) for k, v in own.get(fb, {}).items()}
        return types

    def lineage(self, fb: str) -> list[str]:
        """``fb`` and the FBs it extends, nearest first (a cycle, which the check reports, is cut)."""
        chain = [fb]
        while (base := self.bases.get(chain[-1])) is not None and base not in chain:
            chain.append(base)
        return chain

    def declares(self, kind: str, member: str) -> bool:
        """Does FB or INTERFACE ``kind``, or one it extends, declare ``member``?"""
        seen: set[str] = set()
        todo = self.lineage(kind)
        while todo:
            here = todo.pop()
            if here in seen:
                continue
            seen.add(here)
            if member in self.members.get(here, set()):
                return True
            todo += self.interface_bases.get(here, [])
        return False

    def group(self, start: str, member: str) -> frozenset[str]:
        """The FBs and INTERFACEs whose ``member`` is the one of ``start``: those extending one of them, the base
        whose member one overrides, the INTERFACEs one implements or extends that declare it, the FBs implementing
        one (all upper case)."""
        member = member.upper()
        group, todo = set(), [start.upper()]
        while todo:
            here = todo.pop()
            if here in group:
                continue
            group.add(here)
            related = [fb for fb, base in self.bases.items() if base == here]
            related += [fb for fb, listed in self.implements.items() if here in listed]
            related += [i for i, listed in self.interface_bases.items() if here in listed]
            upward = [self.bases[here]] if here in self.bases else []
            upward += self.implements.get(here, []) + self.interface_bases.get(here, [])
            todo += related + [kind for kind in upward if self.declares(kind, member)]
        return frozenset(group)

    def resolve(self, scope: dict[str, str], path: list[str]) -> str | None:
        """The type of ``path`` (``a``, ``b`` of ``a.b``) in ``scope`` (variable -> type), or None when a step is
        not a variable this knows (a property, a function's result: the check reports what the rename missed)."""
        kind = scope.get(path[0].upper())
        for name in path[1:]:
            kind = self.fields.get(kind or "", {}).get(name.upper())
        return kind
