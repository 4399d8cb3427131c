"""The task configuration on a virtual clock, and a pacer that follows the wall clock.

Virtual clock (issue 4): time starts at 0 ms; a cyclic task of interval I is
due at I, 2I, 3I...; one scan advances the clock to the earliest due time and
runs every task due then, in priority order (lower number first, CFG-05; equal
priorities in declaration order), each task's programs in the order listed
(CFG-06). With no task configured every PROGRAM runs in one 10 ms task.

``Pacer`` runs those scans in real time for browser sessions: it keeps virtual
time in step with the wall clock (times a speed factor); a driver thread
calls ``poll()`` and sleeps for the delay it returns.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Protocol

from ..ir import nodes as ir
from ..model.diagnostics import Diagnostic

TASK_ERROR = "ENGINE-TASKS"
_EPSILON_MS = 1e-6
DEFAULT_INTERVAL_MS = 10
#: A task's time budget per scan unless configured (CODESYS's default watchdog time).
DEFAULT_WATCHDOG_S = 0.1


@dataclass
class Task:
    name: str
    interval_ms: float
    priority: int
    programs: list[str]
    order: int
    watchdog_s: float = DEFAULT_WATCHDOG_S
    next_due: float = 0.0
    stopped: bool = False  # after a fault, until reset

    def sort_key(self) -> tuple[int, int]:
        return self.priority, self.order


def _error(message: str, pou: str | None = None) -> Diagnostic:
    return Diagnostic(code=TASK_ERROR, message=message, pou=pou, file="tasks")


def validate_tasks(program: ir.Program) -> list[Diagnostic]:
    """Task configuration errors: bad interval, unknown program, a program instance in two tasks."""
    diagnostics: list[Diagnostic] = []
    programs = {name.upper(): pou for name, pou in program.pous.items() if pou.kind == "program"}
    owner: dict[str, str] = {}
    names: set[str] = set()
    for task in program.tasks:
        if task.name.upper() in names:
            diagnostics.append(_error(f"task {task.name} is declared twice"))
        names.add(task.name.upper())
        if not (
            isinstance(task.interval_ms, (int, float)) and task.interval_ms > 0 and math.isfinite(task.interval_ms)
        ):
            diagnostics.append(
                _error(f"task {task.name}: the interval must be a positive time, not {task.interval_ms!r} ms")
            )
        for name in task.programs:
            key = name.upper()
            if key not in programs:
                kind = program.pous.get(name) or next((p for n, p in program.pous.items() if n.upper() == key), None)
                what = (
                    f"{name} is a {kind.kind.replace('_', ' ')}, not a program" if kind else f"unknown program {name}"
                )
                diagnostics.append(_error(f"task {task.name}: {what}", name))
            elif key in owner:
                where = "twice in this task" if owner[key] == task.name else f"in tasks {owner[key]} and {task.name}"
                diagnostics.append(_error(f"program {name} is listed {where}: an instance runs in one task only", name))
            else:
                owner[key] = task.name
    return diagnostics


def task_table(program: ir.Program, watchdog_s: float | dict[str, float] = DEFAULT_WATCHDOG_S) -> list[Task]:
    """The tasks to schedule (validated program): the configured ones, else one 10 ms task with every PROGRAM."""
    specs = program.tasks or [
        ir.TaskSpec("DEFAULT", DEFAULT_INTERVAL_MS, 0, [n for n, p in program.pous.items() if p.kind == "program"])
    ]
    limits = {k.upper(): v for k, v in watchdog_s.items()} if isinstance(watchdog_s, dict) else {}
    default = DEFAULT_WATCHDOG_S if isinstance(watchdog_s, dict) else watchdog_s
    tasks = []
    for order, spec in enumerate(specs):
        limit = limits.get(spec.name.upper(), default)
        if not limit > 0:
            raise ValueError(f"watchdog of task {spec.name} must be positive, not {limit!r}")
        tasks.append(
            Task(
                spec.name,
                spec.interval_ms,
                spec.priority,
                [p.upper() for p in spec.programs],
                order,
                limit,
                next_due=spec.interval_ms,
            )
        )
    return tasks


@dataclass
class Schedule:
    """Which tasks run in the next scan, and when, on the virtual clock."""

    tasks: list[Task]
    time_ms: float = 0.0
    _ordered: list[Task] = field(default_factory=list)

    def __post_init__(self) -> None:
        self._ordered = sorted(self.tasks, key=Task.sort_key)

    def next_time(self) -> float:
        return min(task.next_due for task in self.tasks)

    def advance(self) -> tuple[float, list[Task]]:
        """Move the clock to the next due time; the tasks due then, in priority order."""
        now = self.next_time()
        due = [task for task in self._ordered if task.next_due == now]
        for task in due:
            task.next_due += task.interval_ms
        self.time_ms = now
        return now, due

    def at(self, time_ms: float) -> list[Task]:
        """Move the clock to ``time_ms`` (not backwards) for a scan of every task; each task is next due after it."""
        self.skip_to(time_ms)
        return list(self._ordered)

    def skip_to(self, time_ms: float) -> None:
        """Move the clock to ``time_ms`` (not backwards) without a scan; each task is next due after it."""
        if not time_ms >= self.time_ms:
            raise ValueError(f"time {time_ms} ms is before the current time {self.time_ms} ms")
        for task in self.tasks:
            task.next_due = (math.floor(time_ms / task.interval_ms) + 1) * task.interval_ms
        self.time_ms = time_ms


class Scanner(Protocol):
    """What the pacer drives (a Simulation)."""

    @property
    def halted(self) -> object: ...

    def next_scan_time(self) -> float: ...

    @property
    def time_ms(self) -> float: ...

    def cycle(self, n: int = 1) -> int: ...


class Pacer:
    """Runs scans when their virtual time comes up on the wall clock (times ``speed``).

    ``poll()`` runs every scan that is due and returns the seconds until the
    next one. When scans fall more than ``max_lag_ms`` behind (the program is
    slower than real time, or the driver stalled) the pacer skips ahead instead
    of racing to catch up, and counts it in ``overruns``. While the simulation
    is halted at a breakpoint nothing runs; afterwards time resumes from there.
    ``interrupted`` (asked after every scan) makes ``poll`` return at once, keeping
    the schedule: the driver has something to do between two scans.
    """

    def __init__(
        self,
        sim: Scanner,
        *,
        speed: float = 1.0,
        max_lag_ms: float = 200.0,
        clock: Callable[[], float] = time.monotonic,
        idle_s: float = 0.05,
        interrupted: Callable[[], bool] = lambda: False,
    ) -> None:
        if not speed > 0:
            raise ValueError("speed must be positive")
        self.sim, self.speed, self.max_lag_ms, self.clock, self.idle_s = sim, speed, max_lag_ms, clock, idle_s
        self.interrupted = interrupted
        self.overruns = 0
        self._anchor: tuple[float, float] | None = (
            clock(),
            sim.time_ms,
        )  # (wall s, virtual ms) in step; None: re-anchor

    def _virtual_now(self) -> float:
        if self._anchor is None:
            self._anchor = (self.clock(), self.sim.time_ms)
        wall, virtual = self._anchor
        return virtual + (self.clock() - wall) * 1000.0 * self.speed

    def poll(self) -> float:
        if self.sim.halted:
            self._anchor = None
            return self.idle_s
        now = self._virtual_now()
        while self.sim.next_scan_time() <= now + _EPSILON_MS:  # float clocks: due within a nanosecond is due
            if now - self.sim.next_scan_time() > self.max_lag_ms:
                self.overruns += 1
                self._anchor = (self.clock(), self.sim.next_scan_time())
                now = self.sim.next_scan_time()
            self.sim.cycle(1)
            if self.sim.halted:
                self._anchor = None
                return self.idle_s
            if self.interrupted():
                return 0.0
        return max(0.0, (self.sim.next_scan_time() - now) / 1000.0 / self.speed)

    def run(self, seconds: float, sleep: Callable[[float], None] = time.sleep) -> None:
        """Poll for ``seconds`` of wall time (a blocking driver, e.g. for the CLI or a thread)."""
        end = self.clock() + seconds
        while (left := end - self.clock()) > _EPSILON_MS / 1000.0:  # a float clock may never land exactly on ``end``
            sleep(min(self.poll(), left))
        self.poll()  # the scans due at the very end
