"""The workspace: a folder of project folders, with revision-checked, atomic saves."""

from __future__ import annotations

import fcntl
import os
import shutil
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

from ..model import Project
from .atomic import fsync_dir, write_atomic
from .errors import AlreadyExistsError, ConflictError, NotFoundError
from .names import check_pou_name, check_project_name, check_test_file_name
from .project_folder import (
    POU_SUFFIXES,
    POUS_DIR,
    PROJECT_FILE,
    TEST_SUFFIX,
    TESTS_DIR,
    project_files,
    read_project_folder,
    revision_of,
)

LOCKS_DIR = ".locks"


@dataclass(frozen=True)
class ProjectInfo:
    name: str
    revision: str
    modified: float
    pou_count: int


@dataclass(frozen=True)
class StoredProject:
    project: Project
    revision: str
    modified: float


class Workspace:
    """Projects stored as folders under ``root``; every save states the revision it was based on."""

    def __init__(self, root: Path | str) -> None:
        self.root = Path(root).resolve()
        self.root.mkdir(parents=True, exist_ok=True)
        self._locks_guard = threading.Lock()
        self._name_locks: dict[str, threading.Lock] = {}

    def folder(self, name: str) -> Path:
        """The folder of project ``name``; the name is validated so it cannot leave the workspace."""
        folder = (self.root / check_project_name(name)).resolve()
        if folder.parent != self.root:
            raise NotFoundError("project", name)
        return folder

    def exists(self, name: str) -> bool:
        return (self.folder(name) / PROJECT_FILE).is_file()

    def list(self) -> list[ProjectInfo]:
        """Every loadable project, by name; broken folders are skipped here and reported by ``load``."""
        infos = []
        for child in sorted(self.root.iterdir()):
            if child.name.startswith(".") or not (child / PROJECT_FILE).is_file():
                continue
            try:
                stored = self.load(child.name)
            except Exception:
                continue
            infos.append(ProjectInfo(child.name, stored.revision, stored.modified, len(stored.project.pous)))
        return infos

    def load(self, name: str) -> StoredProject:
        folder = self.folder(name)
        if not (folder / PROJECT_FILE).is_file():
            raise NotFoundError("project", name)
        project = read_project_folder(folder)
        return StoredProject(project, revision_of(project), _modified(folder))

    def create(self, project: Project) -> str:
        """Store a new project; refused when one with that name exists."""
        with self._locked(project.name):
            if self.exists(project.name):
                raise AlreadyExistsError("project", project.name)
            return self._write(project)

    def save(self, project: Project, base_revision: str | None) -> str:
        """Replace the stored project if it is still at ``base_revision``; returns the new revision."""
        with self._locked(project.name):
            current = self.load(project.name).revision
            if base_revision != current:
                raise ConflictError(project.name, base_revision, current)
            return self._write(project)

    def delete(self, name: str, base_revision: str | None = None) -> None:
        with self._locked(name):
            stored = self.load(name)
            if base_revision is not None and base_revision != stored.revision:
                raise ConflictError(name, base_revision, stored.revision)
            shutil.rmtree(self.folder(name))

    def rename(self, old: str, new: str, base_revision: str | None = None) -> str:
        """Rename a project (its folder and its ``name``); returns the new revision."""
        check_project_name(new)
        if new == old:
            raise AlreadyExistsError("project", new)
        with self._locked(old), self._locked(new):
            stored = self.load(old)
            if base_revision is not None and base_revision != stored.revision:
                raise ConflictError(old, base_revision, stored.revision)
            if self.exists(new):
                raise AlreadyExistsError("project", new)
            os.rename(self.folder(old), self.folder(new))
            return self._write(stored.project.model_copy(update={"name": new}))

    def _write(self, project: Project) -> str:
        """Write every changed file atomically, then drop POU files the project no longer has."""
        for pou in project.pous:
            check_pou_name(pou.name)
        for test in project.tests:
            check_test_file_name(test.name)
        folder = self.folder(project.name)
        files = project_files(project)
        for rel, content in files.items():
            path = folder / rel
            data = content.encode("utf-8")
            if not path.is_file() or path.read_bytes() != data:
                write_atomic(path, data)
        pous_dir = folder / POUS_DIR
        if pous_dir.is_dir():
            for path in pous_dir.iterdir():
                rel = f"{POUS_DIR}/{path.name}"
                if path.name.endswith(POU_SUFFIXES) and rel not in files:
                    path.unlink()
            fsync_dir(pous_dir)
        tests_dir = folder / TESTS_DIR  # test files the project no longer has; tests/hidden/ stays as it is
        if tests_dir.is_dir():
            for path in tests_dir.iterdir():
                if path.is_file() and path.name.endswith(TEST_SUFFIX) and f"{TESTS_DIR}/{path.name}" not in files:
                    path.unlink()
            fsync_dir(tests_dir)
        return revision_of(project)

    @contextmanager
    def _locked(self, name: str) -> Iterator[None]:
        """Serialise writers of one project across threads and processes (lock files live outside it)."""
        check_project_name(name)
        locks = self.root / LOCKS_DIR
        locks.mkdir(exist_ok=True)
        with self._thread_lock_for(name), open(locks / f"{name}.lock", "w") as handle:
            fcntl.flock(handle, fcntl.LOCK_EX)
            try:
                yield
            finally:
                fcntl.flock(handle, fcntl.LOCK_UN)

    def _thread_lock_for(self, name: str) -> threading.Lock:
        with self._locks_guard:
            return self._name_locks.setdefault(name, threading.Lock())


def _modified(folder: Path) -> float:
    """Latest modification time of any file of the project (what a 409 dialog shows)."""
    times = [p.stat().st_mtime for p in folder.rglob("*") if p.is_file()]
    return max(times, default=folder.stat().st_mtime)
