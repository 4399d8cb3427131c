"""``--library`` of the commands that build a project: a .st file has no project.json to list the vendor
libraries it uses (``Project.libraries``), so the command line adds them."""

from __future__ import annotations

import argparse
from typing import get_args

from ..model import Project
from ..model.project import LibraryName


def add_library_option(command: argparse.ArgumentParser) -> None:
    command.add_argument(
        "--library",
        action="append",
        default=[],
        choices=get_args(LibraryName),
        help="use this vendor compatibility library (as a TwinCAT project adds it in its library manager); "
        "repeatable, added to the project's own",
    )


def using_libraries(project: Project, args: argparse.Namespace) -> Project:
    """``project`` with the ``--library`` options added to the libraries it lists."""
    extra = [name for name in args.library if name not in project.libraries]
    return project.model_copy(update={"libraries": [*project.libraries, *extra]}) if extra else project
