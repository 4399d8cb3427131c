"""Scan history (issue 23): record a running simulation's nondeterminism, recompute any past scan exactly.

A scan is a function of the state before it and of what entered from outside: the inputs applied at its
start (``engine/inputs.py``: writes, forces, releases, panel events, faults, resets) and, for a scan not
chosen by the schedule (``scan_at``), its virtual time. So the history keeps only that, per scan, plus
full-state checkpoints (``engine/state.py``), and ``seek(k)`` restores the nearest checkpoint into a
second simulation of the same program and runs the scans up to ``k`` again, feeding them the recorded
inputs. An idle scan adds nothing to the log.

What a replay cannot redo is kept as a checkpoint at once: a scan that a user changed while it was halted
at a breakpoint (``halt``-phase inputs), a scan that ended with a fault (a watchdog trip depends on the
machine's speed), a scan a reset ended while halted. Checkpoints are taken adaptively: every
``interval`` scans, where the interval keeps the CPU time spent capturing near ``overhead`` (3 %) of the CPU
time of the scans - the scans after a capture pay a little more, refilling the caches it went through, so the
recording as a whole stays near 5 % - and the replay of one interval within ``seek_ms``; or after
``log_bytes`` of input log. Checkpoints and log live in ``budget_bytes`` (default 256 MB): the oldest
checkpoint and the log before the next one go first, so history is available from ``first`` on.

    history = History(sim)        # records from now on (it sets sim.on_scan; call history.applied(...)
    history.seek(42)              #   from sim.on_input). Returns the replay simulation at scan 42's end.
"""

from __future__ import annotations

import bisect
import json
import math
import pickle
import statistics
import time
import zlib
from collections import deque
from collections.abc import Callable, Iterable
from dataclasses import dataclass, replace

from ..engine.compile import CompiledProgram
from ..engine.inputs import AppliedInput, InputEvent
from ..engine.simulation import Simulation
from ..engine.state import PathTable, SimState

#: The default memory budget of one simulation's history.
DEFAULT_BUDGET_BYTES = 256 * 1024 * 1024


class HistoryUnavailable(ValueError):
    """A scan outside the recorded history (dropped by the budget, or not run yet): the user's words."""


@dataclass(frozen=True)
class Checkpoint:
    """The state before scan ``scan`` (after scan ``scan - 1``), pickled and compressed."""

    scan: int
    blob: bytes  # the state, its slot paths numbered in the history's PathTable

    def state(self, paths: PathTable) -> SimState:
        state: SimState = pickle.loads(zlib.decompress(self.blob))
        return paths.unshared(state)


