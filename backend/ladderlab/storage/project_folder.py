"""A project as a folder of small, stable text files that diff well in git.

Layout::

    project.json        name, format, POU order, tasks, configuration, vendor libraries used, typing
    types.st            TYPE ... END_TYPE blocks
    globals.st          VAR_GLOBAL ... END_VAR blocks (the globals of no named list)
    gvls/<name>.st      a named global variable list: its VAR_GLOBAL blocks, under {attribute 'qualified_only'}
                        when it has it, as CODESYS shows a GVL (project.json lists their order)
    pous/<name>.st      ST POUs as complete IEC text (PROGRAM ... END_PROGRAM)
    pous/<name>.plant.st ST plants (a PROGRAM in IEC text; the file name makes it a plant)
    pous/<name>.il      IL POUs as complete IEC text, the body in IL (docs/il.md)
    pous/<name>.ld.json / .fbd.json / .cfc.json / .sfc.json   graphical POUs
    pous/<name>.st.json ST (.il.json: IL) POUs whose text cannot be split back exactly (e.g. a VAR block
                        without END_VAR while the user is still typing); never loses a character
    hmi/<name>.json     operator panels (project.json lists their order)
    EXERCISE.md         the statement of the exercise, when the project is one
    tests/<name>.st     unit test files (docs/testing.md), as typed
    tests/hidden/       a teacher's hidden test files: not part of the model, kept as they are by saves,
                        read by ``hidden_tests`` for ``ladderlab test --grade``

JSON is pretty-printed with sorted keys so an unchanged POU gives an unchanged file.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from ..model import Diagnostic, GlobalVariableList, Panel, Pou, Project, Task, TestFile
from ..model.names import pou_name_problem, test_file_name_problem
from ..model.project import QUALIFIED_ONLY, TEXT_LANGUAGES
from .errors import ProjectLoadError, json_text_problem, validation_diagnostics
from .st_text import StTextError, compose_pou_text, parse_pou_text, round_trips
from .text_files import HINT, decode_text

PROJECT_FILE = "project.json"
TYPES_FILE = "types.st"
GLOBALS_FILE = "globals.st"
POUS_DIR = "pous"
POU_SUFFIXES = (".st", ".plant.st", ".st.json", ".il", ".il.json", ".ld.json", ".fbd.json", ".cfc.json", ".sfc.json")
HMI_DIR = "hmi"
GVLS_DIR = "gvls"
EXERCISE_FILE = "EXERCISE.md"
TESTS_DIR = "tests"
HIDDEN_TESTS_DIR = "tests/hidden"
TEST_SUFFIX = ".st"


def dump_json(data: Any) -> str:
    """The one JSON style of every stored file: sorted keys, 2-space indent, final newline."""
    return json.dumps(data, indent=2, sort_keys=True, ensure_ascii=False) + "\n"


def _task(task: Task) -> dict[str, Any]:
    """A task as project.json holds it; ``single`` and ``watchdog_ms`` only when set, so files of cyclic tasks stay
    as they were (``interval`` stays even when null: null means a SINGLE task without an interval)."""
    data = task.model_dump(mode="json")
    for optional in ("single", "watchdog_ms"):
        if data[optional] is None:
            del data[optional]
    return data


def _text_file(text: str) -> str:
    return text + "\n" if text else ""


def project_files(project: Project) -> dict[str, str]:
    """Relative path -> content of every file the project is stored as."""
    meta: dict[str, Any] = {
        "format": project.format,
        "name": project.name,
        "pous": [p.name for p in project.pous],
        "tasks": [_task(t) for t in project.tasks],
    }
    if project.configuration is not None:
        configuration = project.configuration.model_dump(mode="json")
        for resource, stored in zip(project.configuration.resources, configuration["resources"], strict=True):
            stored["tasks"] = [_task(t) for t in resource.tasks]
        meta["configuration"] = configuration
    if project.panels:
        meta["panels"] = [p.name for p in project.panels]
    if project.gvls:
        meta["gvls"] = [g.name for g in project.gvls]
    if project.libraries:
        meta["libraries"] = list(project.libraries)
    if project.typing != "iec":
        meta["typing"] = project.typing
    files = {
        PROJECT_FILE: dump_json(meta),
        TYPES_FILE: _text_file(project.types),
        GLOBALS_FILE: _text_file(project.globals),
    }
    for gvl in project.gvls:
        files[gvl_path(gvl.name)] = gvl_text(gvl)
    for pou in project.pous:
        files.update([pou_file(pou)])
    for panel in project.panels:
        files[f"{HMI_DIR}/{panel.name}.json"] = dump_json(panel.model_dump(mode="json", exclude_defaults=True))
    if project.exercise:
        files[EXERCISE_FILE] = _text_file(project.exercise)
    for test in project.tests:
        files[test_path(test.name)] = _text_file(test.text)
    return files


def gvl_path(name: str) -> str:
    return f"{GVLS_DIR}/{name}.st"


def gvl_text(gvl: GlobalVariableList) -> str:
    """A GVL file: its text under the qualified_only pragma when it has it, as the list reads in CODESYS."""
    return _text_file("\n".join(filter(None, [QUALIFIED_ONLY if gvl.qualified_only else "", gvl.text])))


def test_path(name: str) -> str:
    return f"{TESTS_DIR}/{name}{TEST_SUFFIX}"


#: The object orientation's fields of a POU (and its actions), left out of its file when they hold their defaults.
OO_KEYS = ("methods", "properties", "actions", "implements", "abstract", "final")


def pou_file(pou: Pou) -> tuple[str, str]:
    """The stored path and content of one POU."""
    if pou.language in TEXT_LANGUAGES and round_trips(pou):
        suffix = ".plant.st" if pou.kind == "plant" else f".{pou.language}"
        return f"{POUS_DIR}/{pou.name}{suffix}", compose_pou_text(pou)
    data = pou.model_dump(mode="json", by_alias=True, exclude_none=True)
    for key in OO_KEYS:  # only FBs that use object orientation carry these: other POUs' files stay as they were
        if not data[key]:
            del data[key]
    return f"{POUS_DIR}/{pou.name}.{pou.language}.json", dump_json(data)


def revision_of(project: Project) -> str:
    """A content hash: equal projects have equal revisions, whoever saved them. Test files are files, without
    an order: they count in the order a load reads them (by file name), so a save returns the revision the
    saved folder has (a browser that added ``b`` after ``c`` would otherwise conflict with its own save)."""
    data = project.model_dump(mode="json", by_alias=True)
    data["tests"] = sorted(data["tests"], key=lambda test: test_path(test["name"]))
    canonical = json.dumps(data, sort_keys=True)
    return hashlib.sha256(canonical.encode()).hexdigest()[:16]


def is_project_file(rel: str) -> bool:
    """Whether ``rel`` (``/``-separated) names a file a project folder may hold: saves write and delete only these."""
    if rel in (PROJECT_FILE, TYPES_FILE, GLOBALS_FILE, EXERCISE_FILE):
        return True
    folder, _, name = rel.partition("/")
    if folder == GVLS_DIR:  # gvls/<name>.st, a GVL's name
        return name.endswith(".st") and pou_name_problem(name[: -len(".st")]) is None
    if folder == HMI_DIR:  # hmi/<name>.json, a panel's name
        return name.endswith(".json") and re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]{0,63}\.json", name) is not None
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


def read_project_folder(folder: Path, encoding: str | None = None, hint: str = HINT) -> Project:
    """Load a project folder; raises ProjectLoadError naming every bad file and JSON path.

    Its files are UTF-8 unless ``encoding`` says otherwise (text_files.py: a file that does not decode is a
    located BAD-ENCODING error; ``hint`` says what to do about it). A symbolic link that leads out of the
    folder is refused (a project someone sent must not make LadderLab show or overwrite files elsewhere);
    links within the folder are followed."""
    problems: list[Diagnostic] = []
    read = _Reader(folder, encoding, hint, problems)
    if not _inside(folder, folder / POUS_DIR):
        raise ProjectLoadError([_outside(POUS_DIR)])
    meta = read.json(folder / PROJECT_FILE, PROJECT_FILE) if _inside(folder, folder / PROJECT_FILE) else None
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
    pous = [pou for pou in (_read_pou(folder, name, read) for name in _pou_names(folder, order)) if pou]
    panels = _read_panels(read, meta.get("panels", []))
    gvls = _read_gvls(read, meta.get("gvls", []))
    data = {
        "name": meta.get("name"),
        "format": meta.get("format"),
        "tasks": meta.get("tasks", []),
        "configuration": meta.get("configuration"),
        "types": read.text(folder / TYPES_FILE, TYPES_FILE) or "",
        "globals": read.text(folder / GLOBALS_FILE, GLOBALS_FILE) or "",
        "exercise": read.text(folder / EXERCISE_FILE, EXERCISE_FILE) or "",
        "libraries": meta.get("libraries", []),
        "typing": meta.get("typing", "iec"),
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
    project.panels = panels
    project.gvls = gvls
    project.tests = _read_tests(read, TESTS_DIR)
    if problems:
        raise ProjectLoadError(problems)
    return project


def _read_tests(read: _Reader, rel_dir: str) -> list[TestFile]:
    """The test files of one folder of the project (``tests`` or ``tests/hidden``), by name; unreadable ones are
    problems of ``read``."""
    found: list[TestFile] = []
    folder = read.folder / rel_dir
    if not folder.is_dir():
        return found
    for path in sorted(folder.iterdir()):
        if not path.is_file() or not path.name.endswith(TEST_SUFFIX) or path.name.startswith("."):
            continue
        name = path.name[: -len(TEST_SUFFIX)]
        rel = f"{rel_dir}/{path.name}"
        problem = test_file_name_problem(name)
        if problem:
            read.problems.append(
                Diagnostic(code="BAD-FILE", file=rel, message=f"cannot read this test file: {problem}")
            )
            continue
        text = read.text(path, rel)
        if text is not None:
            found.append(TestFile(name=name, text=text))
    return found


def hidden_tests(folder: Path, encoding: str | None = None) -> list[TestFile]:
    """A teacher's hidden test files of a project folder (``tests/hidden/<name>.st``); unreadable ones are left
    out (the grade counts what runs)."""
    return _read_tests(_Reader(folder, encoding, HINT, []), HIDDEN_TESTS_DIR)


def _read_gvls(read: _Reader, order: object) -> list[GlobalVariableList]:
    """The GVLs in project.json order, then any other ``gvls/*.st`` (added by hand), sorted."""
    folder, problems = read.folder, read.problems
    if not isinstance(order, list) or not all(isinstance(n, str) for n in order):
        message = "expected a list of global variable list names"
        problems.append(Diagnostic(code="BAD-FILE", file=PROJECT_FILE, json_path="$.gvls", message=message))
        return []
    bad = [name for name in order if not is_project_file(gvl_path(name))]
    if bad:
        message = f"{bad[0]!r} is not a global variable list name: {pou_name_problem(bad[0])}"
        problems.append(Diagnostic(code="BAD-FILE", file=PROJECT_FILE, json_path="$.gvls", message=message))
        return []
    gvls_dir = folder / GVLS_DIR
    if not _inside(folder, gvls_dir):
        problems.append(_outside(GVLS_DIR))
        return []
    listed = sorted(p.name for p in gvls_dir.iterdir()) if gvls_dir.is_dir() else []
    found = [name[: -len(".st")] for name in listed if is_project_file(f"{GVLS_DIR}/{name}")]
    known = {name.upper() for name in order}
    names = list(dict.fromkeys([*order, *(n for n in found if n.upper() not in known)]))
    gvls = []
    for name in names:
        rel = gvl_path(name)
        if not (folder / rel).is_file():
            message = f"global variable list {name!r} is listed in project.json but has no file {rel}"
            problems.append(Diagnostic(code="BAD-FILE", file=rel, message=message))
            continue
        text = read.text(folder / rel, rel)
        if text is not None:
            gvls.append(GlobalVariableList(name=name, text=text))  # its pragma line sets the flag
    return gvls


def _read_panels(read: _Reader, order: object) -> list[Panel]:
    """The panels in project.json order, then any other ``hmi/*.json`` (added by hand), sorted."""
    folder, problems = read.folder, read.problems
    if not isinstance(order, list) or not all(isinstance(n, str) for n in order):
        problems.append(
            Diagnostic(
                code="BAD-FILE", file=PROJECT_FILE, json_path="$.panels", message="expected a list of panel names"
            )
        )
        order = []
    bad = [name for name in order if not is_project_file(f"{HMI_DIR}/{name}.json")]
    if bad:
        message = f"{bad[0]!r} is not a panel name (letters, digits and _, not starting with a digit)"
        problems.append(Diagnostic(code="BAD-FILE", file=PROJECT_FILE, json_path="$.panels", message=message))
        return []
    hmi = folder / HMI_DIR
    if not _inside(folder, hmi):
        problems.append(_outside(HMI_DIR))
        return []
    listed = sorted(p.name for p in hmi.iterdir()) if hmi.is_dir() else []
    found = [name[: -len(".json")] for name in listed if is_project_file(f"{HMI_DIR}/{name}")]
    names = list(dict.fromkeys([*order, *(n for n in found if n not in order)]))
    panels = []
    for name in names:
        rel = f"{HMI_DIR}/{name}.json"
        if not _inside(folder, folder / rel):
            problems.append(_outside(rel))
            continue
        data = read.json(folder / rel, rel)
        if data is None:
            continue
        try:
            panel = Panel.model_validate(data)
        except ValidationError as err:
            problems.extend(validation_diagnostics(err, data, rel))
            continue
        if panel.name != name:
            problems.append(
                Diagnostic(
                    code="BAD-FILE",
                    file=rel,
                    json_path="$.name",
                    message=f"the file is named for panel {name!r} but holds {panel.name!r}",
                )
            )
            continue
        panels.append(panel)
    return panels


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


def read_pou_file(path: Path) -> Pou:
    """One POU file alone (e.g. an exercise's starting file); ProjectLoadError naming the file."""
    problems: list[Diagnostic] = []
    name = _pou_name_of(path.name)
    pou = _read_pou(path.parent.parent, name, _Reader(path.parent.parent, None, HINT, problems)) if name else None
    if pou is None:
        message = (
            f"{path.name} is not a POU file (.st, .plant.st, .il, .ld.json, .fbd.json, .cfc.json, .sfc.json, .st.json)"
        )
        raise ProjectLoadError(problems or [Diagnostic(code="BAD-FILE", file=path.name, message=message)])
    return pou


def pou_paths(folder: Path, name: str) -> list[Path]:
    return [p for p in (folder / POUS_DIR / f"{name}{s}" for s in POU_SUFFIXES) if p.is_file()]


def _read_pou(folder: Path, name: str, read: _Reader) -> Pou | None:
    problems = read.problems
    paths = pou_paths(folder, name)
    if len(paths) != 1:
        message = (
            (
                f"POU {name!r} is listed in project.json but has no file pous/{name}.st, .il, .ld.json, .fbd.json, "
                ".cfc.json or .sfc.json"
            )
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
        data = read.json(path, rel)
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
        text = read.text(path, rel, pou=name)
        if text is None:
            return None
        try:
            pou = parse_pou_text(text, language=path.suffix[1:], plant=path.name.endswith(".plant.st"))
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


class _Reader:
    """Reads the files of one project folder in one encoding, collecting every problem."""

    def __init__(self, folder: Path, encoding: str | None, hint: str, problems: list[Diagnostic]):
        self.folder, self.encoding, self.hint, self.problems = folder, encoding, hint, problems

    def text(self, path: Path, rel: str, pou: str | None = None) -> str | None:
        """A text file exactly as stored (no newline translation: a '\\r' typed into a POU comes back as typed);
        "" when it is missing, None when it leads out of the folder or does not decode (reported)."""
        if not path.is_file():
            return ""
        if not _inside(self.folder, path):
            self.problems.append(_outside(rel, pou))
            return None
        try:
            return decode_text(path.read_bytes(), rel, self.encoding, self.hint)
        except ProjectLoadError as err:
            self.problems.extend(d.model_copy(update={"pou": pou}) for d in err.diagnostics)
            return None

    def json(self, path: Path, rel: str) -> Any:
        if not path.is_file():
            self.problems.append(Diagnostic(code="BAD-FILE", file=rel, message="file is missing"))
            return None
        text = self.text(path, rel)
        if text is None:
            return None
        refused = json_text_problem(text, rel)
        if refused is not None:
            self.problems.append(refused)
            return None
        try:
            return json.loads(text)
        except json.JSONDecodeError as err:
            self.problems.append(
                Diagnostic(
                    code="BAD-JSON", file=rel, line=err.lineno, column=err.colno, message=f"invalid JSON: {err.msg}"
                )
            )
            return None
