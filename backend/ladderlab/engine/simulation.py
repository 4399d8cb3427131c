"""The scan engine as one synchronous object: run scans on the virtual clock, read, write, force, debug.

    sim = Simulation(program)                    # an ir.Program (or a CompiledProgram)
    sim.cycle(3); sim.read("MAIN.T1.ET"); sim.write("MAIN.START", True); sim.force("GVL.LAMP", "TRUE")
    sim.run_for(1000); sim.scan_at(12.5); sim.snapshot(); sim.reset(cold=True); sim.fault

Everything from outside the program enters through ``submit`` (``inputs.py``: writes, forces,
releases, panel events, injected faults, resets), applied at the start of the next scan and
reported to ``on_input`` with the scan number. A scan applies those inputs, reads the SINGLE
tasks' variables and the process image's inputs, applies injected faults and forces, runs the
plant task (plants: the models of the process, tasks.py), applies injected faults and forces
again where the plants' signals cross into the program, runs every control task due (each a
generated function ``ll_task_N``), applies forces again, publishes the outputs and records its
wall time. A fault (PlcRuntimeError,
watchdog, or any unexpected exception in generated code) stops its task until
``reset`` and is kept in ``faults``; the caller's process never sees it.

Variants (docs/runtime.md): ``fast`` (no hooks), ``monitor`` (probes record the
power flow of every LD/FBD element: ``probes(instance)``), ``debug`` (probes and
pause points). ``use_variant`` switches between monitor and debug between scans,
keeping every variable and FB instance: both variants have the same classes.

Debug variant (``variant="debug"``): the scan is a generator that yields at
armed pause points. ``cycle()`` then returns early with ``halted`` set; while
halted ``read``/``write``/``force`` act at once, and ``resume()`` / ``step()``
continue the same scan and return the next ``Halt`` (None when the scan ended).
Everything happens in the caller's thread: a server drives one Simulation from
one thread (see docs/runtime.md).
"""

from __future__ import annotations

import contextlib
import time
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, replace
from types import FrameType, GeneratorType
from typing import Any, cast

from ..iec.addresses import parse_address
from ..iec.spelling import did_you_mean
from ..ir import nodes as ir
from ..ir import types as t
from .call_stack import CallFrame, call_stack
from .codegen import names
from .codegen.context import ProbeTable
from .codegen.faults import Fault, make_fault
from .codegen.runtime import UNSET, Watchdog
from .codegen.scope import global_owner
from .codegen.typeinfo import runtime_name
from .compile import CompiledProgram, compile_program
from .debug import STEP_ENDS, Debugger, Halt
from .doubles import Mocks
from .frames import FramePlan, frame_plan
from .inputs import AppliedInput, Injection, InputEvent, InputRefused, immediate, injection
from .paths import (
    AccessorFault,
    Location,
    LocationReader,
    NoTarget,
    Resolver,
    Roots,
    UnknownPath,
    coerce_for,
    leaves,
    plain,
)
from .process_image import AREA_ORDER, IoPoint, ProcessImage, key_of, located_address, view_kind
from .state import SimState, data_of, holds_references, restore_into, restore_list
from .stopped import stopped_elements
from .stored_once import StoredOnce
from .tasks import DEFAULT_WATCHDOG_S, Schedule, Task, task_table

#: Scan times are sampled: the wall clock is read around every SAMPLE_EVERY-th scan (the first included), so a
#: scan of a small program does not pay two clock readings (docs/runtime.md, "The scan loop").
SAMPLE_EVERY = 16
#: The slot types that may hold a user FB instance, whose path ``_instance_paths`` records
_HOLDERS = (t.FbInstance, t.Array, t.Struct)


def drained(generator: GeneratorType) -> object:
    """What a debug-variant call returns, run to its end (its pause points pass: it runs outside any scan)."""
    while True:
        try:
            next(generator)
        except StopIteration as stop:
            return stop.value


@dataclass
class ScanStats:
    """Scans completed so far, and the wall time of the sampled ones (halted time excluded), in milliseconds."""

    count: int = 0
    samples: int = 0
    total_ms: float = 0.0
    min_ms: float = 0.0
    max_ms: float = 0.0
    last_ms: float = 0.0

    @property
    def avg_ms(self) -> float:
        return self.total_ms / self.samples if self.samples else 0.0

    def add(self, ms: float) -> None:
        self.min_ms = ms if not self.samples else min(self.min_ms, ms)
        self.max_ms = max(self.max_ms, ms)
        self.samples += 1
        self.total_ms += ms
        self.last_ms = ms


@dataclass(frozen=True)
class ProbeView:
    """Monitoring values of one POU instance: last value of every probed element, and which ran in the last scan."""

    values: dict[str, object]
    executed: frozenset[str]
    #: Elements of networks the last scan did not record (``Simulation.view``): their state is not known.
    unknown: frozenset[str] = frozenset()


