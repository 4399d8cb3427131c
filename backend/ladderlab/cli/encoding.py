"""``--encoding`` of every command that reads files (CoDeSys 2.3 exports from Russian courses are cp1251)."""

from __future__ import annotations

import argparse

from ..model import Diagnostic
from ..storage import StorageError
from ..storage.text_files import check_encoding


def add_encoding_option(command: argparse.ArgumentParser) -> None:
    command.add_argument(
        "--encoding",
        default=None,
        metavar="NAME",
        help="encoding of the files read (default UTF-8), e.g. cp1251 for CoDeSys 2.3 exports",
    )


def encoding_of(args: argparse.Namespace) -> str | None:
    """The ``--encoding`` given (None: UTF-8); an unknown one is a BAD-OPTION error (exit 2)."""
    try:
        return check_encoding(args.encoding)
    except ValueError as error:
        raise StorageError([Diagnostic(code="BAD-OPTION", message=f"--encoding: {error}")]) from None
