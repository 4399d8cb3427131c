"""Load the PROJECT argument of the CLI: a project folder, a whole-project .json, or a .st / .il file."""

from __future__ import annotations

import contextlib
import json
from pathlib import Path

from filelock import FileLock
from pydantic import ValidationError

from ..model import Diagnostic, Project
from . import journal
from .errors import ProjectLoadError, json_text_problem, validation_diagnostics
from .project_folder import PROJECT_FILE, is_project_file, read_project_folder
from .text_files import CLI_HINT, decode_text
from .workspace import LOCKS_DIR


def load_project_path(path: Path | str, encoding: str | None = None, hint: str = CLI_HINT) -> Project:
    """Read whatever a user points the CLI at, its files in ``encoding`` (default UTF-8); raises ProjectLoadError
    with located diagnostics (a file that does not decode: BAD-ENCODING at its first bad byte)."""
    return load_project_with_warnings(path, encoding, hint)[0]


def load_project_with_warnings(
    path: Path | str, encoding: str | None = None, hint: str = CLI_HINT
) -> tuple[Project, list[Diagnostic]]:
    """``load_project_path``, with the warnings of reading a .st / .il file that a check of the project cannot
    repeat (located in the file: a misplaced pragma outside any POU, a second CONFIGURATION left out)."""
    path = Path(path)
    if path.is_dir():
        _finish_interrupted_save(path)
        if not (path / PROJECT_FILE).is_file():
            raise _error(str(path), f"not a project folder: it has no {PROJECT_FILE}")
        return read_project_folder(path, encoding, hint), []
    if not path.is_file():
        raise _error(str(path), "no such file or folder")
    if path.suffix.lower() == ".json":
        return _load_json_project(path, decode_text(path.read_bytes(), path.name, encoding, hint)), []
    if path.suffix.lower() in (".st", ".il"):  # IEC source; a POU whose body is IL is IL in either (docs/il.md)
        text = decode_text(path.read_bytes(), path.name, encoding, hint)
        return project_and_warnings_from_st(text, name=path.stem, file=path.name)
    raise _error(str(path), "expected a project folder, a project .json file or a .st or .il file")


def _finish_interrupted_save(folder: Path) -> None:
    """Replay or drop a save a crash interrupted, so the folder reads as exactly one revision.

    Inside a workspace (it has ``.locks/``) under that project's lock, as a server would take it."""
    if not journal.pending(folder):
        return
    locks = folder.resolve().parent / LOCKS_DIR
    with FileLock(locks / f"{folder.resolve().name}.lock") if locks.is_dir() else contextlib.nullcontext():
        journal.recover(folder, is_project_file)


def _load_json_project(path: Path, text: str) -> Project:
    refused = json_text_problem(text, path.name)
    if refused is not None:
        raise ProjectLoadError([refused])
    try:
        data = json.loads(text)
    except json.JSONDecodeError as err:
        raise ProjectLoadError(
            [
                Diagnostic(
                    code="BAD-JSON",
                    file=path.name,
                    line=err.lineno,
                    column=err.colno,
                    message=f"invalid JSON: {err.msg}",
                )
            ]
        ) from err
    try:
        return Project.model_validate(data)
    except ValidationError as err:
        raise ProjectLoadError(validation_diagnostics(err, data, path.name)) from err


def project_from_st(text: str, *, name: str, file: str) -> Project:
    """A project made of the TYPEs, VAR_GLOBALs, POUs and CONFIGURATION tasks of one IEC source file (ST, IL).

    The file is parsed (not just split like a stored POU file) because its CONFIGURATION
    becomes the project's tasks; POU texts keep the file's line numbers, so later
    diagnostics point into it.
    """
    return project_and_warnings_from_st(text, name=name, file=file)[0]


def project_and_warnings_from_st(text: str, *, name: str, file: str) -> tuple[Project, list[Diagnostic]]:
    """``project_from_st`` and the reading's warnings no check of the project repeats, located in ``file``."""
    from ..st.project_text import read_source  # the parser: imported at first use (startup, issue 27)

    read = read_source(text, name)
    errors = [d for d in read.diagnostics if d.severity == "error"]
    if read.project is None or errors:
        raise ProjectLoadError([d.model_copy(update={"file": file}) for d in errors or read.diagnostics])
    return read.project, [d.model_copy(update={"file": file}) for d in read.unkept]


def _error(file: str, message: str) -> ProjectLoadError:
    return ProjectLoadError([Diagnostic(code="BAD-PATH", file=file, message=message)])