class Simulation:
    def __init__(
        self,
        program: ir.Program | CompiledProgram,
        *,
        variant: str | None = None,
        watchdog_s: float | dict[str, float] = DEFAULT_WATCHDOG_S,
        wall_clock: Callable[[], float] = time.perf_counter,
        watchdog_clock: Callable[[], float] = time.thread_time,
    ) -> None:
        if isinstance(program, CompiledProgram):
            if variant is not None and variant != program.variant:
                raise ValueError(f"the program was compiled as the {program.variant} variant, not {variant}")
            compiled = program
        else:
            compiled = compile_program(program, variant or "fast")
        self.compiled = compiled
        self._variants = {compiled.variant: compiled}
        self._context = compiled.generated.context
        self._ns = cast("dict[str, Any]", compiled.namespace())  # the generated module's globals: functions, G, views
        self._clock = wall_clock
        self._watchdog = Watchdog(watchdog_clock, self._ns["ll_wb"])
        self._ns["ll_wd"] = self._watchdog.check
        self._ns["ll_watchdog"] = self._watchdog  # a chunk compiled at first call stops it meanwhile (compile.py)
        self._tasks: list[Task] = task_table(compiled.program, watchdog_s)
        self._schedule = Schedule(self._tasks)
        self._resolver = Resolver(self._context)
        self._attached: dict[str, tuple[object, str]] = {}  # outside the tasks (attach): name -> (instance, POU)
        self._roots = Roots(self._ns, self._attached, self._run_accessor)
        #: faults of the SETs that online writes of 'call' properties ran (the runner logs them; the tasks go on)
        self.accessor_faults: list[Fault] = []
        self._image: ProcessImage = self._ns["ll_image"]
        self._has_inputs, self._has_outputs = bool(self._image.inputs), bool(self._image.outputs)  # sized once
        self._triggers = {task.name: self._resolver.resolve(task.single) for task in self._tasks if task.single}
        pous = self._context.pous
        self._plant_instances = {i.name.upper() for i in self._context.instances if pous[i.pou.upper()].plant}
        self.debugger: Debugger | None = None
        self._stamp = 0  # counts scans started: the stamp probe groups record (ll_scan)
        self._pending: list[tuple[InputEvent, Location | None, object]] = []  # waiting for the next scan start
        self._forces: dict[str, tuple[Location, object]] = {}
        self._injections: dict[str, tuple[Location, Injection]] = {}
        #: Hears every input as it is applied (the online log, a recording); see inputs.py.
        self.on_input: Callable[[AppliedInput], None] | None = None
        #: Hears the end of every completed scan: its number, its virtual time, and whether the schedule chose
        #: that time (``cycle``, ``run_for``) or the caller did (``scan_at``): a scan history (issue 23).
        self.on_scan: Callable[[int, float, bool], None] | None = None
        self._scheduled = True  # whether the scan under way runs at the time the schedule chose
        self._halts = 0  # halts of the scan under way so far
        self._halt_pid: int | None = None
        self.faults: list[Fault] = []
        self.stats = ScanStats()
        self.scan_count = 0
        self.halted: Halt | None = None
        self._scan: Iterator | None = None
        self._busy = 0.0
        self._watchdog_left = 0.0
        self._paths: dict[int, str] | None = None
        self._instances: dict[str, tuple[object, str]] = {}  # upper-case path -> (instance, upper-case POU name)
        self._links: dict[str, dict[str, str]] = {}  # their VAR_IN_OUT links to program instances
        self.mocks = Mocks()
        #: (program, probe number) -> (container, key) of its variable (_read_some_deferred)
        self._deferred_pairs: dict[tuple[str, int], tuple[object, object]] = {}
        #: (instance or function, elements or None, by network run?) -> how a frame reads them (frames.py)
        self._frame_plans: dict[tuple[str, tuple[str, ...] | None, bool], FramePlan] = {}
        self._viewed: dict[str, Iterable[str] | None] | None = None  # ``view``'s argument; None: every network
        self._viewed_since: dict[tuple[str, int], int] = {}  # (instance, network) -> the stamp it was viewed from
        self._record = True  # whether the next scans record the viewed networks (``record``)
        #: while scans record no network: (instance, its own ``ll_v`` flags), each holding a list of False instead
        self._silenced: list[tuple[object, list[bool], list[bool]]] | None = None
        #: (instance, its own flags, its list of False) of the instances with a viewed network, until ``view``
        self._mutes: list[tuple[object, list[bool], list[bool]]] | None = None
        self._quiet_stamp = -1  # the stamp of the last scan that recorded no network (``quiet``)
        #: (the stamp of a scan that faulted, probe-view key -> the elements its faults stopped: ``probes``)
        self._stopped: tuple[int, dict[str, frozenset[str]]] = (-1, {})
        self._stored_once = StoredOnce(self._context)  # constant FB inputs an online change may have overwritten
        self._attach_debugger()
        self._initialise(warm=False)

    # ------------------------------------------------------------------ variants

    @property
    def variant(self) -> str:
        return self.compiled.variant

    def use_variant(self, variant: str, compiled: CompiledProgram | None = None) -> None:
        """Switch between the monitor and the debug variant between scans; all state stays.

        ``compiled`` is that variant of the same program (compiled now, once, when not given)."""
        if variant == self.variant:
            return
        if {variant, self.variant} != {"monitor", "debug"}:
            raise ValueError(
                f"a simulation switches between the monitor and the debug variant only, "
                f"not from {self.variant} to {variant}"
            )
        if self.halted is not None:
            raise RuntimeError("the simulation is halted: resume(), step() or reset() first")
        if compiled is None:
            compiled = self._variants.get(variant) or compile_program(self.compiled.program, variant)
        if compiled.variant != variant or compiled.declarations != self.compiled.declarations:
            raise ValueError(f"that is not the {variant} variant of this simulation's program")
        self._unsilence()  # (the debug code records every network: its flags are the real ones again)
        if self.variant == "monitor":  # the debug code stores every probe: start from complete lists
            for obj, pou in self._instances_by_path().values():
                table = self.compiled.generated.context.probes_of(pou)
                self._read_deferred(obj, table)
                values = obj.ll_pr  # type: ignore[attr-defined]  # generated POU classes and their namespace are untyped
                for alias, source in table.aliases.items():  # (the monitor code stores their value once)
                    values[alias] = values[source]
        self._variants[variant] = compiled
        compiled.install(self._ns)
        self.compiled = compiled
        self._frame_plans.clear()  # (a plan reads its variant's table: aliases, network runs)
        self._attach_debugger()

    @property
    def watchdogs(self) -> dict[str, float]:
        """Each task's watchdog budget in seconds, by task name: a replay of its scans runs under the same ones."""
        return {task.name: task.watchdog_s for task in self._tasks}

    def variant_program(self, variant: str) -> CompiledProgram | None:
        """This simulation's program compiled as ``variant``, when it was (a scan history replays the monitor code)."""
        return self._variants.get(variant)

    def _attach_debugger(self) -> None:
        """The debugger of the debug variant, and what the scan loop may skip in the variant now installed."""
        self.debugger = (
            Debugger(self.compiled.generated.pauses, self._ns["ll_halt"]) if self.variant == "debug" else None
        )
        self._watched = self.compiled.watched
        lean = self.debugger is None and not self._triggers and not self._has_inputs and not self._has_outputs
        self._lone = self._schedule.lone if lean else None

    # ------------------------------------------------------------------ state

    def _initialise(self, warm: bool, implicit: bool = True) -> None:
        """The process image cleared (the inputs stay as the world set them), the globals - program instances first
        (codegen/tasks.py) - then the VAR_CONFIG initial values, then (``implicit``) every instance's FB_init."""
        self._unsilence()  # (a restart may make new instances: the next quiet scans silence those)
        self._mutes = None
        self._image.clear()
        self._ns["ll_init_globals"](warm)
        self._ns["ll_config_init"](warm)
        if implicit:
            self._implicit_calls("ll_fb_init", warm)
        self._schedule.reset_triggers()
        self._paths = None
        if self._viewed is not None:  # fresh instances record every network
            self.view(self._viewed)

    def _implicit_calls(self, function: str, warm: bool) -> None:
        """Every instance's FB_init (``ll_fb_init``) or FB_exit (``ll_fb_exit``; ir/fb_init.py), under the longest
        task watchdog. The debug variant's calls are generators: their pause points are passed over (a breakpoint
        in FB_init does not halt the initialisation; docs/st.md). A runtime error stops every task with the fault,
        located in the method. A program without either has no such function (codegen/tasks.py)."""
        calls = self._ns.get(function)
        if calls is None:
            return
        self._paths = None  # (a fault names the instance it happened in)
        self._watchdog.arm(max((task.watchdog_s for task in self._tasks), default=0.1))
        try:
            run = calls(warm)
            if self.debugger is not None:
                for _ in run:
                    pass
        except Exception as error:
            for task in self._tasks:
                task.stopped = True
            self._record_fault(error, "(initialisation)" if function == "ll_fb_init" else "(reset)", self.time_ms)
        finally:
            self._watchdog.deadline = float("inf")

    @property
    def time_ms(self) -> float:
        """Virtual time of the last scan (0 before the first)."""
        return self._schedule.time_ms

    def next_scan_time(self) -> float:
        return self._schedule.next_time()

    def following_scan_time(self) -> float:
        """When the scan after the next one is due (on the schedule: a ``scan_at`` may come between)."""
        return self._schedule.following_time()

    @property
    def fault(self) -> Fault | None:
        """The most recent fault since the last reset."""
        return self.faults[-1] if self.faults else None

    @property
    def tasks(self) -> list[Task]:
        return list(self._tasks)

    def reset(self, cold: bool = False) -> None:
        """Warm (RETAIN variables keep their values) or cold restart; clears faults, ends a halted scan.

        Forces, injected faults and inputs waiting for the next scan stay."""
        self.submit(InputEvent("reset", cold=cold))

    def _reset(self, cold: bool, initialise: bool = True, implicit: bool = True) -> None:
        """``implicit``: a restart the program sees, which runs FB_exit on the instances first and FB_init on the
        new ones (not a restore of a captured state, which sets every value itself)."""
        self._deferred_pairs.clear()  # (a restart may make new FB instances: arrays of them are rebuilt)
        if self._scan is not None:
            self._scan.close()  # type: ignore[attr-defined]  # generated POU classes and their namespace are untyped
            self.scan_count += 1  # the abandoned scan keeps its number: the next scan has the next one
        self._scan, self.halted = None, None
        if self.debugger is not None:
            self.debugger.waiting_for_transition = False
            self.debugger.arm(None)
        self.faults.clear()
        self.accessor_faults.clear()
        for task in self._tasks:
            task.stopped = False
        if implicit:
            self._implicit_calls("ll_fb_exit", not cold)
        if initialise:
            self._initialise(warm=not cold, implicit=implicit)
        self._apply_forces()
        # A restart runs no scan: no element ran since, so the power flow of the scan before it (its probe groups'
        # stamps) is no longer shown beside the initial values. (A restored state sets its own stamp after this.)
        self._stamp += 1
        self._ns["ll_scan"] = self._stamp

    # ------------------------------------------------------------------ running

    def cycle(self, n: int = 1) -> int:
        """Run ``n`` scans of the task configuration; returns how many completed (fewer when one halts)."""
        self._not_halted()
        if self._record is (self._silenced is not None) and n > 0:
            self._fit_recording()
        if self._lone is not None:
            return self._cycle_lone(n, self._lone)
        for done in range(n):
            now, due = self._schedule.advance()
            if not self._scan_now(now, due, scheduled=True):
                return done
        return n

    def run_for(self, ms: float) -> int:
        """Run every scan due within the next ``ms`` of virtual time; returns how many completed."""
        self._not_halted()
        end, done = self.time_ms + ms, 0
        if self._record is (self._silenced is not None) and self._schedule.next_time() <= end:
            self._fit_recording()  # (only before a scan: silenced flags say the last scan recorded nothing)
        while self._schedule.next_time() <= end:
            now, due = self._schedule.advance()
            if not self._scan_now(now, due, scheduled=True):
                break
            done += 1
        return done

    def scan_at(self, time_ms: float) -> bool:
        """One scan of every task at the absolute virtual time ``time_ms`` (not before the current time).

        Returns False when the scan halted (debug variant)."""
        self._not_halted()
        due = self._schedule.at(time_ms)
        if self._record is (self._silenced is not None):
            self._fit_recording()
        return self._scan_now(time_ms, due, scheduled=False)

    def _program_instance(self, name: str) -> object:
        return self._instances_by_path()[name][0]

    @staticmethod
    def _programs_run(tasks: list[Task]) -> list[str]:
        """The program instances the scan runs of ``tasks`` (those a fault stopped run no more)."""
        return [program for task in tasks if not task.stopped for program in task.programs]

    def _not_halted(self) -> None:
        if self.halted is not None:
            raise RuntimeError("the simulation is halted: resume(), step() or reset() first")

    def _cycle_lone(self, n: int, task: Task) -> int:
        """``cycle`` for the usual configuration, one cyclic task and nothing else to schedule (no plant, SINGLE
        task, process image or debugger): the steps of ``_scan_now`` inline, each skipped when it has nothing to do
        (inputs, forces, injected faults, the watchdog of a program without loops, an unsampled scan's clock)."""
        ns, schedule, stats, period = self._ns, self._schedule, self.stats, cast(float, task.interval_ms)
        silenced = self._silenced is not None
        self._scheduled = True
        for done in range(n):
            if self._pending:
                self._apply_inputs()
            if self._lone is None:  # a listener (on_input, on_scan) switched to the debug variant
                return done + self.cycle(n - done)
            if self._stored_once.stale and not task.stopped:
                self._stored_once.restore(task.programs, self._program_instance)
            if self._injections or self._forces:
                self._cross()
            now = task.next_due
            task.next_due = now + period
            schedule.time_ms = now
            ns["ll_now"] = now
            self._stamp += 1
            ns["ll_scan"] = self._stamp
            if silenced:
                self._quiet_stamp = self._stamp
            if not task.stopped:
                sampled = not self.scan_count % SAMPLE_EVERY
                start = self._clock() if sampled else 0.0
                if self._watched:
                    outer = self._watchdog.deadline, self._watchdog.limit_s  # a scan run from a test's body (call)
                    self._watchdog.arm(task.watchdog_s)
                try:
                    ns[task.function]()
                except Exception as error:
                    self._fault(task, error, now)
                if self._watched:
                    self._watchdog.deadline, self._watchdog.limit_s = outer
                if sampled:
                    stats.add((self._clock() - start) * 1000.0)
                if self._stored_once.faulted and not task.stopped:
                    self._stored_once.restore_faulted(task.programs, self._program_instance)
            if self._forces:
                self._apply_forces()
            stats.count += 1
            self.scan_count += 1
            if self.on_scan is not None:
                self.on_scan(self.scan_count - 1, now, True)
        return n

    def _scan_now(self, now: float, due: list[Task], scheduled: bool) -> bool:
        self._halts = 0
        self._scheduled = scheduled
        self._apply_inputs()
        if self._triggers:
            due = self._schedule.with_triggers(due, lambda task: self._triggers[task.name].get(self._roots))
        if self._stored_once.stale and self.debugger is None:  # (the debug variant's calls store every input)
            self._stored_once.restore(self._programs_run(due), self._program_instance)
        if self._has_inputs:  # (a program without %I addresses pays nothing per scan)
            self._image.read_inputs()
        plants = [task for task in due if task.plant]
        control = [task for task in due if not task.plant] if plants else due
        self._cross(plants_next=bool(plants))
        self._ns["ll_now"] = now
        self._stamp += 1
        self._ns["ll_scan"] = self._stamp
        if self._silenced is not None:
            self._quiet_stamp = self._stamp
        if self.debugger is None:
            outer = self._watchdog.deadline, self._watchdog.limit_s  # a scan run from a test's body (call)
            sampled = not self.scan_count % SAMPLE_EVERY
            start = self._clock() if sampled else 0.0
            self._run_tasks(plants, now)
            if plants:
                self._cross()
            self._run_tasks(control, now)
            if self._stored_once.faulted:
                self._stored_once.restore_faulted(self._programs_run(due), self._program_instance)
            self._finish((self._clock() - start) * 1000.0 if sampled else None)
            self._watchdog.deadline, self._watchdog.limit_s = outer
            return True
        self._scan, self._busy = self._debug_scan(now, plants, control), 0.0
        return self._drive()

    def _run_tasks(self, tasks: list[Task], now: float) -> None:
        for task in tasks:
            if not task.stopped:
                if self._watched:
                    self._watchdog.arm(task.watchdog_s)
                try:
                    self._ns[task.function]()
                except Exception as error:
                    self._fault(task, error, now)

    def _debug_scan(self, now: float, plants: list[Task], control: list[Task]) -> Iterator:
        yield from self._debug_tasks(plants, now)
        if plants:
            self._cross()
        yield from self._debug_tasks(control, now)

    def _debug_tasks(self, tasks: list[Task], now: float) -> Iterator:
        for task in tasks:
            if task.stopped:
                continue
            self._watchdog.arm(task.watchdog_s)
            try:
                yield from self._ns[task.function]()
            except Exception as error:
                self._fault(task, error, now)

    def _drive(self) -> bool:
        start = self._clock()
        try:
            pid, instance = next(self._scan)  # type: ignore[arg-type]  # generated POU classes and their namespace are untyped
        except StopIteration:
            self._busy += self._clock() - start
            self._scan = None
            self.debugger.arm(None)  # type: ignore[union-attr]  # the debug variant is in use on this path
            self._finish(self._busy * 1000.0)
            return True
        self._busy += self._clock() - start
        self._watchdog_left = self._watchdog.pause()
        self._halts += 1
        self._halt_pid = pid
        point = self.compiled.generated.pauses[pid]
        self.halted = Halt(
            point, self._instance_path(instance) if instance is not None else None, self.debugger.reason(pid)
        )
        self.debugger.halted_at(pid)  # type: ignore[union-attr]  # the debug variant is in use on this path
        self.debugger.arm(None)  # type: ignore[union-attr]  # the debug variant is in use on this path
        return False

    def _finish(self, elapsed_ms: float | None) -> None:
        """The end of a scan; ``elapsed_ms`` is its wall time when it was sampled (a debug scan always is)."""
        if self._forces:
            self._apply_forces()
        if self._has_outputs:
            self._image.publish()
        if elapsed_ms is not None:
            self.stats.add(elapsed_ms)
        self.stats.count += 1
        self.scan_count += 1
        if self.on_scan is not None:
            self.on_scan(self.scan_count - 1, self.time_ms, self._scheduled)

    def _fault(self, task: Task, error: Exception, now: float) -> None:
        task.stopped = True
        self._record_fault(error, task.name, now)
        if self.variant != "fast":
            stamp, stopped = self._stopped
            found = stopped_elements(error, self.compiled.generated, self.compiled.filename, self._probe_owner)
            if stamp == self._stamp:  # (another task's fault in the same scan)
                found = {key: found.get(key, frozenset()) | stopped.get(key, frozenset()) for key in stopped | found}
            self._stopped = (self._stamp, found)

    def _record_fault(self, error: Exception, task: str, now: float) -> None:
        """Keep ``error`` in ``faults``, located, as a fault of ``task`` (a task's name, or what ran outside tasks)."""
        self.faults.append(self._located_fault(error, task, now))

    def _located_fault(self, error: Exception, task: str, now: float) -> Fault:
        """``error`` as a located fault of ``task`` at ``now`` (where in the program, the instance, the values)."""
        return make_fault(
            error,
            self.compiled.generated,
            self.compiled.filename,
            self._ns,
            task=task,
            time_ms=now,
            scan=self.scan_count,
            instance_path=self._instance_path,
            places=self.compiled.program.places,
        )

    def _run_accessor(
        self, path: str, function: str, dispatched: bool, reference: tuple[object, object], inputs: tuple[object, ...]
    ) -> object:
        """Run the GET (``inputs`` none) or SET (the value) ``function`` of a property monitored as 'call' on the
        instance at ``reference`` now (``dispatched``: the one of the instance's function block): only between scans
        (NoTarget in a halted one), under a task's watchdog; a fault in it is AccessorFault with the located fault
        (the program's tasks go on)."""
        kind = "GET" if not inputs else "SET"
        if self.halted is not None or self._scan is not None:
            raise NoTarget(f"{path}: the scan is halted in the middle, and a property's {kind} runs only between scans")
        if dispatched:  # an override: the one of the instance's function block
            instance = reference[0][reference[1]]  # type: ignore[index]  # an instance's container
            code = self._ns[names.dispatch_table(function)][type(instance)]
        else:
            code = self._ns[names.function(function)]
        now = self._ns["ll_now"]
        self._watchdog.arm(min((task.watchdog_s for task in self._tasks), default=DEFAULT_WATCHDOG_S))
        try:
            result = code(*inputs, reference)
            if isinstance(result, GeneratorType):  # the debug variant: run it through (no halt outside a scan)
                result = drained(result)
            return result
        except Exception as error:
            fault = self._located_fault(error, "monitoring", now)
            raise AccessorFault(f"{path}: its {kind} faulted: {fault.text()}", fault) from None

    # ------------------------------------------------------------------ outside the task configuration (tests)

    def attach(self, name: str, pou: str, links: dict[str, str] | None = None) -> object:
        """A new instance of the PROGRAM or FUNCTION_BLOCK ``pou`` that no task runs, reachable by path as
        ``name`` (read, write, force, probes, snapshot, state) until a reset; returns it.

        ``links`` binds VAR_IN_OUT slots of the instance to program instances of the configuration (slot ->
        program name), so its code reads and writes them (a test's ``Main.Start := TRUE``)."""
        key, pou_key = name.upper(), pou.upper()
        obj = self._ns[names.pou_class(self._context.pous[pou_key].name)]()
        layout = self._context.layouts[pou_key]
        for slot, program in (links or {}).items():
            place = layout.get(slot)
            owner = obj if place.page == 0 else getattr(obj, f"ll_p{place.page}")
            setattr(owner, place.attr, self._resolver.resolve(program).reference(self._roots))
        self._attached[key] = (obj, pou_key)
        self._links[key] = dict(links or {})
        self._resolver.attach(key, pou_key)
        self._paths = None
        return obj

    def call(self, obj: object, *, limit_s: float, passthrough: tuple[type[BaseException], ...] = ()) -> Fault | None:
        """Run one call of an (attached) instance now, outside any scan, under a watchdog of ``limit_s``: a
        test's body. Scans it runs (``cycle`` from a function it calls) keep their own task watchdogs. A runtime
        error becomes the returned Fault; exceptions of the ``passthrough`` types reach the caller."""
        self._not_halted()
        now = self._ns["ll_now"]
        self._watchdog.arm(limit_s)
        try:
            obj.execute(now)  # type: ignore[attr-defined]  # generated POU classes and their namespace are untyped
        except passthrough:
            raise
        except Exception as error:
            return self._located_fault(error, "", now)
        finally:
            self._watchdog.deadline = float("inf")
        return None

    def advance_clock(self, ms: float) -> None:
        """Move the virtual clock ``ms`` forward without a scan: FB calls outside scans see the new time, and
        each task is next due at its first interval after it (ADVANCE_TIME)."""
        if not ms >= 0:
            raise ValueError(f"the clock only moves forward, not by {ms} ms")
        now = max(self.time_ms, self._ns["ll_now"]) + ms
        self._schedule.skip_to(now)
        self._ns["ll_now"] = now

    def replace_function(self, name: str, function: Callable[..., object]) -> None:
        """Every later call of the user FUNCTION ``name`` calls ``function`` with its arguments (fast and
        monitor variants: inputs, then VAR_IN_OUT references as (container, key))."""
        pou = self._context.pous.get(name.upper())
        if pou is None or pou.kind != "function":
            raise UnknownPath(f"no user FUNCTION {name!r}")
        self._ns[names.function(pou.name)] = function

    def mock(self, obj: object) -> None:
        """From now on calls of this FB instance are counted and its body does not run (MOCK). Only a program
        lowered for unit tests (``mockable``) calls a standard FB's body through its class."""
        if not self.compiled.program.mockable:
            raise RuntimeError("MOCK needs a program lowered with its unit tests (ir.Program.mockable)")
        self.mocks.mock(obj)

    # ------------------------------------------------------------------ debugging

    def _debugging(self) -> Debugger:
        if self.debugger is None:
            raise RuntimeError("breakpoints and stepping need a simulation built with variant='debug'")
        return self.debugger

    def resume(self) -> Halt | None:
        """Continue a halted scan to its end or the next breakpoint; returns the new halt (None: scan ended)."""
        self._debugging()
        if self.halted is None:
            raise RuntimeError("the simulation is not halted")
        return self._continue(None)

    def step(self, granularity: str = "statement") -> Halt | None:
        """Run to the next pause point of this granularity: statement (into calls) | over | out | network |
        transition | cycle.

        Halted: continue the current scan (``over`` passes over the calls the halted POU makes,
        ``out`` runs until its caller goes on; a breakpoint on the way halts first). Not halted:
        start the next scan and stop at its first such point. Returns the new halt (None: the scan ended).
        ``transition`` stays armed in the scans that follow until an SFC transition fires
        (``debugger.waiting_for_transition``): run scans to get there."""
        debugger = self._debugging()
        debugger.arm(granularity)
        if self.halted is None:
            self.cycle(1)
            return self.halted
        ends = STEP_ENDS.get(granularity)
        start = self._call_frames()
        halt = self._continue(granularity)
        while halt is not None and ends is not None and halt.reason == "step" and not ends(self._call_frames(), start):
            halt = self._continue(granularity)
        return halt

    def _call_frames(self) -> tuple[object, ...]:
        """The task and the POU calls the halted scan is suspended in, outermost first: their generators
        (``yield from`` chains one per call), without the chunk functions that hold parts of one POU's body."""
        return tuple(g for g in self._generators() if not names.is_chunk_function(g.gi_code.co_name))

    def _generators(self) -> Iterator[GeneratorType]:
        """The generators of the halted scan, outermost first, without the scan's own (``_debug_scan``,
        ``_debug_tasks``): the task's, then each POU call's and its body's parts, each suspended in the next."""
        frame = cast("GeneratorType | None", self._scan)  # the debug scan is a generator
        while frame is not None:
            if frame.gi_code not in _SCHEDULER_CODE:
                yield frame
            frame = frame.gi_yieldfrom

    def call_stack(self) -> tuple[CallFrame, ...]:
        """The POU calls the halted scan stands in, outermost first, with a FUNCTION's or METHOD's own variables
        (engine/call_stack.py); empty when not halted."""
        if self.halted is None:
            return ()
        return call_stack(self._generators(), self.halted, self.compiled.generated, self._instance_path)

    def _continue(self, granularity: str | None) -> Halt | None:
        self.debugger.arm(granularity)  # type: ignore[union-attr]  # the debug variant is in use on this path
        self.halted = None
        self._watchdog.resume(self._watchdog_left)
        self._drive()
        return self.halted

    def set_breakpoint(
        self,
        pou: str,
        *,
        line: int | None = None,
        network: str | None = None,
        element: str | None = None,
        body: str | None = None,
    ) -> list[int]:
        """Halt before an ST statement (line), an LD/FBD network, or at an element (an SFC step, transition...);
        ``body`` names the action or named transition of an SFC POU they are in. Returns the pause point ids."""
        return self._debugging().add_breakpoint(pou, line=line, network=network, element=element, body=body)

    def clear_breakpoint(
        self,
        pou: str,
        *,
        line: int | None = None,
        network: str | None = None,
        element: str | None = None,
        body: str | None = None,
    ) -> None:
        self._debugging().remove_breakpoint(pou, line=line, network=network, element=element, body=body)

    def clear_breakpoints(self) -> None:
        self._debugging().clear_breakpoints()

    # ------------------------------------------------------------------ probes

    def probes(self, instance: str, elements: Iterable[str] | None = None) -> ProbeView:
        """Probe values of a POU instance (``MAIN``, ``MAIN.FB1``) or a FUNCTION (by name): monitor and debug variants.

        ``values``: the last value each element computed (elements that never ran are left out);
        ``executed``: the elements that ran in the last scan (while halted: so far in this scan).
        ``elements``: only these are read (unknown ones are left out): an online view watches the networks it
        shows, and reading every element of a 10,000-network POU after a scan costs more than the scan."""
        if self.variant == "fast":
            raise RuntimeError("probes need a simulation built with variant='monitor' or 'debug'")
        key = instance.strip().upper()
        pou = self._context.pous.get(key)
        function = pou is not None and pou.kind == "function"  # (a FUNCTION's networks are always recorded)
        wanted = None if elements is None else tuple(elements)
        recorded: dict[int, bool] = {}
        if function:
            escaped = names.escape(pou.name)  # type: ignore[union-attr]  # function: pou is set
            values, stamps = self._ns[f"ll_pr_{escaped}"], self._ns[f"ll_px_{escaped}"]
            plan = self._frame_plan(key, self.compiled.generated.context.probes_of(pou.name), wanted, False)  # type: ignore[union-attr]  # as above
        else:
            found = self._instances_by_path().get(key)
            if found is None:
                known = [
                    *self._instance_paths().values(),
                    *(p.name for p in self._context.pous.values() if p.kind == "function"),
                ]
                raise UnknownPath(f"no POU instance {instance!r}{did_you_mean(instance, known)}")
            obj, pou_key = found
            table = self.compiled.generated.context.probes_of(pou_key)
            plan = self._frame_plan(key, table, wanted, self.variant == "monitor" or self.quiet)
            recorded = {network: self._recorded(key, obj, network) for network in plan.networks}
            if elements is None:
                self._read_deferred(obj, table)
            else:
                self._read_some_deferred(key, obj, table, plan.deferred, recorded)
            values, stamps = obj.ll_pr, obj.ll_px  # type: ignore[attr-defined]  # generated POU classes and their namespace are untyped
        found_values, executed, unknown = plan.read(values, stamps, self._stamp, recorded, UNSET)
        stamp, stopped = self._stopped
        if stamp == self._stamp and key in stopped:  # the elements after a fault did not run, though their group did
            return ProbeView(found_values, frozenset(executed) - stopped[key], frozenset(unknown))
        return ProbeView(found_values, frozenset(executed), frozenset(unknown))

    def _probe_owner(self, frame: FrameType, pou: str) -> str | None:
        """The ``probes`` key of the probes a generated frame running ``pou``'s code stores (``stopped_elements``):
        its instance's path when that instance is of ``pou`` (not a method's or a base body's), a FUNCTION's name."""
        me = frame.f_locals.get("self")
        if me is None:
            found = self._context.pous.get(pou.upper())
            return pou.upper() if found is not None and found.kind == "function" else None
        path = self._instance_path(me)
        entry = self._instances_by_path().get(path.upper()) if path is not None else None
        return path.upper() if entry is not None and entry[1] == pou.upper() else None  # type: ignore[union-attr]  # path is set with entry

    def _frame_plan(self, key: str, table: ProbeTable, elements: tuple[str, ...] | None, networks: bool) -> FramePlan:
        """``frame_plan`` of these elements, kept for the next frame (a client asks for the same ones each time)."""
        plans = self._frame_plans
        plan = plans.get((key, elements, networks))
        if plan is None:
            if len(plans) >= _FRAME_PLANS:
                plans.clear()
            plan = plans[(key, elements, networks)] = frame_plan(table, elements, networks)
        return plan

    def _recorded(self, instance: str, obj: object, network: int) -> bool:
        """Whether the last scan recorded the probes of the instance's ``network``: viewed since before it began, and
        not a scan that recorded no network (``record``)."""
        if self._quiet_stamp == self._stamp:
            return False
        return obj.ll_v[network] and self._viewed_since.get((instance, network), -1) < self._stamp  # type: ignore[attr-defined]  # generated POU classes and their namespace are untyped

    def view(self, viewed: dict[str, Iterable[str] | None] | None) -> None:
        """Record the power flow (monitor variant) only of the networks that hold ``viewed``'s elements: POU instance
        path -> element ids (None: all its networks); the networks of other instances record none; ``viewed`` None:
        every network (as a new simulation does). A network costs its probes only while viewed (docs/runtime.md,
        "Viewed networks"); one starts being recorded with the next scan (``probes`` lists its elements as
        ``unknown`` until then). The debug variant records every probe. Which networks are viewed is part of the
        state (``state``), so a restored scan knows which networks it recorded."""
        self._viewed = None if viewed is None else {key.strip().upper(): ids for key, ids in viewed.items()}
        self._unsilence()  # (the flags set are the real ones; the next quiet scan silences them again)
        self._mutes = None
        tables = self.compiled.generated.context.probe_tables
        if not any(table.networks for table in tables.values()):
            return  # no network records anything (the fast variant): no instance to walk (50,000 networks: ~0.1 s)
        for key, (obj, pou) in self._instances_by_path().items():
            table = tables.get(pou.upper())
            if table is None or not table.networks:
                continue
            ids = None if self._viewed is None else self._viewed.get(key, ())
            if ids is None:
                wanted = set(range(table.networks))
            else:
                indices = (table.index(e) for e in ids)
                wanted = {table.network_of[i] for i in indices if i is not None and i in table.network_of}
            flags = obj.ll_v  # type: ignore[attr-defined]  # generated POU classes and their namespace are untyped
            for network in range(table.networks):
                on = network in wanted
                if on and not flags[network]:
                    self._viewed_since[(key, network)] = self._stamp
                flags[network] = on
            self.compiled.compile_viewed(self._ns, pou.upper(), flags)

    def record(self, on: bool) -> None:
        """Whether the next scans record the power flow of the viewed networks (monitor variant; docs/runtime.md,
        "Scans no frame shows"). Off, each scan runs every network as if nobody viewed it (the twins without
        probes), and until a recording scan ran, ``probes`` lists the elements of every network as ``unknown``,
        never a stale value (``quiet``). A server's runner records only the scans a frame may show
        (simulation/runner.py). FUNCTIONs and bodies other than networks record in every scan, as always."""
        self._record = on

    @property
    def quiet(self) -> bool:
        """Whether the last scan recorded no network's power flow (``record``)."""
        return self._quiet_stamp == self._stamp

    def _fit_recording(self) -> None:
        """Before scans: silence the viewed networks (``record(False)``, monitor variant) or give them their flags
        back. Silenced, each instance's ``ll_v`` is a list of False of its own (the generated code reads it at
        every call), so its flags stay as ``view`` set them; a state captured meanwhile says no network recorded."""
        if self._record or self.variant != "monitor":
            self._unsilence()
        elif self._silenced is None:
            self._silence()

    def _silence(self) -> None:
        mutes = self._mutes
        if mutes is None:
            mutes = self._mutes = []
            for obj, _pou in self._instances_by_path().values():
                flags = getattr(obj, "ll_v", None)
                if flags and True in flags:
                    mutes.append((obj, flags, [False] * len(flags)))  # (nothing writes into it: unsilenced first)
        for obj, _flags, off in mutes:
            obj.ll_v = off  # type: ignore[attr-defined]  # generated POU classes and their namespace are untyped
        self._silenced = mutes

    def _unsilence(self) -> None:
        """The instances' own flags back (``_fit_recording``); ``quiet`` still says what the last scan recorded."""
        if self._silenced is not None:
            for obj, flags, _off in self._silenced:
                obj.ll_v = flags  # type: ignore[attr-defined]  # generated POU classes and their namespace are untyped
            self._silenced = None

    def _context_probes(self, pou: str) -> ProbeTable | None:
        return self.compiled.generated.context.probe_tables.get(pou.upper())

    def _read_deferred(self, obj: object, table: ProbeTable) -> None:
        """Fill in the probes the monitor code reads after the scan (codegen/deferred.py); never-run ones stay unset."""
        if not table.deferred or self.variant != "monitor":
            return
        obj.ll_read_probes()  # type: ignore[attr-defined]  # generated POU classes and their namespace are untyped
        values, stamps = obj.ll_pr, obj.ll_px  # type: ignore[attr-defined]  # generated POU classes and their namespace are untyped
        for index in table.deferred:
            if all(stamps[g] < 0 for g in table.groups[index]):
                values[index] = UNSET

    def _read_some_deferred(
        self,
        program: str,
        obj: object,
        table: ProbeTable,
        deferred: Iterable[tuple[int, int | None, int, tuple[int, ...]]],
        recorded: dict[int, bool],
    ) -> None:
        """``_read_deferred`` for the ``deferred`` probes (number, network run, groups: ``FramePlan.deferred``) only,
        those of networks the last scan recorded: each reads its variable where its path led the first time (a
        deferred probe's path has members only; ``reset`` and ``restore`` forget the places)."""
        if self.variant != "monitor":
            return
        values, stamps = obj.ll_pr, obj.ll_px  # type: ignore[attr-defined]  # generated POU classes and their namespace are untyped
        pairs = self._deferred_pairs
        for index, network, first, more in deferred:
            if network is not None and not recorded[network]:
                continue  # (shown as unknown)
            last = stamps[first] if first >= 0 else -1
            for g in more:
                last = max(last, stamps[g])
            if last < 0:  # never ran
                values[index] = UNSET
                continue
            pair = pairs.get((program, index))
            if pair is None:
                location = self._resolver.resolve(f"{program}.{table.deferred_paths[index]}")
                pair = pairs[(program, index)] = location.reference(self._roots)
            container, key = pair
            values[index] = container[key]  # type: ignore[index]  # an instance or a page (Addressable)

    # ------------------------------------------------------------------ instances

    def instances(self) -> dict[str, list[str]]:
        """Instance paths of every program and function block, by POU name (upper case):
        ``{"BLINKER": ["MAIN.BLINK"]}``.

        The online views show one instance of a POU at a time; this lists the ones to choose from."""
        found: dict[str, list[str]] = {}
        for path, (_obj, pou) in self._instances_by_path().items():
            found.setdefault(pou, []).append(path)
        return found

    def _instances_by_path(self) -> dict[str, tuple[object, str]]:
        """Upper-case path -> (user POU instance, upper-case POU name), cached until reset."""
        self._instance_paths()
        return self._instances

    def _instance_paths(self) -> dict[int, str]:
        """id(user POU instance) -> path (``MAIN``, ``MAIN.FB1``, ``MAIN.ARR[2]``, ``GFB``), cached until reset."""
        if self._paths is None:
            self._paths, self._instances = {}, {}
            for key, (obj, pou) in self._attached.items():
                self._add_instance(key, obj, pou)
            for place in self._context.globals.places.values():
                value = getattr(self._roots.get(("global", "G" if not place.page else f"G{place.page}")), place.attr)
                self._add_values(place.slot.name, place.slot.type, value)
        return self._paths

    def _add_instance(self, path: str, obj: object, pou: str) -> None:
        self._paths[id(obj)] = path  # type: ignore[index]  # generated POU classes and their namespace are untyped
        self._instances[path.upper()] = (obj, pou)
        layout = self._context.layouts[pou]
        for place in layout.places.values():
            if place.slot.var_class == "VAR_IN_OUT" or not isinstance(place.slot.type, _HOLDERS):
                continue  # (no path made for the elementary slots: a 50,000-network POU has 200,000)
            owner = obj if place.page == 0 else getattr(obj, f"ll_p{place.page}")
            self._add_values(f"{path}.{place.slot.name}", place.slot.type, getattr(owner, place.attr))

    def _add_values(self, path: str, ty: t.IrType, value: object) -> None:
        if isinstance(ty, t.FbInstance) and self._context.user_fb(ty.fb) is not None:
            self._add_instance(path, value, ty.fb.upper())
        elif isinstance(ty, t.Array) and isinstance(ty.element, (t.FbInstance, t.Array, t.Struct)):
            lo = ty.dims[0][0]
            inner = t.Array(ty.element, ty.dims[1:]) if len(ty.dims) > 1 else ty.element
            for offset, item in enumerate(value):  # type: ignore[arg-type]  # generated POU classes and their namespace are untyped
                self._add_values(f"{path}[{lo + offset}]", inner, item)
        elif isinstance(ty, t.Struct):
            for f in ty.fields:
                self._add_values(f"{path}.{f.name}", f.type, getattr(value, names.slot(f.name)))

    def _instance_path(self, obj: object) -> str | None:
        return self._instance_paths().get(id(obj))

    # ------------------------------------------------------------------ the process image

    def published(self, address: str) -> object:
        """An output address (``%QX3.0``, ``%QW4``) as the last finished scan published it to the world, forces
        applied; paths read the program's image instead, which a halted scan may have changed since."""
        location = self.location(address)
        parsed = parse_address(address)
        if parsed.area != "Q":
            raise ValueError(f"{parsed.text} is not an output: only %Q addresses are published")
        return self._image.view("outputs", view_kind(parsed, runtime_name(location.type)))[key_of(parsed)]

    def io_points(self) -> list[IoPoint]:
        """Every address the program uses, inputs first (I, Q, M, S, then by byte and bit), with the variables
        declared at it: globals by name, a program's or FB's by every instance path."""
        instances = self.instances()
        points: dict[tuple, IoPoint] = {}
        owners = [("", self._context.globals)] + [(pou, layout) for pou, layout in self._context.layouts.items()]
        for pou, layout in owners:
            for slot in layout.located.values():
                address = located_address(slot.address)
                bit = address.bit if address.bit is not None else -1
                key = (AREA_ORDER.index(address.area), address.offset, bit, address.width, address.text)
                point = points.setdefault(key, IoPoint(address.area, address.text, runtime_name(slot.type) or ""))
                if slot.name.upper() != (slot.address or "").upper():  # a declared name
                    paths = [slot.name] if not pou else [f"{path}.{slot.name}" for path in instances.get(pou, [])]
                    point.names += paths
        return [points[key] for key in sorted(points)]

    # ------------------------------------------------------------------ variables

    def location(self, path: str) -> Location:
        return self._resolver.resolve(path)

    def value(self, location: Location) -> object:
        """Raw current value at a resolved location: for callers that resolve paths once and read every scan."""
        return location.get(self._roots)

    def reader(self, locations: dict[str, Location]) -> LocationReader:
        """A reader of many resolved locations at once (the online monitor's frames); valid across resets."""
        return LocationReader(locations, self._roots, self._context)

    def read(self, path: str, *, enum_literals: bool = False) -> object:
        """Current value (arrays as lists, structures and FB instances as dicts; ``enum_literals``: enumerations
        as ``TCOLOR#Red``, else numbers)."""
        location = self._resolver.resolve(path)
        return plain(self._context, location.type, location.get(self._roots), enum_literals=enum_literals)

    def write(self, path: str, value: object) -> None:
        """Write once, before the next scan (at once while halted); the program may overwrite it."""
        self.submit(InputEvent("write", path, value))

    def force(self, path: str, value: object) -> None:
        """Hold a variable at ``value`` before and after every scan (from the next, at once while halted),
        until ``unforce``."""
        self.submit(InputEvent("force", path, value))

    def unforce(self, path: str) -> None:
        self.submit(InputEvent("release", path))

    def unforce_all(self) -> None:
        self.submit(InputEvent("release_all"))

    @property
    def forced(self) -> dict[str, object]:
        """Forced variables by canonical path (a force waiting for the next scan counts already)."""
        forced = {path: value for path, (_, value) in self._forces.items()}
        for event, location, prepared in self._pending:
            if event.kind == "force" and location is not None:
                forced[location.path] = prepared
            elif event.kind == "release" and location is not None:
                forced.pop(location.path, None)
            elif event.kind == "release_all":
                forced.clear()
        return forced

    @property
    def injected(self) -> dict[str, str]:
        """Variables with an injected fault, by canonical path: the fault's mode."""
        return {path: injected.event.mode or "" for path, (_, injected) in self._injections.items()}

    @property
    def pending(self) -> list[InputEvent]:
        """Inputs waiting for the start of the next scan, in the order they will apply."""
        return [event for event, _, _ in self._pending]

    # ------------------------------------------------------------------ inputs (inputs.py)

    def submit(self, event: InputEvent) -> None:
        """Give the simulation an input: applied at the start of the next scan, or at once (a reset; a user's
        write, force or release while a scan is halted). Checked now: raises InputRefused, UnknownPath or
        ValueError (a value that does not fit its variable) and nothing happens."""
        event.check()
        location = self._resolver.resolve(event.path) if event.path else None
        event, prepared = self._prepare(event, location)
        if immediate(event, halted=self.halted is not None):
            self._apply(event, location, prepared, halted=self.halted is not None)
        else:
            self._pending.append((event, location, prepared))

    def _prepare(self, event: InputEvent, location: Location | None) -> tuple[InputEvent, object]:
        """What applying the event needs: the value for its variable, or the fault to hold there. A ``stuck``
        fault without a value gets the variable's value now, so the event alone says what it holds."""
        if location is not None and location.called:
            self._refuse_called(event, location)
        if event.kind in ("write", "force", "panel"):
            assert location is not None  # ``check`` made sure these kinds name a variable
            value = coerce_for(location, event.value)
            if location.through_pointer:  # NoTarget (a ValueError: refused) while the pointer is NULL, or when what
                location.trial(self._roots, value)  # it points to cannot hold the value (engine/codegen/views.py)
            return event, value
        if event.kind != "fault":
            return event, None
        assert location is not None
        if location.through_pointer:
            raise InputRefused(f"{location.path}: inject faults on the variable itself, not through a pointer")
        if not location.elementary:
            raise InputRefused(f"{location.path}: faults act on one BOOL or numeric signal at a time")
        if event.mode == "stuck" and event.value is None:
            event = replace(event, value=location.get(self._roots))
        try:
            return event, injection(event, location.type, lambda value: coerce_for(location, value))
        except InputRefused as error:
            raise InputRefused(f"{location.path}: {error}") from None

    def _refuse_called(self, event: InputEvent, location: Location) -> None:
        """InputRefused unless ``event`` is a write of a property monitored as 'call' between scans (its SET runs
        once; CODESYS: "read or written by calling the property"): nothing holds its value to force or fault."""
        if event.kind in ("force", "fault"):
            raise InputRefused(
                f"{location.path} is a property monitored as 'call': a write runs its SET once, and no variable holds "
                f"its value to {event.kind}"
            )
        if event.kind in ("write", "panel") and self.halted is not None:
            raise InputRefused(f"{location.path}: its SET runs only between scans; the scan is halted in the middle")

    def _apply_inputs(self) -> None:
        """The inputs waiting for this scan, in order; a second panel event on a variable waits a scan more."""
        pending, self._pending = self._pending, []
        panel: set[str] = set()  # variables a panel event was applied to at this scan start
        waiting: set[str] = set()  # variables with an event that waits: later events on them wait too
        for event, location, prepared in pending:
            key = location.path if location is not None else None
            if key is not None and (key in waiting or (event.kind == "panel" and key in panel)):
                waiting.add(key)
                self._pending.append((event, location, prepared))
                continue
            self._apply(event, location, prepared, halted=False)
            if event.kind == "panel" and key is not None:
                panel.add(key)

    def _apply(self, event: InputEvent, location: Location | None, prepared: object, halted: bool) -> None:
        kind = event.kind
        if kind in ("write", "panel", "force", "release", "release_all"):  # (a constant input's: stored_once.py)
            self._stored_once.touched(location)
        if kind in ("write", "panel") and location is not None and location.called:
            try:
                location.set(self._roots, prepared)
            except AccessorFault as error:  # logged where the SET faulted (the runner); the tasks go on
                self.accessor_faults.append(error.fault)  # type: ignore[arg-type]  # a Fault (paths.py keeps it untyped)
        elif kind in ("write", "panel") and location is not None:
            _set(location, self._roots, prepared)
        elif kind == "force" and location is not None:
            self._forces[location.path] = (location, prepared)
            _set(location, self._roots, prepared)
        elif kind == "release" and location is not None:
            self._forces.pop(location.path, None)
        elif kind == "release_all":
            self._forces.clear()
        elif kind == "fault" and location is not None and isinstance(prepared, Injection):
            self._injections[location.path] = (location, prepared)
            self._stored_once.injected(where for where, _ in self._injections.values())
        elif kind == "clear_fault":
            if location is None:
                lifted = list(self._injections.values())
                self._injections.clear()
            else:
                one = self._injections.pop(location.path, None)
                lifted = [one] if one is not None else []
            for where, fault in lifted:  # the signal as its writer (a plant, a panel, a test) last left it
                where.set(self._roots, fault.lifted(where.get(self._roots)))
            self._stored_once.injected(where for where, _ in self._injections.values())
        scan = self.scan_count
        applied = (
            AppliedInput(event, scan, "halt", self._halt_pid, self._halts) if halted else AppliedInput(event, scan)
        )
        if kind == "reset":
            self._reset(event.cold)
        if self.on_input is not None:
            self.on_input(applied)

    def _cross(self, plants_next: bool = False) -> None:
        """Where signals cross between the plants and the program: injected faults, then forces (a force wins).

        Before the plants run, a fault on a plant's own variable (``Tank.Level``) is lifted: the plant computes
        its process from the true value, and only the program reads the faulted one (a noisy level would
        otherwise feed its noise back into the physics and wander off)."""
        for location, injected in self._injections.values():
            current, owned = location.get(self._roots), self._plant_owned(location)
            if plants_next and owned:
                location.set(self._roots, injected.lifted(current))
            else:  # after the plants ran, their own variables hold what they just computed: the true signal
                location.set(self._roots, injected.value(current, fresh=owned and not plants_next))
        self._apply_forces()

    def _plant_owned(self, location: Location) -> bool:
        """Whether the variable lives in a plant's instance (its path starts with the instance's name)."""
        return location.path.split(".", 1)[0].upper() in self._plant_instances

    def _apply_forces(self) -> None:
        for location, value in self._forces.values():
            _set(location, self._roots, value)

    # ------------------------------------------------------------------ state (engine/state.py)

    def state(self) -> SimState:
        """The whole state between scans as plain data (not while halted). After a scan that recorded no network
        (``quiet``), its flags say so: a simulation it is restored into shows those networks as unknown."""
        self._not_halted()
        if self.quiet and self._silenced is None:
            self._silence()
            try:
                return self.state()
            finally:
                self._unsilence()
        pages = sorted({global_owner(p.page) for p in self._context.globals.places.values()})
        return SimState(
            self.compiled.declarations_digest,
            self.time_ms,
            self._ns["ll_now"],
            self.scan_count,
            self._stamp,
            tuple((task.next_due, task.stopped, task.trigger) for task in self._tasks),
            {name: data_of(obj) for name, (obj, _pou) in self._attached.items()},
            {page: data_of(self._ns[page]) for page in pages},
            self._image.state(),
            {path: value for path, (_, value) in self._forces.items()},
            {name: (pou, dict(self._links.get(name, {}))) for name, (_obj, pou) in self._attached.items()},
            {path: (fault.event.to_json(), fault.state()) for path, (_, fault) in self._injections.items()},
            tuple(event.to_json() for event, _, _ in self._pending),
            {name: data_of(self._ns[name]) for name in self._function_probe_lists()},
            dict(self._stopped[1]) if self._stopped[0] == self._stamp else {},
        )

    def _function_probe_lists(self) -> list[str]:
        """The module-level probe lists of the FUNCTION POUs (values and stamps; a function has no instance to hold
        them), in the monitor and debug variants: a restored scan shows the power flow of the functions it ran."""
        escaped = [names.escape(pou.name) for pou in self._context.pous.values() if pou.kind == "function"]
        return [name for key in escaped for name in (f"ll_pr_{key}", f"ll_px_{key}") if name in self._ns]

    def restore(self, state: SimState) -> None:
        """Make this simulation's state ``state`` (captured from a simulation of the same program): variables,
        instances, probes, clock, tasks, forces, injected faults, waiting inputs, attached instances. Faults
        are cleared, a halted scan ended. A restore is no input: ``on_input`` hears nothing of it."""
        if state.declarations != self.compiled.declarations_digest:
            raise ValueError("that state was captured from another program")
        data = [*state.instances.values(), *state.globals.values()]
        self._unsilence()  # (the state's flags go into the instances' own lists)
        self._mutes = None
        # a state that holds every value overwrites all an initialisation would set (about half a restore's time)
        self._reset(cold=True, initialise=any(holds_references(item) for item in data), implicit=False)
        for name, (pou, links) in state.attached.items():
            if name not in self._attached:
                self.attach(name, pou, links)
        for name, data in state.instances.items():
            restore_into(self._attached[name][0], data)  # type: ignore[arg-type]  # captured slot data is a dict
        for page, data in state.globals.items():
            restore_into(self._ns[page], data)  # type: ignore[arg-type]  # captured slot data is a dict
        for name, data in state.functions.items():
            restore_list(self._ns[name], data)  # type: ignore[arg-type]  # captured probe lists are lists
        self._image.restore(state.image)
        self._schedule.time_ms = state.time_ms
        for task, (due, stopped, trigger) in zip(self._tasks, state.tasks):
            task.next_due, task.stopped, task.trigger = due, stopped, trigger
        self._ns["ll_now"] = state.now
        self.scan_count = state.scan_count
        self._stamp = state.stamp
        self._ns["ll_scan"] = state.stamp
        self._quiet_stamp = -1  # (a state captured after a quiet scan holds its silenced flags: ``_fit_recording``)
        self._stopped = (state.stamp, dict(state.stopped))
        self._forces.clear()
        for path, value in state.forces.items():
            location = self._resolver.resolve(path)
            self._forces[location.path] = (location, coerce_for(location, value))
        self._apply_forces()
        self._injections.clear()
        for path, (data, carried) in state.injections.items():
            location = self._resolver.resolve(path)
            _, fault = self._prepare(InputEvent.from_json(data), location)
            assert isinstance(fault, Injection)  # the event of a fault prepares an injection
            fault.set_state(carried)  # type: ignore[arg-type]  # the plain data Injection.state() gave
            self._injections[location.path] = (location, fault)
        self._stored_once.everything()  # (captured after a write, a pin may hold another value)
        self._stored_once.injected(where for where, _ in self._injections.values())
        self._pending = []
        for data in state.pending:
            event = InputEvent.from_json(data)
            location = self._resolver.resolve(event.path) if event.path else None
            self._pending.append((event, location, self._prepare(event, location)[1]))
        self._viewed_since.clear()  # the state says which networks its last scan recorded (ll_v)
        if self._viewed is not None:  # this simulation's monitor views these from the next scan on
            self.view(self._viewed)

    def snapshot(self) -> dict[str, object]:
        """Every elementary variable of every program instance and every global: path -> value."""
        return dict(leaves(self._context, self._roots))


def _set(location: Location, roots: Roots, value: object) -> None:
    """Write a user's value; through a pointer that is NULL now (``p^``) there is no variable and nothing is
    written: a force through a pointer holds whatever the pointer points to, scan by scan (ON-11)."""
    with contextlib.suppress(NoTarget):
        location.set(roots, value)


#: Frame plans a simulation keeps (Simulation._frame_plan): a few clients' views of a few POUs each
_FRAME_PLANS = 64


#: The debug scan's own generators, above the task's: no call of the program's (Simulation._call_frames).
_SCHEDULER_CODE = (Simulation._debug_scan.__code__, Simulation._debug_tasks.__code__)