class History:
    """The scan history of one live simulation (on its engine thread, like the simulation itself)."""

    def __init__(
        self,
        sim: Simulation,
        *,
        budget_bytes: int = DEFAULT_BUDGET_BYTES,
        overhead: float = 0.03,
        seek_ms: float = 800.0,
        min_interval: int = 16,
        log_bytes: int = 1 << 20,
        clock: Callable[[], float] = time.thread_time,
    ) -> None:
        if budget_bytes <= 0:
            raise ValueError(f"the history budget must be positive, not {budget_bytes} bytes")
        self.live = sim
        self.budget_bytes = budget_bytes
        self.overhead = overhead
        self.seek_ms = seek_ms
        self.min_interval = min_interval
        self.log_bytes = log_bytes
        self._clock = clock
        self.checkpoints: list[Checkpoint] = []
        self._paths = PathTable()
        self._inputs: dict[int, list[bytes]] = {}  # scan -> the inputs applied for it, as JSON, in order
        self._times: dict[int, float] = {}  # scan -> its virtual time, for scans the schedule did not choose
        self._barriers: set[int] = set()  # scans a replay cannot redo: viewed from the checkpoint after them
        self._errors: set[int] = set()  # scans that ended with a runtime error or a watchdog trip
        #: scans that ended with a fault and recorded no network's power flow (``Simulation.quiet``), with their
        #: faults' texts: ``seek`` recomputes them from the checkpoint before, when they fault alike again
        self._quiet_errors: dict[int, list[str]] = {}
        self._marks: dict[int, set[str]] = {}  # scan -> what else happened in it: a breakpoint hit, a trace trigger
        self.marked = 0  # grows with every newly marked scan (an input, an error): the timeline refetches marks
        self.log_size = 0  # bytes of _inputs and _times
        self.checkpoint_size = 0
        self.interval = min_interval
        self._since = 0  # scans since the last checkpoint
        self._log_since = 0  # log bytes since the last checkpoint
        self._faults = len(sim.faults)
        self._capture_s = 0.0
        self._captures: deque[float] = deque(maxlen=9)  # the CPU times of the latest captures
        self._scan_s: float | None = None  # CPU time per scan since the previous checkpoint (scans, the runner)
        self._after: float | None = None  # the clock when the previous checkpoint was taken
        self._replay: Simulation | None = None
        self._ended: int | None = None  # the last scan recorded, once recording ended (``end``)
        self._replay_at: int | None = None  # scans the replay simulation has completed (its scan_count)
        #: the networks a replayed scan records its power flow in (``Simulation.view``'s argument; None: every
        #: network). The runner sets the networks its clients view: the others' probed code is compiled only at
        #: first use, so recording every network would make the first seek of a large program compile it all.
        self.viewed: dict[str, Iterable[str] | None] | None = None
        self._replay_viewed: dict[str, Iterable[str] | None] | None = None  # what the replay records now
        sim.on_scan = self._scanned
        self._checkpoint()

    # ------------------------------------------------------------------ recording (the live engine's hooks)

    @property
    def size(self) -> int:
        """Bytes the history holds: checkpoints and input log."""
        return self.checkpoint_size + self.log_size

    @property
    def capture_s(self) -> float:
        """CPU seconds the last checkpoint took (capture, pickle, compress)."""
        return self._capture_s

    @property
    def first(self) -> int:
        """The oldest scan that can be viewed: the one the oldest checkpoint was taken after (scan 0 when that
        checkpoint is the initial state)."""
        return max(0, self.checkpoints[0].scan - 1)

    @property
    def last(self) -> int:
        """The newest scan that can be viewed (-1 before the first scan)."""
        return self._ended if self._ended is not None else self.live.scan_count - 1

    def end(self) -> None:
        """Stop recording (the live simulation continues from a past scan: a fork); what was recorded stays
        viewable. The replay simulation is let go until the next seek (its memory is a whole program's)."""
        self._ended = self.live.scan_count - 1
        if self.live.on_scan == self._scanned:
            self.live.on_scan = None
        self._replay, self._replay_at = None, None

    def applied(self, applied: AppliedInput) -> None:
        """Record an input as the engine applied it (``Simulation.on_input``)."""
        line = json.dumps(applied.event.to_json(), separators=(",", ":")).encode()
        self.marked += 1
        self._inputs.setdefault(applied.scan, []).append(line)
        self._grow_log(len(line) + 8)
        if applied.phase == "halt":
            self._barriers.add(applied.scan)
            if applied.event.kind == "reset":  # it ended the halted scan: what follows starts from here
                self._checkpoint()

    def mark(self, scan: int, kind: str) -> None:
        """Mark ``scan`` on the timeline with something the runner saw (``breakpoint``: it halted there, ``trigger``:
        a trace's trigger fired at its end); no input, so nothing to replay."""
        if kind not in self._marks.setdefault(scan, set()):
            self._marks[scan].add(kind)
            self.marked += 1

    def _scanned(self, scan: int, time_ms: float, scheduled: bool) -> None:
        if not scheduled:
            self._times[scan] = time_ms
            self._grow_log(16)
        self._since += 1
        faults = len(self.live.faults)
        if faults != self._faults:
            self._faults = faults
            if faults:
                self._barriers.add(scan)
                self._errors.add(scan)
                self.marked += 1
                if self.live.quiet:
                    self._quiet_errors[scan] = [fault.text() for fault in self.live.faults if fault.scan == scan]
        if scan in self._barriers or self._since >= self.interval or self._log_since >= self.log_bytes:
            self._checkpoint()

    def _grow_log(self, size: int) -> None:
        self.log_size += size
        self._log_since += size
        if self.size > self.budget_bytes:
            self._evict()

    def _checkpoint(self) -> None:
        start = self._clock()
        if self._after is not None and self._since:
            self._scan_s = (start - self._after) / self._since
        state = self._paths.shared(replace(self.live.state(), pending=()))  # waiting inputs: in the log when applied
        blob = zlib.compress(pickle.dumps(state, pickle.HIGHEST_PROTOCOL), 1)
        self._after = self._clock()
        self._capture_s = self._after - start
        self._captures.append(self._capture_s)
        scan = self.live.scan_count
        if self.checkpoints and self.checkpoints[-1].scan == scan:
            self.checkpoint_size -= len(self.checkpoints.pop().blob)
        self.checkpoints.append(Checkpoint(scan, blob))
        self.checkpoint_size += len(blob)
        self._since = self._log_since = 0
        self._adapt()
        self._evict()

    def _adapt(self) -> None:
        """Checkpoint as often as ``overhead`` of the scan time allows, but at least every ``seek_ms`` of replay.

        Both times are the engine thread's CPU time (``clock``), so a loaded machine does not shrink the interval."""
        if self._scan_s is None:  # no scan time to go by yet
            self.interval = self.min_interval
            return
        scan_ms = max(self._scan_s * 1000.0, 1e-3)
        # The median of the latest captures: what one costs, but for noise (a full GC in one) and the first few,
        # before CPython specialises the generated code that reads the slots (state.py). Not the cheapest: that
        # one set an interval whose captures cost more than ``overhead`` (benchmarks/RESULTS.md).
        capture_ms = statistics.median(self._captures) * 1000.0
        cheap = math.ceil(capture_ms / (self.overhead * scan_ms))
        bounded = max(self.min_interval, math.floor(self.seek_ms / scan_ms))
        self.interval = max(self.min_interval, min(cheap, bounded))

    def _evict(self) -> None:
        """Drop the oldest checkpoints (and the log before the next one) until the history fits its budget."""
        while self.size > self.budget_bytes and len(self.checkpoints) > 1:
            self.checkpoint_size -= len(self.checkpoints.pop(0).blob)
            first = self.checkpoints[0].scan
            for scan in [scan for scan in self._inputs if scan < first]:
                self.log_size -= sum(len(line) + 8 for line in self._inputs.pop(scan))
            for scan in [scan for scan in self._times if scan < first]:
                del self._times[scan]
                self.log_size -= 16
            self._barriers = {scan for scan in self._barriers if scan >= first}
            self._errors = {scan for scan in self._errors if scan >= first}
            self._quiet_errors = {scan: texts for scan, texts in self._quiet_errors.items() if scan >= first}
            self._marks = {scan: kinds for scan, kinds in self._marks.items() if scan >= first}
            if self._replay_at is not None and self._replay_at < first:
                self._replay_at = None

    # ------------------------------------------------------------------ seeking

    def marks(self, limit: int = 1000) -> list[tuple[int, list[str]]]:
        """The newest ``limit`` scans with an input, an error or a mark, for the timeline: (scan, what happened in
        it: the inputs' kinds - write, force, release, panel, fault, reset... -, ``error``, ``breakpoint``,
        ``trigger``)."""
        scans = sorted(self._inputs.keys() | self._errors | self._marks.keys())[-limit:]
        return [
            (
                scan,
                sorted(
                    {str(line["kind"]) for line in self.inputs_of(scan)}
                    | ({"error"} if scan in self._errors else set())
                    | self._marks.get(scan, set())
                ),
            )
            for scan in scans
        ]

    def inputs_of(self, scan: int) -> list[dict[str, object]]:
        """The inputs applied for ``scan`` (as ``InputEvent`` JSON), in order."""
        return [json.loads(line) for line in self._inputs.get(scan, ())]

    def seek(self, scan: int) -> Simulation:
        """A simulation (the history's own, never the live one) at the end of ``scan``: every variable, FB
        instance and probe as that scan left them. HistoryUnavailable outside ``first``..``last``."""
        if not self.first <= scan <= self.last:
            if scan > self.last:
                raise HistoryUnavailable(f"scan {scan} has not run yet (the last scan is {self.last})")
            raise HistoryUnavailable(f"scan {scan} is no longer in the history: it starts at scan {self.first}")
        replay = self._replay_sim()
        if scan in self._quiet_errors and self._rerun(scan):
            return replay
        if scan in self._barriers or scan < self.checkpoints[0].scan:  # the checkpoint taken after it holds it
            self._restore(self._checkpoint_at(scan + 1))
        else:
            checkpoint = self._checkpoint_at(scan)
            going_on = self._replay_at is not None and checkpoint.scan <= self._replay_at <= scan
            if not (going_on and self._replay_viewed == self.viewed):  # else: a step forward from the last seek
                self._restore(checkpoint)
                replay.view(self.viewed)  # whichever networks the live monitor recorded when the checkpoint was taken
                self._replay_viewed = self.viewed
            assert self._replay_at is not None
            self._replay_scans(self._replay_at, scan)
            self._replay_at = scan + 1
        return replay

    def _rerun(self, scan: int) -> bool:
        """Run a faulted scan that recorded no network again from the checkpoint before it, recording the viewed
        networks, so its power flow is known: True when it faulted alike (a runtime error always does: only the
        watchdog depends on the machine's speed, and the runner records every scan of a program that checks it),
        else the checkpoint after it is restored by ``seek`` (its networks unknown). The next seek restores a
        checkpoint again (the scan stays a barrier)."""
        checkpoint = self._checkpoint_at(scan)
        if checkpoint.scan > scan:
            return False
        replay = self._replay_sim()
        self._restore(checkpoint)
        replay.view(self.viewed)
        self._replay_viewed = self.viewed
        self._replay_scans(checkpoint.scan, scan)
        self._replay_at = None
        return [fault.text() for fault in replay.faults if fault.scan == scan] == self._quiet_errors[scan]

    def _replay_scans(self, first: int, last: int) -> None:
        """Run scans ``first`` to ``last`` again in the replay, each fed its recorded inputs. Every one records the
        viewed networks' power flow: what a seek shows of an element the last scan did not run (an SFC transition's
        last computed condition, a probe's last value) is what the scans before it left, as live."""
        replay = self._replay_sim()
        for number in range(first, last + 1):
            for line in self._inputs.get(number, ()):
                replay.submit(InputEvent.from_json(json.loads(line)))
            if number in self._times:
                replay.scan_at(self._times[number])
            else:
                replay.cycle(1)

    def stepper(self, scan: int, debug: CompiledProgram) -> Simulation:
        """A new simulation of ``debug`` (the program's debug variant) at the start of ``scan``: the state the scan
        before it left, with ``scan``'s recorded inputs waiting, so ``step`` goes through that scan network by
        network or line by line and its end is what ``seek(scan)`` shows. Neither the live simulation nor the
        replay is touched, so the history stays as recorded. HistoryUnavailable outside the history (a seek's
        words), or saying why (``it ...``) for a scan that cannot be redone (changed at a breakpoint, ended with a
        fault, at a time the schedule did not choose) or whose previous state is no longer kept."""
        if not self.first <= scan <= self.last:
            self.seek(scan)  # raises HistoryUnavailable with the words of a seek
        if scan < self.checkpoints[0].scan:
            raise HistoryUnavailable("it is the oldest scan kept: the state before it is no longer in the history")
        if scan in self._times:
            raise HistoryUnavailable("it ran at a time of its caller's choosing")
        if scan in self._barriers:
            raise HistoryUnavailable(
                "it ended with a runtime error" if scan in self._errors else "it was changed while halted"
            )
        checkpoint = self._checkpoint_at(scan)
        state = checkpoint.state(self._paths) if checkpoint.scan == scan else self.seek(scan - 1).state()
        stepper = Simulation(debug, watchdog_s=self.live.watchdogs)
        stepper.restore(state)
        for line in self._inputs.get(scan, ()):
            stepper.submit(InputEvent.from_json(json.loads(line)))
        return stepper

    def changed(self, path: str, scan: int, direction: int) -> int | None:
        """The nearest scan after (``direction`` 1) or before (-1) ``scan`` that changed ``path``: whose end
        value differs from the end value of the scan before it. None when the history holds none."""
        self.live.location(path)  # an unknown path fails before any replay
        return self.find(lambda sim: sim.read(path), _differs, scan, direction)

    def find(
        self,
        measure: Callable[[Simulation], object],
        hit: Callable[[object, object], bool],
        scan: int,
        direction: int,
    ) -> int | None:
        """The nearest scan after (``direction`` 1) or before (-1) ``scan`` where ``hit(before, now)`` holds for
        ``measure`` at the end of the scan before it and at its end; None when the history holds none."""
        if direction == 1:
            previous = measure(self.seek(scan))
            for number in range(scan + 1, self.last + 1):
                now = measure(self.seek(number))  # stepping forward replays one scan each
                if hit(previous, now):
                    return number
                previous = now
            return None
        high = min(scan, self.last + 1) - 1
        while high > self.first:  # one checkpoint interval at a time, each replayed forward
            low = max(self.first, self._checkpoint_at(high).scan - 1)
            values = [measure(self.seek(number)) for number in range(low, high + 1)]
            for offset in range(len(values) - 1, 0, -1):
                if hit(values[offset - 1], values[offset]):
                    return low + offset
            high = low
        return None

    def diff(self, first: int, second: int) -> dict[str, tuple[object, object]]:
        """The variables whose values differ between the ends of two scans: path -> (first's, second's)."""
        before = self.seek(first).snapshot()
        after = self.seek(second).snapshot()
        return {
            path: (before.get(path), after.get(path))
            for path in before.keys() | after.keys()
            if _differs(before.get(path), after.get(path))
        }

    def _checkpoint_at(self, scan: int) -> Checkpoint:
        """The newest checkpoint taken before scan ``scan`` ran."""
        index = bisect.bisect_right([c.scan for c in self.checkpoints], scan) - 1
        return self.checkpoints[index]

    def _restore(self, checkpoint: Checkpoint) -> None:
        self._replay_sim().restore(checkpoint.state(self._paths))
        self._replay_at = checkpoint.scan

    def _replay_sim(self) -> Simulation:
        if self._replay is None:
            program = (self.live.variant_program("monitor") or self.live.compiled).own_code()  # see own_code
            self._replay = Simulation(program, watchdog_s=self.live.watchdogs)  # the live scans' budgets, not 0.1 s
        return self._replay


def _differs(old: object, value: object) -> bool:
    """Another value or another type (TRUE is not 1); a NaN that stays NaN has not changed."""
    if value == old and type(value) is type(old):
        return False
    return not (value != value and type(old) is float and old != old)
