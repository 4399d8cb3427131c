"""Saves of several files that commit as a whole: a redo journal inside the project folder.

A save first writes every changed file into ``<project>/.ladderlab-save/`` and then the list of
what it changes (``COMMIT``: files to move into place, files to delete), written under a temporary
name, fsynced and renamed: that rename is the commit point. Only then are the staged files renamed
over their targets (each rename is atomic), the deleted files unlinked and the journal removed.

``recover`` runs before a project is read (and for every project when a workspace is opened): a
journal with ``COMMIT`` is finished (renaming a staged file that was already moved finds nothing to
do), one without it is dropped. So after a crash, a kill -9 or a power cut at any moment the folder
holds exactly the old or exactly the new revision, and a disk that fills up while staging leaves
the old files untouched. The journal lives in the project folder, so it moves with the folder and
a rename is never across file systems; its name starts with a dot, so the loader ignores it.
"""

from __future__ import annotations

import contextlib
import errno
import json
import os
import re
import shutil
from collections.abc import Callable
from pathlib import Path

from .atomic import fsync_dir

JOURNAL = ".ladderlab-save"
COMMIT = "COMMIT"
#: Temporary files of ``write_atomic`` (``.<name>.<random>.tmp``) a crash may have left behind.
_STALE_TEMP = re.compile(r"^\..+\.tmp\Z")
#: errno values that mean "no room on the disk" (507 for the server).
NO_SPACE = frozenset({errno.ENOSPC, getattr(errno, "EDQUOT", errno.ENOSPC), errno.EFBIG})


#: Whether a path relative to the project folder is one the project may hold.
Allowed = Callable[[str], bool]


class StagingFailed(OSError):
    """Writing the new version failed before the commit point; nothing of the project changed."""


def commit(folder: Path, writes: dict[str, bytes], deletes: list[str], allowed: Allowed) -> None:
    """Replace the files ``writes`` (relative path -> content) and remove ``deletes``, all or nothing.

    ``allowed(rel)`` says whether a relative path is one the project may hold; recovery checks every
    path of a journal with it, so a crafted journal in a folder someone sent cannot write elsewhere.
    The caller holds the project's lock."""
    for rel in [*writes, *deletes]:
        if not allowed(rel):
            raise ValueError(f"not a project file: {rel!r}")
    journal = folder / JOURNAL
    _remove(journal)
    try:
        journal.mkdir(parents=True)
        staged = []
        for number, (rel, data) in enumerate(writes.items()):
            name = f"{number}.new"
            _write_synced(journal / name, data)
            staged.append([name, rel])
        manifest = json.dumps({"write": staged, "delete": list(deletes)}).encode()
        _write_synced(journal / f"{COMMIT}.tmp", manifest)
        fsync_dir(journal)
        os.replace(journal / f"{COMMIT}.tmp", journal / COMMIT)  # the commit point
    except OSError as error:
        _remove(journal)
        raise StagingFailed(error.errno, error.strerror or str(error)) from error
    fsync_dir(journal)
    _apply(folder, journal, staged, list(deletes))


def recover(folder: Path, allowed: Allowed) -> str | None:
    """Finish or drop an interrupted save of ``folder`` and remove stale temporary files.

    Returns "replayed" or "dropped" when there was a journal, else None. The caller holds the lock."""
    journal = folder / JOURNAL
    outcome = None
    if journal.is_symlink() or journal.is_file():
        journal.unlink()
        outcome = "dropped"
    elif journal.is_dir():
        manifest = _manifest(journal / COMMIT, allowed)
        if manifest is None:
            _remove(journal)
            outcome = "dropped"
        else:
            _apply(folder, journal, *manifest)
            outcome = "replayed"
    for place in (folder, folder / "pous"):
        if place.is_dir() and not place.is_symlink():
            for path in place.iterdir():
                if _STALE_TEMP.match(path.name) and path.is_file():
                    path.unlink(missing_ok=True)
    return outcome


def pending(folder: Path) -> bool:
    """Whether ``folder`` holds a journal (an interrupted save) that ``recover`` would act on."""
    return os.path.lexists(folder / JOURNAL)


def _manifest(path: Path, allowed: Allowed) -> tuple[list[list[str]], list[str]] | None:
    """The committed changes, or None when the journal never reached its commit point (or is not ours)."""
    try:
        data = json.loads(path.read_bytes())
        writes, deletes = data["write"], data["delete"]
        ok = all(
            isinstance(pair, list) and len(pair) == 2 and re.fullmatch(r"\d+\.new", pair[0]) and allowed(pair[1])
            for pair in writes
        ) and all(isinstance(rel, str) and allowed(rel) for rel in deletes)
    except (OSError, ValueError, KeyError, TypeError):
        return None
    return (writes, deletes) if ok else None


def _apply(folder: Path, journal: Path, writes: list[list[str]], deletes: list[str]) -> None:
    """Move the staged files into place, delete the removed ones, drop the journal (idempotent)."""
    touched = {folder}
    for name, rel in writes:
        staged, target = journal / name, folder / rel
        if os.path.lexists(staged):
            target.parent.mkdir(parents=True, exist_ok=True)
            os.replace(staged, target)
            touched.add(target.parent)
    for rel in deletes:
        (folder / rel).unlink(missing_ok=True)
        touched.add((folder / rel).parent)
    for place in touched:
        if place.is_dir():
            fsync_dir(place)
    _remove(journal)
    fsync_dir(folder)


def _write_synced(path: Path, data: bytes) -> None:
    with open(path, "wb") as handle:
        handle.write(data)
        handle.flush()
        os.fsync(handle.fileno())


def _remove(path: Path) -> None:
    if path.is_symlink() or path.is_file():
        path.unlink()
    elif path.is_dir():
        with contextlib.suppress(FileNotFoundError):
            shutil.rmtree(path)
