"""Saves commit as a whole (issue 18): a crash at any step leaves exactly the old or the new revision.

The deterministic half of the crash tests: every file-system step of a save (staging writes,
fsyncs, renames, unlinks, removals) is made to "crash" in turn, the workspace is reopened, and the
folder must hold byte for byte the files of one of the two revisions. tests/server/test_crash_safety.py
kills a real server process at random moments.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from ladderlab.model import Pou, Project
from ladderlab.storage import Workspace, journal, load_project_path
from ladderlab.storage.project_folder import is_project_file, project_files
from tests.support import EXAMPLES


class Crash(BaseException):
    """A kill -9 at this point: nothing after it runs, not even cleanup handlers that catch Exception."""


def files_of(folder: Path) -> dict[str, bytes]:
    return {p.relative_to(folder).as_posix(): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


def expected_files(project: Project) -> dict[str, bytes]:
    return {rel: text.encode() for rel, text in project_files(project).items()}


def st(name: str, body: str) -> Pou:
    return Pou(name=name, kind="program", language="st", declarations="VAR\n  x : INT;\nEND_VAR", body=body)


OLD = Project(name="p", types="TYPE Mode : (A, B); END_TYPE", pous=[st("Keep", "x := 1;"), st("Gone", "x := 2;")])
NEW = Project(
    name="p",
    globals="VAR_GLOBAL\n  g : INT;\nEND_VAR",
    pous=[st("Keep", "x := 3;"), *(st(f"Added{i}", f"x := {i};") for i in range(4))],
)


class CrashAt:
    """Counts file-system steps of the storage code; raises Crash at step ``at`` (never when None)."""

    def __init__(self, monkeypatch: pytest.MonkeyPatch, at: int | None) -> None:
        self.at, self.steps = at, 0
        for name in ("replace", "fsync", "unlink", "rmdir", "mkdir", "rename"):
            monkeypatch.setattr(os, name, self._wrap(getattr(os, name)))
        real_write = journal._write_synced

        def write(path: Path, data: bytes) -> None:
            if self._step():  # crash half way through the file
                path.write_bytes(data[: len(data) // 2])
                raise Crash
            real_write(path, data)

        monkeypatch.setattr(journal, "_write_synced", write)

    def _step(self) -> bool:
        self.steps += 1
        return self.steps == self.at

    def _wrap(self, real):
        def step(*args, **kwargs):
            if self._step():
                raise Crash
            return real(*args, **kwargs)

        return step


def crash_at(monkeypatch: pytest.MonkeyPatch, root: Path, at: int, action) -> bool:
    """Store OLD in a new workspace at ``root``, then run ``action(workspace, revision)`` crashing at step ``at``;
    whether it crashed."""
    ws = Workspace(root)
    revision = ws.create(OLD)
    with monkeypatch.context() as m:
        CrashAt(m, at)
        try:
            action(ws, revision)
        except Crash:
            return True
    return False


def test_a_crash_at_every_step_of_a_save_leaves_the_old_or_the_new_revision(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    ws = Workspace(tmp_path / "count")
    base = ws.create(OLD)
    with monkeypatch.context() as m:
        counter = CrashAt(m, None)
        ws.save(NEW, base)
        steps = counter.steps
    assert steps > 10
    outcomes = []
    for at in range(1, steps + 1):
        root = tmp_path / f"ws{at}"
        assert crash_at(monkeypatch, root, at, lambda ws, revision: ws.save(NEW, revision)), f"step {at} ran to the end"
        reopened = Workspace(root)  # a server starting again: recovery runs
        stored = reopened.load("p")
        folder = root / "p"
        assert stored.project in (OLD, NEW), f"crash at step {at}: a mix of revisions"
        assert files_of(folder) == expected_files(stored.project), f"crash at step {at}: files left over"
        outcomes.append("new" if stored.project == NEW else "old")
    assert outcomes[0] == "old" and outcomes[-1] == "new"
    assert outcomes == sorted(outcomes, key=["old", "new"].index), "once committed, a save stays committed"


def test_a_crash_while_creating_leaves_no_project_or_the_whole_project(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    for at in range(1, 40):
        root = tmp_path / f"ws{at}"
        ws = Workspace(root)
        with monkeypatch.context() as m:
            counter = CrashAt(m, at)
            try:
                ws.create(OLD)
                finished = True
            except Crash:
                finished = False
        reopened = Workspace(root)
        if reopened.exists("p"):
            assert reopened.load("p").project == OLD
            assert files_of(root / "p") == expected_files(OLD)
        else:
            assert not finished
            assert not (root / "p").exists(), "an empty folder of a create that never committed is removed"
        if finished:
            assert counter.steps < at
            break
    else:
        pytest.fail("the create never finished")


def test_a_crash_while_deleting_leaves_the_project_or_nothing(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    for at in (1, 2, 3, 5, 8):
        root = tmp_path / f"ws{at}"
        crash_at(monkeypatch, root, at, lambda ws, revision: ws.delete("p", revision))
        reopened = Workspace(root)
        assert [i.name for i in reopened.list()] in ([], ["p"])
        if reopened.exists("p"):
            assert reopened.load("p").project == OLD
        assert not (root / ".trash").exists(), "half-deleted projects are removed on start"


def test_recovery_refuses_a_journal_that_names_files_outside_the_project(tmp_path: Path) -> None:
    """A project folder someone sent may hold a crafted journal: it must not write anywhere else."""
    ws = Workspace(tmp_path / "ws")
    ws.create(OLD)
    folder = ws.root / "p"
    crafted = folder / journal.JOURNAL
    crafted.mkdir()
    (crafted / "0.new").write_text("owned")
    (crafted / journal.COMMIT).write_text('{"write": [["0.new", "../../escaped.txt"]], "delete": ["../victim"]}')
    (tmp_path / "victim").write_text("keep me")
    Workspace(ws.root)
    assert not (tmp_path / "escaped.txt").exists()
    assert (tmp_path / "victim").read_text() == "keep me"
    assert not crafted.exists(), "an invalid journal is dropped"
    assert ws.load("p").project == OLD


@pytest.mark.parametrize(
    ("rel", "allowed"),
    [
        ("project.json", True),
        ("types.st", True),
        ("pous/Main.st", True),
        ("pous/Main.ld.json", True),
        ("pous/../x.st", False),
        ("pous/.hidden.st", False),
        ("pous/a/b.st", False),
        ("../project.json", False),
        ("pous/Main.py", False),
        ("/etc/passwd", False),
    ],
)
def test_only_project_files_may_be_written_by_a_save(rel: str, allowed: bool) -> None:
    assert is_project_file(rel) is allowed


def test_stale_temporary_files_are_removed_on_start(tmp_path: Path) -> None:
    ws = Workspace(tmp_path / "ws")
    ws.create(OLD)
    folder = ws.root / "p"
    for stale in (folder / ".project.json.k2j3h4.tmp", folder / "pous" / ".Keep.st.abc123.tmp"):
        stale.write_text("half")
    (folder / journal.JOURNAL).mkdir()
    (folder / journal.JOURNAL / "0.new").write_text("uncommitted")
    (folder / "notes.txt").write_text("the user's own file stays")
    Workspace(ws.root)
    assert sorted(files_of(folder)) == sorted([*expected_files(OLD), "notes.txt"])


def test_the_cli_reads_an_interrupted_save_as_exactly_one_revision(tmp_path: Path) -> None:
    """``ladderlab check FOLDER`` on a folder whose save was cut off after the commit point."""
    ws = Workspace(tmp_path / "ws")
    ws.create(OLD)
    folder = ws.root / "p"
    writes = {rel: data for rel, data in expected_files(NEW).items() if files_of(folder).get(rel) != data}
    deletes = sorted(set(files_of(folder)) - set(expected_files(NEW)))
    journal.commit(folder, writes, deletes, is_project_file)
    assert load_project_path(folder) == NEW
    staged = folder / journal.JOURNAL
    staged.mkdir()
    (staged / "0.new").write_text("PROGRAM Keep\nEND_PROGRAM\n")
    (staged / journal.COMMIT).write_text('{"write": [["0.new", "pous/Keep.st"]], "delete": []}')
    os.replace(staged / "0.new", folder / "pous" / "Keep.st")  # the crash came after the first rename
    assert load_project_path(folder).pou("Keep").body == ""
    assert not staged.exists()


# ----------------------------------------------------------------- locks (issue 19 item 6: filelock)


def test_the_project_lock_excludes_threads_and_other_processes(tmp_path: Path) -> None:
    ws = Workspace(tmp_path / "ws")
    ws.create(OLD)
    order: list[str] = []
    with ws._locked("p"):
        reader = threading.Thread(target=lambda: order.append(f"loaded {ws.load('p').project.name}"))
        reader.start()
        other = threading.Thread(
            target=lambda: order.append(f"created {ws.create(OLD.model_copy(update={'name': 'q'}))}")
        )
        other.start()
        other.join(5)
        assert not other.is_alive(), "another project's lock is independent"
        time.sleep(0.2)
        assert reader.is_alive(), "a load waits for the writer of its project"
        order.append("released")
    reader.join(5)
    assert order[1:] == ["released", "loaded p"]

    script = (
        "import sys, time\n"
        "from ladderlab.storage import Workspace\n"
        "ws = Workspace(sys.argv[1])\n"
        "with ws._locked('p'):\n"
        "    print('locked', flush=True)\n"
        "    time.sleep(1.0)\n"
    )
    holder = subprocess.Popen([sys.executable, "-c", script, str(ws.root)], stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout.readline().strip() == "locked"
        started = time.monotonic()
        ws.load("p")
        waited = time.monotonic() - started
    finally:
        holder.wait(10)
    assert waited > 0.3, "the lock of another process is honoured"


def test_the_lock_is_released_when_the_holder_fails(tmp_path: Path) -> None:
    ws = Workspace(tmp_path / "ws")
    ws.create(OLD)
    with pytest.raises(RuntimeError), ws._locked("p"):
        raise RuntimeError("boom")
    done = threading.Event()
    threading.Thread(target=lambda: (ws.load("p"), done.set())).start()
    assert done.wait(5)


def test_storage_imports_without_posix_only_modules() -> None:
    """The server must import on Windows and macOS: no fcntl anywhere in the package."""
    package = Path(__file__).parents[2] / "backend" / "ladderlab"
    offenders = [p for p in package.rglob("*.py") if "import fcntl" in p.read_text(encoding="utf-8")]
    assert offenders == []


def test_a_folder_copied_by_hand_loads_under_its_folder_name(tmp_path: Path) -> None:
    ws = Workspace(tmp_path / "ws")
    shutil.copytree(EXAMPLES / "motor", ws.root / "motor2")
    assert ws.load("motor2").project.name == "motor2"
