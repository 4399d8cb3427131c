"""``--library`` and ``--typing`` of the commands that build a project: a .st file has no project.json to list the
vendor libraries it uses (``Project.libraries``) or its type rules (``Project.typing``), so the command line adds
them."""

from __future__ import annotations

import argparse
from typing import get_args

from ..model import Project
from ..model.project import LibraryName, Typing


def add_library_option(command: argparse.ArgumentParser) -> None:
    command.add_argument(
        "--library",
        action="append",
        default=[],
        choices=get_args(LibraryName),
        help="use this vendor compatibility library (as a TwinCAT project adds it in its library manager); "
        "repeatable, added to the project's own",
    )
    command.add_argument(
        "--typing",
        choices=get_args(Typing),
        default=None,
        help="the ST type rules: iec (IEC 61131-3) or codesys (CODESYS V3's implicit conversions and arithmetic on "
        "bit strings, docs/st.md); default: the project's own (iec for a .st file)",
    )


def using_libraries(project: Project, args: argparse.Namespace) -> Project:
    """``project`` with the ``--library`` options added to the libraries it lists, and the ``--typing`` rules."""
    extra = [name for name in args.library if name not in project.libraries]
    update: dict[str, object] = {"libraries": [*project.libraries, *extra]} if extra else {}
    if getattr(args, "typing", None) is not None:
        update["typing"] = args.typing
    return project.model_copy(update=update) if update else project
