"""A project as a folder of small, stable text files that diff well in git.

Layout::

    project.json        name, format, POU order, tasks
    types.st            TYPE ... END_TYPE blocks
    globals.st          VAR_GLOBAL ... END_VAR blocks
    pous/<name>.st      ST POUs as complete IEC text (PROGRAM ... END_PROGRAM)
    pous/<name>.ld.json / pous/<name>.fbd.json / pous/<name>.sfc.json   graphical POUs
    pous/<name>.st.json ST POUs whose text cannot be split back exactly (e.g. a VAR block
                        without END_VAR while the user is still typing); never loses a character
    tests/<name>.st     unit test files (docs/testing.md), as typed
    tests/hidden/       a teacher's hidden test files: not part of the model, kept as they are by saves,
                        read by ``hidden_tests`` for ``ladderlab test --grade``

JSON is pretty-printed with sorted keys so an unchanged POU gives an unchanged file.
"""

from __future__ import annotations

import hashlib
import json
import os
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from ..model import Diagnostic, Pou, Project, TestFile
from ..model.names import test_file_name_problem
from .errors import ProjectLoadError, json_text_problem, validation_diagnostics
from .st_text import StTextError, compose_pou_text, parse_pou_text, round_trips

PROJECT_FILE = "project.json"
TYPES_FILE = "types.st"
GLOBALS_FILE = "globals.st"
POUS_DIR = "pous"
POU_SUFFIXES = (".st", ".st.json", ".ld.json", ".fbd.json", ".sfc.json")
TESTS_DIR = "tests"
HIDDEN_TESTS_DIR = "tests/hidden"
TEST_SUFFIX = ".st"


def dump_json(data: Any) -> str:
    """The one JSON style of every stored file: sorted keys, 2-space indent, final newline."""
    return json.dumps(data, indent=2, sort_keys=True, ensure_ascii=False) + "\n"


def _text_file(text: str) -> str:
    return text + "\n" if text else ""


def project_files(project: Project) -> dict[str, str]:
    """Relative path -> content of every file the project is stored as."""
    files = {
        PROJECT_FILE: dump_json(
            {
                "format": project.format,
                "name": project.name,
                "pous": [p.name for p in project.pous],
                "tasks": [t.model_dump(mode="json", exclude_none=True) for t in project.tasks],
            }
        ),
        TYPES_FILE: _text_file(project.types),
        GLOBALS_FILE: _text_file(project.globals),
    }
    for pou in project.pous:
        files.update([pou_file(pou)])
    for test in project.tests:
        files[test_path(test.name)] = _text_file(test.text)
    return files


def test_path(name: str) -> str:
    return f"{TESTS_DIR}/{name}{TEST_SUFFIX}"


def pou_file(pou: Pou) -> tuple[str, str]:
    """The stored path and content of one POU."""
    if pou.language == "st" and round_trips(pou):
        return f"{POUS_DIR}/{pou.name}.st", compose_pou_text(pou)
    data = pou.model_dump(mode="json", by_alias=True, exclude_none=True)
    return f"{POUS_DIR}/{pou.name}.{pou.language}.json", dump_json(data)


def revision_of(project: Project) -> str:
    """A content hash: equal projects have equal revisions, whoever saved them."""
    canonical = json.dumps(project.model_dump(mode="json", by_alias=True), sort_keys=True)
    return hashlib.sha256(canonical.encode()).hexdigest()[:16]


def is_project_file(rel: str) -> bool:
    """Whether ``rel`` (``/``-separated) names a file a project folder may hold: saves write and delete only these."""
    if rel in (PROJECT_FILE, TYPES_FILE, GLOBALS_FILE):
        return True
    folder, _, name = rel.partition("/")
    if folder == TESTS_DIR:  # tests/<name>.st; never tests/hidden/ (a teacher's files, not the model's)
        return name.endswith(TEST_SUFFIX) and test_file_name_problem(name[: -len(TEST_SUFFIX)]) is None
    return (
        folder == POUS_DIR
        and name.endswith(POU_SUFFIXES)
        and not name.startswith(".")
        and "/" not in name
        and "\\" not in name
        and name not in (".", "..")
    )


