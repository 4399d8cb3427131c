"""A named global variable list in a whole-project ST file (``ladderlab export st``, ``source_to_project``).

IEC ST has no named lists, so the list's name and CODESYS's qualified_only travel as attribute pragmas above its
first VAR_GLOBAL block (a tool that does not know them skips them as any pragma); the blocks that follow it without
another item between belong to the list::

    {attribute 'global_variable_list' := 'GVL_IO'}
    {attribute 'qualified_only'}
    VAR_GLOBAL
        bStart : BOOL;
    END_VAR
"""

from __future__ import annotations

import re

from ..model.project import QUALIFIED_ONLY, GlobalVariableList

_NAME = re.compile(r"\{\s*attribute\s+'global_variable_list'\s*:=\s*'([A-Za-z_][A-Za-z0-9_]*)'\s*\}", re.IGNORECASE)
_QUALIFIED = re.compile(r"\{\s*attribute\s+'qualified_only'\s*\}", re.IGNORECASE)
#: the text of a list without a block, so it reads back as a list
EMPTY = "VAR_GLOBAL\nEND_VAR"


def gvl_source(gvl: GlobalVariableList) -> str:
    """The list as a part of a project's ST file."""
    lines = [f"{{attribute 'global_variable_list' := '{gvl.name}'}}"]
    if gvl.qualified_only:
        lines.append(QUALIFIED_ONLY)
    return "\n".join([*lines, gvl.text.strip("\n") or EMPTY])


def gvl_heading(between: str) -> tuple[str, bool] | None:
    """(name, qualified_only) of the list whose pragmas stand in ``between`` (the text before a VAR_GLOBAL block,
    after the item before it), or None when it opens no list."""
    named = _NAME.search(between)
    if named is None:
        return None
    return named.group(1), _QUALIFIED.search(between, named.end()) is not None
