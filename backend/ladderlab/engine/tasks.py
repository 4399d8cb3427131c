"""The task configuration on a virtual clock, and a pacer that follows the wall clock.

Virtual clock (issue 4): time starts at 0 ms; a cyclic task of interval I is
due at I, 2I, 3I...; one scan advances the clock to the earliest due time and
runs every task due then, in priority order (lower number first, CFG-05; equal
priorities in declaration order), each task's program instances in the order
listed (CFG-06). A SINGLE task runs once on each rising edge of its BOOL
variable, read at the start of every scan; a task with both INTERVAL and SINGLE
is cyclic while the variable is FALSE (CFG-05). When a task has a SINGLE or no
task is cyclic, the resource also scans every ``IDLE_MS`` (so a configuration
without tasks advances time and runs nothing). With no task configured every
PROGRAM runs in one 10 ms task.

The plant task (``Task.plant``: the project's plants, the models of the process) is due in
every scan and runs before the control tasks of that scan, on the same clock; scans come when
control tasks are due (with no control task, every plant task interval).

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
from .codegen.tasks import task_function

TASK_ERROR = "ENGINE-TASKS"
_EPSILON_MS = 1e-6
DEFAULT_INTERVAL_MS = 10
#: How often a resource with SINGLE tasks (or no cyclic one) scans when no cyclic task is due.
IDLE_MS = 10
#: A task's time budget per scan unless configured (CODESYS's default watchdog time).
DEFAULT_WATCHDOG_S = 0.1


@dataclass
class Task:
    name: str
    interval_ms: float | None  # None: runs only on the rising edges of ``single``
    priority: int
    programs: list[str]
    order: int
    watchdog_s: float = DEFAULT_WATCHDOG_S
    next_due: float = 0.0
    stopped: bool = False  # after a fault, until reset
    single: str | None = None  # the path of the BOOL variable whose rising edges run the task once
    function: str = ""  # the generated function that runs the task (codegen/tasks.py)
    trigger: bool = False  # the SINGLE variable's value at the previous scan
    plant: bool = False  # the plant task: runs first in every scan

    def sort_key(self) -> tuple[int, int]:
        return self.priority, self.order


def _error(message: str, pou: str | None = None) -> Diagnostic:
    return Diagnostic(code=TASK_ERROR, message=message, pou=pou, file="tasks")


def validate_tasks(program: ir.Program) -> list[Diagnostic]:
    """Task configuration errors: bad interval, unknown program instance, an instance in two tasks, a plant
    outside the plant task or a program in it."""
    diagnostics: list[Diagnostic] = []
    instances = {i.name.upper(): i for i in program.program_instances()}
    plants: set[str] = set()  # the instances of plants: the plant task's, and no other task's
    for instance in instances.values():
        pou = program.pous.get(instance.pou) or next(
            (p for n, p in program.pous.items() if n.upper() == instance.pou.upper()), None
        )
        if pou is not None and pou.plant:
            plants.add(instance.name.upper())
        if pou is None or pou.kind != "program":
            what = f"{instance.pou} is a {pou.kind.replace('_', ' ')}, not a program" if pou else "unknown program"
            diagnostics.append(_error(f"program instance {instance.name}: {what}", instance.pou))
    owner: dict[str, str] = {}
    names: set[str] = set()
    for task in program.task_specs():
        if task.name.upper() in names:
            diagnostics.append(_error(f"task {task.name} is declared twice"))
        names.add(task.name.upper())
        interval = task.interval_ms
        if interval is None and task.single is None:
            diagnostics.append(_error(f"task {task.name} needs an interval or a SINGLE variable"))
        elif interval is not None and not (isinstance(interval, (int, float)) and 0 < interval < math.inf):
            diagnostics.append(_error(f"task {task.name}: the interval must be a positive time, not {interval!r} ms"))
        for name in task.programs:
            key = name.upper()
            if key not in instances:
                kind = next((p.kind for n, p in program.pous.items() if n.upper() == key), None)
                what = f"{name} is a {kind.replace('_', ' ')}, not a program" if kind else f"unknown program {name}"
                diagnostics.append(_error(f"task {task.name}: {what}", name))
            elif (key in plants) != task.plant:
                what = (
                    f"{name} is a plant: plants run in the plant task, before the control tasks of every scan"
                    if key in plants
                    else f"the plant task runs plants only; {name} is a program"
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
    limits = {k.upper(): v for k, v in watchdog_s.items()} if isinstance(watchdog_s, dict) else {}
    default = DEFAULT_WATCHDOG_S if isinstance(watchdog_s, dict) else watchdog_s
    tasks = []
    for order, spec in enumerate(program.task_specs()):
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
                next_due=spec.interval_ms if spec.interval_ms is not None else math.inf,
                single=spec.single,
                function=task_function(order),
                plant=spec.plant,
            )
        )
    return tasks


@dataclass
class Schedule:
    """Which tasks run in the next scan, and when, on the virtual clock."""

    tasks: list[Task]
    time_ms: float = 0.0
    _ordered: list[Task] = field(default_factory=list)
    _cyclic: list[Task] = field(default_factory=list)
    _idle: bool = False  # scans also every IDLE_MS (a SINGLE task, or no cyclic one)
    _idle_due: float = IDLE_MS

    def __post_init__(self) -> None:
        self._ordered = sorted(self.tasks, key=lambda task: (not task.plant, *task.sort_key()))
        self._cyclic = [task for task in self._ordered if task.interval_ms is not None]
        control = [task for task in self.tasks if not task.plant]
        # the plants run in every scan; the control tasks' due times make the scans (with none, the plants')
        self._plants = [task for task in self._ordered if task.plant] if control else []
        clocks = [task for task in self._cyclic if not task.plant] if control else self._cyclic
        # (task, interval) of the cyclic tasks, in priority order: every scan walks it, so no lookups there
        self._periods = [(task, task.interval_ms) for task in clocks if task.interval_ms is not None]
        self._idle = not clocks or any(task.single for task in self.tasks)
        lone = len(self.tasks) == 1 and len(self._periods) == 1 and not self._plants and not self._idle
        #: The one cyclic task when it is the whole configuration: each scan runs it, at its next due time.
        self.lone: Task | None = self._periods[0][0] if lone else None

    def next_time(self) -> float:
        due = min([task.next_due for task, _ in self._periods]) if self._periods else math.inf
        return self._idle_due if self._idle and self._idle_due < due else due

    def following_time(self) -> float:
        """When the scan after the next one is due: ``next_time`` once ``advance`` has run (nothing changes)."""
        now = self.next_time()
        dues = [task.next_due + period if task.next_due == now else task.next_due for task, period in self._periods]
        due = min(dues, default=math.inf)
        if not self._idle:
            return due
        idle = self._idle_due + IDLE_MS if self._idle_due == now else self._idle_due
        return min(idle, due)

    def advance(self) -> tuple[float, list[Task]]:
        """Move the clock to the next due time; the tasks due then: the plants (every scan) first, then the
        cyclic tasks due, in priority order."""
        now = self.next_time()
        due = []
        for task in self._plants:
            task.next_due = now + task.interval_ms  # type: ignore[operator]  # the plant task is cyclic
            due.append(task)
        for task, period in self._periods:
            if task.next_due == now:
                task.next_due += period
                due.append(task)
        if self._idle and self._idle_due == now:
            self._idle_due += IDLE_MS
        self.time_ms = now
        return now, due

    def at(self, time_ms: float) -> list[Task]:
        """Move the clock to ``time_ms`` (not backwards) for a scan of every cyclic task; each is next due after it."""
        self.skip_to(time_ms)
        return list(self._cyclic)

    def skip_to(self, time_ms: float) -> None:
        """Move the clock to ``time_ms`` (not backwards) without a scan; each task is next due after it."""
        if not time_ms >= self.time_ms:
            raise ValueError(f"time {time_ms} ms is before the current time {self.time_ms} ms")
        for task, period in self._periods:
            task.next_due = (math.floor(time_ms / period) + 1) * period
        self._idle_due = (math.floor(time_ms / IDLE_MS) + 1) * IDLE_MS
        self.time_ms = time_ms

    def with_triggers(self, due: list[Task], read: Callable[[Task], object]) -> list[Task]:
        """The tasks of this scan: the cyclic ones due, but a task whose SINGLE variable is TRUE (CFG-05), and
        every SINGLE task whose variable rose since the previous scan (``read`` gives its value now)."""
        running = set(map(id, due))
        for task in self.tasks:
            if task.single is None:
                continue
            value = bool(read(task))
            rising, task.trigger = value and not task.trigger, value
            if rising:
                running.add(id(task))
            elif value:
                running.discard(id(task))
        return [task for task in self._ordered if id(task) in running]

    def reset_triggers(self) -> None:
        for task in self.tasks:
            task.trigger = False


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

    def set_speed(self, speed: float) -> None:
        """Pace at ``speed`` from now on: the virtual time reached so far at the old speed is kept (the pacer
        re-anchors there), so a change of scale neither loses nor gains virtual time."""
        if not speed > 0:
            raise ValueError("speed must be positive")
        if self._anchor is not None:
            self._anchor = (self.clock(), self._virtual_now())
        self.speed = speed

    def _virtual_now(self) -> float:
        if self._anchor is None:
            self._anchor = (self.clock(), self.sim.time_ms)
        wall, virtual = self._anchor
        return virtual + (self.clock() - wall) * 1000.0 * self.speed

    def wall_time(self, virtual_ms: float) -> float:
        """The wall clock time at which ``poll`` runs a scan due at ``virtual_ms`` (now, when it is due already)."""
        now = self.clock()
        if self._anchor is None:
            return now
        wall, virtual = self._anchor
        return max(now, wall + (virtual_ms - virtual) / 1000.0 / self.speed)

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