def read_project_folder(folder: Path) -> Project:
    """Load a project folder; raises ProjectLoadError naming every bad file and JSON path.

    A symbolic link that leads out of the folder is refused (a project someone sent must not make
    LadderLab show or overwrite files elsewhere); links within the folder are followed."""
    problems: list[Diagnostic] = []
    if not _inside(folder, folder / POUS_DIR):
        raise ProjectLoadError([_outside(POUS_DIR)])
    meta = _read_json(folder / PROJECT_FILE, PROJECT_FILE, problems) if _inside(folder, folder / PROJECT_FILE) else None
    if meta is None and not problems:
        problems.append(_outside(PROJECT_FILE))
    if meta is None:
        raise ProjectLoadError(problems)
    if not isinstance(meta, dict):
        raise ProjectLoadError(
            [
                Diagnostic(
                    code="BAD-FILE",
                    file=PROJECT_FILE,
                    json_path="$",
                    message="expected an object with name, format, pous and tasks",
                )
            ]
        )
    order = meta.get("pous", [])
    if not isinstance(order, list) or not all(isinstance(n, str) for n in order):
        problems.append(
            Diagnostic(code="BAD-FILE", file=PROJECT_FILE, json_path="$.pous", message="expected a list of POU names")
        )
        order = []
    pous = [pou for pou in (_read_pou(folder, name, problems) for name in _pou_names(folder, order)) if pou]
    data = {
        "name": meta.get("name"),
        "format": meta.get("format"),
        "tasks": meta.get("tasks", []),
        "types": _read_text(folder, TYPES_FILE, problems),
        "globals": _read_text(folder, GLOBALS_FILE, problems),
    }
    project = None
    try:
        project = Project.model_validate({**data, "pous": []})
    except ValidationError as err:
        problems.extend(validation_diagnostics(err, meta, PROJECT_FILE))
    if problems:
        raise ProjectLoadError(problems)
    assert project is not None
    project.pous = pous
    project.tests = read_tests(folder / TESTS_DIR, TESTS_DIR, problems)
    if problems:
        raise ProjectLoadError(problems)
    return project


def read_tests(folder: Path, rel_dir: str, problems: list[Diagnostic] | None = None) -> list[TestFile]:
    """The test files of one folder (``tests`` or ``tests/hidden``), by name; unreadable ones are problems."""
    found: list[TestFile] = []
    if not folder.is_dir():
        return found
    for path in sorted(folder.iterdir()):
        if not path.is_file() or not path.name.endswith(TEST_SUFFIX) or path.name.startswith("."):
            continue
        name = path.name[: -len(TEST_SUFFIX)]
        rel = f"{rel_dir}/{path.name}"
        problem = test_file_name_problem(name)
        try:
            text = _read_exact(path)
        except UnicodeDecodeError as err:
            problem = f"not UTF-8 text: {err.reason}"
        if problem:
            if problems is not None:
                problems.append(Diagnostic(code="BAD-FILE", file=rel, message=f"cannot read this test file: {problem}"))
            continue
        found.append(TestFile(name=name, text=text))
    return found


def hidden_tests(folder: Path) -> list[TestFile]:
    """A teacher's hidden test files of a project folder (``tests/hidden/<name>.st``)."""
    return read_tests(folder / HIDDEN_TESTS_DIR, HIDDEN_TESTS_DIR)


def _pou_names(folder: Path, order: list[str]) -> list[str]:
    """POU names in project.json order, then any POU files added by hand (e.g. from git), sorted."""
    names = list(order)
    known = {n.upper() for n in names}
    pous_dir = folder / POUS_DIR
    if pous_dir.is_dir():
        for path in sorted(pous_dir.iterdir(), key=lambda p: p.name):
            name = _pou_name_of(path.name)
            if name and name.upper() not in known:
                names.append(name)
                known.add(name.upper())
    return names


def _pou_name_of(filename: str) -> str | None:
    for suffix in sorted(POU_SUFFIXES, key=len, reverse=True):
        if filename.endswith(suffix) and not filename.startswith("."):
            return filename[: -len(suffix)]
    return None


