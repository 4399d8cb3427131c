"""The workspace: a folder of project folders, with revision-checked saves that commit as a whole."""

from __future__ import annotations

import contextlib
import os
import secrets
import shutil
import stat
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

from filelock import FileLock

from ..model import Diagnostic, Project
from . import journal
from .errors import AlreadyExistsError, ConflictError, NotFoundError, StorageError, StorageFullError
from .names import check_pou_name, check_project_name, check_test_file_name
from .project_folder import (
    EXERCISE_FILE,
    GVLS_DIR,
    HMI_DIR,
    POU_SUFFIXES,
    POUS_DIR,
    PROJECT_FILE,
    TEST_SUFFIX,
    TESTS_DIR,
    is_project_file,
    project_files,
    read_project_folder,
    revision_of,
)

LOCKS_DIR = ".locks"
TRASH_DIR = ".trash"  # deleted projects go here first (one rename), then are removed


@dataclass(frozen=True)
class ProjectInfo:
    """One entry of the project list; a project that does not load has ``problems`` and no revision."""

    name: str
    revision: str | None
    modified: float
    pou_count: int
    problems: list[Diagnostic] = field(default_factory=list)


@dataclass(frozen=True)
class StoredProject:
    project: Project
    revision: str
    modified: float


class Workspace:
    """Projects stored as folders under ``root``; every save states the revision it was based on.

    Opening a workspace finishes or drops any save a crash interrupted and removes stale
    temporary files and half-deleted projects (storage/journal.py)."""

    def __init__(self, root: Path | str) -> None:
        self.root = Path(root).resolve()
        self.root.mkdir(parents=True, exist_ok=True)
        self._locks_guard = threading.Lock()
        self._name_locks: dict[str, threading.Lock] = {}
        #: ``list``'s entries by project name, each with the fingerprint of the folder it was read from
        self._listed: dict[str, tuple[tuple[object, ...], ProjectInfo]] = {}
        self.recover()

    def folder(self, name: str) -> Path:
        """The folder of project ``name``; the name is validated so it cannot leave the workspace."""
        folder = (self.root / check_project_name(name)).resolve()
        if folder.parent != self.root:
            raise NotFoundError("project", name)
        return folder

    def exists(self, name: str) -> bool:
        return (self.folder(name) / PROJECT_FILE).is_file()

    def recover(self) -> None:
        """Finish or drop interrupted saves, remove stale temporary files and half-deleted projects."""
        for child in sorted(self.root.iterdir()):
            if child.name.startswith(".") or child.is_symlink() or not child.is_dir():
                continue
            try:
                with self._locked(child.name):
                    journal.recover(child, is_project_file)
                    _remove_if_empty(child)
            except StorageError:
                continue  # not a project name: not ours to touch
        trash = self.root / TRASH_DIR
        if trash.is_dir():
            shutil.rmtree(trash, ignore_errors=True)

    def names(self) -> list[str]:
        """The project folders' names, sorted, without loading them."""
        return sorted(
            child.name
            for child in self.root.iterdir()
            if not child.name.startswith(".") and (child / PROJECT_FILE).is_file()
        )

    def list(self) -> list[ProjectInfo]:
        """Every project folder by name; one that does not load is listed with its problems.

        A project is loaded (parsed and hashed) only when its folder changed since the last list: its entry is kept
        with the folder's fingerprint (``_fingerprint``), and taken again while the fingerprint is the same."""
        infos, listed = [], {}
        for name in self.names():
            child = self.root / name
            before = _fingerprint(child)
            known = self._listed.get(name)
            if before is not None and known is not None and known[0] == before:
                info = known[1]
            else:
                info = self._info(child)
            if before is not None and _fingerprint(child) == before:  # (unchanged while it was read)
                listed[name] = (before, info)
            infos.append(info)
        self._listed = listed
        return infos

    def _info(self, child: Path) -> ProjectInfo:
        try:
            stored = self.load(child.name)
        except StorageError as error:
            return ProjectInfo(child.name, None, _modified(child), 0, error.diagnostics)
        except OSError as error:
            problem = Diagnostic(code="BAD-FILE", message=f"cannot be read: {error.strerror or error}")
            return ProjectInfo(child.name, None, _modified(child), 0, [problem])
        return ProjectInfo(child.name, stored.revision, stored.modified, len(stored.project.pous))

    def load(self, name: str) -> StoredProject:
        with self._locked(name):
            return self._load(name)

    def _load(self, name: str) -> StoredProject:
        """The stored project (the caller holds its lock); named after its folder, whatever project.json says."""
        folder = self.folder(name)
        journal.recover(folder, is_project_file)
        if not (folder / PROJECT_FILE).is_file():
            raise NotFoundError("project", name)
        project = read_project_folder(folder)
        if project.name != name:  # a folder copied or renamed by hand, or a rename a crash interrupted
            project = project.model_copy(update={"name": name})
        return StoredProject(project, revision_of(project), _modified(folder))

    def create(self, project: Project) -> str:
        """Store a new project; refused when one with that name exists."""
        with self._locked(project.name):
            if self.exists(project.name):
                raise AlreadyExistsError("project", project.name)
            folder = self.folder(project.name)
            folder.mkdir(exist_ok=True)
            try:
                return self._write(project)
            except BaseException:
                _remove_if_empty(folder)
                raise

    def save(self, project: Project, base_revision: str | None) -> str:
        """Replace the stored project if it is still at ``base_revision``; returns the new revision."""
        with self._locked(project.name):
            current = self._load(project.name).revision
            if base_revision != current:
                raise ConflictError(project.name, base_revision, current)
            return self._write(project)

    def delete(self, name: str, base_revision: str | None = None) -> None:
        """Remove a project: one rename out of the workspace's list, then the files."""
        with self._locked(name):
            stored = self._load(name)
            if base_revision is not None and base_revision != stored.revision:
                raise ConflictError(name, base_revision, stored.revision)
            trash = self.root / TRASH_DIR
            trash.mkdir(exist_ok=True)
            doomed = trash / f"{name}.{secrets.token_hex(4)}"
            os.rename(self.folder(name), doomed)
            shutil.rmtree(doomed, ignore_errors=True)

    def rename(self, old: str, new: str, base_revision: str | None = None) -> str:
        """Rename a project (its folder and its ``name``); returns the new revision.

        The folder's rename is the change; project.json is saved with the new name afterwards,
        and until then (a crash in between) the folder name wins on load."""
        check_project_name(new)
        if new == old:
            raise AlreadyExistsError("project", new)
        with self._locked(old), self._locked(new):
            stored = self._load(old)
            if base_revision is not None and base_revision != stored.revision:
                raise ConflictError(old, base_revision, stored.revision)
            if os.path.lexists(self.folder(new)):
                raise AlreadyExistsError("project", new)
            os.rename(self.folder(old), self.folder(new))
            return self._write(stored.project.model_copy(update={"name": new}))

    def _write(self, project: Project) -> str:
        """Commit every changed file and the removal of the POU, test and panel files (and the exercise) the project
        no longer has, as one."""
        for pou in project.pous:
            check_pou_name(pou.name)
        for test in project.tests:
            check_test_file_name(test.name)
        folder = self.folder(project.name)
        files = {rel: content.encode("utf-8") for rel, content in project_files(project).items()}
        writes = {rel: data for rel, data in files.items() if not _holds(folder / rel, data)}
        pous_dir = folder / POUS_DIR
        deletes = []
        if pous_dir.is_dir():
            deletes = sorted(
                f"{POUS_DIR}/{path.name}"
                for path in pous_dir.iterdir()
                if path.name.endswith(POU_SUFFIXES)
                and f"{POUS_DIR}/{path.name}" not in files
                and is_project_file(f"{POUS_DIR}/{path.name}")
            )
        tests_dir = folder / TESTS_DIR  # test files the project no longer has; tests/hidden/ stays as it is
        if tests_dir.is_dir():
            deletes += sorted(
                f"{TESTS_DIR}/{path.name}"
                for path in tests_dir.iterdir()
                if path.is_file() and path.name.endswith(TEST_SUFFIX) and f"{TESTS_DIR}/{path.name}" not in files
            )
        for kept in (HMI_DIR, GVLS_DIR):  # panels and GVLs the project no longer has
            kept_dir = folder / kept
            if kept_dir.is_dir():
                deletes += sorted(
                    f"{kept}/{path.name}"
                    for path in kept_dir.iterdir()
                    if is_project_file(f"{kept}/{path.name}") and f"{kept}/{path.name}" not in files
                )
        if EXERCISE_FILE not in files and (folder / EXERCISE_FILE).is_file():
            deletes.append(EXERCISE_FILE)
        if writes or deletes:
            try:
                journal.commit(folder, writes, deletes, is_project_file)
            except journal.StagingFailed as error:
                if error.errno in journal.NO_SPACE:
                    raise StorageFullError(project.name, error.strerror or "the disk is full") from error
                raise
        return revision_of(project)

    @contextmanager
    def _locked(self, name: str) -> Iterator[None]:
        """Serialise the readers and writers of one project across threads and processes.

        The lock files live outside the project folder (``.locks/``), so they never show up in git;
        ``filelock`` locks them on Linux, macOS and Windows alike."""
        check_project_name(name)
        locks = self.root / LOCKS_DIR
        locks.mkdir(exist_ok=True)
        with self._thread_lock_for(name), FileLock(locks / f"{name}.lock"):
            yield

    def _thread_lock_for(self, name: str) -> threading.Lock:
        with self._locks_guard:
            return self._name_locks.setdefault(name, threading.Lock())