def pou_paths(folder: Path, name: str) -> list[Path]:
    return [p for p in (folder / POUS_DIR / f"{name}{s}" for s in POU_SUFFIXES) if p.is_file()]


def _read_pou(folder: Path, name: str, problems: list[Diagnostic]) -> Pou | None:
    paths = pou_paths(folder, name)
    if len(paths) != 1:
        message = (
            (f"POU {name!r} is listed in project.json but has no file pous/{name}.st, .ld.json, .fbd.json or .sfc.json")
            if not paths
            else (f"POU {name!r} has several files: {', '.join(p.name for p in paths)}; keep one")
        )
        problems.append(Diagnostic(code="BAD-FILE", file=f"{POUS_DIR}/{name}", pou=name, message=message))
        return None
    path = paths[0]
    rel = f"{POUS_DIR}/{path.name}"
    if not _inside(folder, path):
        problems.append(_outside(rel, name))
        return None
    if path.name.endswith(".json"):
        data = _read_json(path, rel, problems)
        if data is None:
            return None
        try:
            pou = Pou.model_validate(data)
        except ValidationError as err:
            problems.extend(validation_diagnostics(err, data, rel))
            return None
        expected_language = path.name[len(name) + 1 :].split(".")[0]
        if pou.language != expected_language:
            problems.append(
                Diagnostic(
                    code="BAD-FILE",
                    file=rel,
                    json_path="$.language",
                    pou=name,
                    message=f"expected language {expected_language!r} for a "
                    f"{path.name.split('.', 1)[1]} file, got {pou.language!r}",
                )
            )
            return None
    else:
        try:
            pou = parse_pou_text(_read_exact(path))
        except UnicodeDecodeError as err:
            problems.append(Diagnostic(code="BAD-FILE", file=rel, pou=name, message=f"not UTF-8 text: {err.reason}"))
            return None
        except StTextError as err:
            problems.append(
                Diagnostic(code="BAD-FILE", file=rel, pou=name, line=err.line, column=err.column, message=err.reason)
            )
            return None
    if pou.name != name:
        problems.append(
            Diagnostic(
                code="BAD-FILE",
                file=rel,
                pou=name,
                message=f"the file is named for POU {name!r} but declares {pou.name!r}",
            )
        )
        return None
    return pou


def _read_text(folder: Path, rel: str, problems: list[Diagnostic]) -> str:
    path = folder / rel
    if not path.is_file():
        return ""
    if not _inside(folder, path):
        problems.append(_outside(rel))
        return ""
    try:
        return _read_exact(path)
    except UnicodeDecodeError as err:
        problems.append(Diagnostic(code="BAD-FILE", file=rel, message=f"not UTF-8 text: {err.reason}"))
        return ""


def _inside(folder: Path, path: Path) -> bool:
    """Whether ``path`` (following links) stays inside ``folder``; a path that does not exist does."""
    if not os.path.lexists(path):
        return True
    return path.resolve().is_relative_to(folder.resolve())


def _outside(rel: str, pou: str | None = None) -> Diagnostic:
    return Diagnostic(
        code="BAD-FILE",
        file=rel,
        pou=pou,
        message="is a symbolic link that leads out of the project folder; LadderLab does not follow it",
    )


def _read_exact(path: Path) -> str:
    """UTF-8 text without newline translation: a '\\r' typed into a POU must come back as typed."""
    return path.read_bytes().decode("utf-8")


def _read_json(path: Path, rel: str, problems: list[Diagnostic]) -> Any:
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        problems.append(Diagnostic(code="BAD-FILE", file=rel, message="file is missing"))
        return None
    except UnicodeDecodeError as err:
        problems.append(Diagnostic(code="BAD-FILE", file=rel, message=f"not UTF-8 text: {err.reason}"))
        return None
    refused = json_text_problem(text, rel)
    if refused is not None:
        problems.append(refused)
        return None
    try:
        return json.loads(text)
    except json.JSONDecodeError as err:
        problems.append(
            Diagnostic(code="BAD-JSON", file=rel, line=err.lineno, column=err.colno, message=f"invalid JSON: {err.msg}")
        )
        return None