def _holds(path: Path, data: bytes) -> bool:
    """Whether ``path`` is a regular file with exactly ``data`` (an unchanged file is not rewritten)."""
    return path.is_file() and not path.is_symlink() and path.read_bytes() == data


def _remove_if_empty(folder: Path) -> None:
    """Remove a project folder a crash left without any file (a create that never committed)."""
    with contextlib.suppress(OSError):
        folder.rmdir()


def _fingerprint(folder: Path) -> tuple[object, ...] | None:
    """``folder`` and everything under it, each with its inode, size and modification and status change times
    (ns; the latter changes with permissions too): what a load reads, so an equal fingerprint means an equal load
    (a save writes files by rename: new inodes). None when a load must not be skipped: a journal of an interrupted
    save (the load finishes it), a symbolic link (its target may change without the folder changing), a folder
    that cannot be listed."""
    if (folder / journal.JOURNAL).exists():
        return None
    entries: list[object] = []

    def add(path: str) -> bool:
        try:
            found = os.lstat(path)
        except OSError:
            return False
        entries.append((path, found.st_ino, found.st_size, found.st_mtime_ns, found.st_ctime_ns))
        return not stat.S_ISLNK(found.st_mode)

    unlisted: list[OSError] = []
    if not add(str(folder)):
        return None
    for place, folders, files in os.walk(folder, onerror=unlisted.append):
        folders.sort()
        if not all(add(os.path.join(place, name)) for name in (*folders, *sorted(files))):
            return None
    return None if unlisted else tuple(entries)


def _modified(folder: Path) -> float:
    """Latest modification time of any project file (what a 409 dialog shows); the journal does not count."""
    times = [
        p.stat().st_mtime
        for p in (folder / PROJECT_FILE, folder / "types.st", folder / "globals.st", *_pou_files(folder))
        if p.is_file()
    ]
    return max(times, default=folder.stat().st_mtime)


def _pou_files(folder: Path) -> list[Path]:
    pous = folder / POUS_DIR
    return [p for p in pous.iterdir() if p.name.endswith(POU_SUFFIXES)] if pous.is_dir() else []
