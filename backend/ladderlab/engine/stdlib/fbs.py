"""Standard function blocks (spec SFB-01..SFB-21), as the IEC reference bodies (SFB-10..SFB-18).

Generated code sets inputs as attributes, calls ``execute(now_ms)`` and reads
outputs as attributes. ``now_ms`` is the scan's clock (SFB-19): every call in
one scan sees the same value. A fresh instance is the cold state; ``reset()``
returns to it. Pins are named exactly as in IEC; ``INPUTS``, ``OUTPUTS`` and
``MEMORY`` (hidden state, e.g. the M of R_TRIG) list them for monitoring, see
``pins()``. Hidden state that IEC does not name starts with ``_``.

Decisions where implementations differ, each pinned by a test:

* F_TRIG pulses only on a real TRUE -> FALSE change: M holds the previous CLK,
  starting FALSE, so a first call with CLK FALSE gives no pulse (SFB-12 [REC]).
  R_TRIG with CLK TRUE in the first call pulses (M starts FALSE, SFB-11).
* CTU counts while CV < the largest value of CV's type (not only up to PV);
  CTD while CV > the smallest; Q compares with PV (SFB-13..15). CU/CD are
  R_EDGE inputs: a count needs a FALSE -> TRUE change between calls.
* Timers: Q switches when ET >= PT, ET never exceeds PT, PT is read on every
  call (a change takes effect at once, SFB-19), a negative PT acts as T#0s.
  TP ignores rising edges while its pulse runs, including in the call in
  which the pulse ends.
"""

from __future__ import annotations

from ...iec.stdlib import TYPED_COUNTER_TYPES
from ...iec.values import resolve


class FunctionBlock:
    """Base of the standard FBs: pin lists and cold reset."""

    __slots__ = ()
    INPUTS: tuple[str, ...] = ()
    OUTPUTS: tuple[str, ...] = ()
    MEMORY: tuple[str, ...] = ()

    def reset(self) -> None:
        """Back to the cold-start state (IEC defaults)."""
        self.__init__()  # type: ignore[misc]


def pins(fb: FunctionBlock) -> dict[str, object]:
    """All visible pins and named memory of an instance, for monitoring."""
    return {name: getattr(fb, name) for name in (*fb.INPUTS, *fb.OUTPUTS, *fb.MEMORY)}


class SR(FunctionBlock):
    """Set-dominant bistable: Q1 := S1 OR (NOT R AND Q1) (SFB-10)."""

    __slots__ = ("Q1", "R", "S1")
    INPUTS, OUTPUTS = ("S1", "R"), ("Q1",)

    def __init__(self) -> None:
        self.S1 = self.R = self.Q1 = False

    def execute(self, now_ms: int) -> None:
        self.Q1 = self.S1 or (not self.R and self.Q1)


class RS(FunctionBlock):
    """Reset-dominant bistable: Q1 := NOT R1 AND (S OR Q1) (SFB-10)."""

    __slots__ = ("Q1", "R1", "S")
    INPUTS, OUTPUTS = ("S", "R1"), ("Q1",)

    def __init__(self) -> None:
        self.S = self.R1 = self.Q1 = False

    def execute(self, now_ms: int) -> None:
        self.Q1 = not self.R1 and (self.S or self.Q1)


class R_TRIG(FunctionBlock):
    """Rising edge: Q := CLK AND NOT M; M := CLK (SFB-11)."""

    __slots__ = ("CLK", "M", "Q")
    INPUTS, OUTPUTS, MEMORY = ("CLK",), ("Q",), ("M",)

    def __init__(self) -> None:
        self.CLK = self.Q = self.M = False

    def execute(self, now_ms: int) -> None:
        clk = self.CLK
        self.Q = clk and not self.M
        self.M = clk


class F_TRIG(FunctionBlock):
    """Falling edge: Q := M AND NOT CLK; M := CLK, M starting FALSE (SFB-12 [REC])."""

    __slots__ = ("CLK", "M", "Q")
    INPUTS, OUTPUTS, MEMORY = ("CLK",), ("Q",), ("M",)

    def __init__(self) -> None:
        self.CLK = self.Q = self.M = False

    def execute(self, now_ms: int) -> None:
        clk = self.CLK
        self.Q = self.M and not clk
        self.M = clk


class _Counter(FunctionBlock):
    """Common state of the counters: the type of PV/CV sets the counting limits."""

    __slots__ = ("CV", "PV", "_max", "_min", "_type")
    CV_TYPE = "INT"

    def __init__(self, cv_type: str | None = None) -> None:
        elem = resolve(cv_type or self.CV_TYPE).elem
        if elem.category != "int":
            raise ValueError(f"a counter's CV must be an integer type, not {elem.name}")
        self._type, self._min, self._max = elem.name, elem.min, elem.max
        self.PV = self.CV = 0

    def reset(self) -> None:
        self.__init__(self._type)  # type: ignore[misc]


class CTU(_Counter):
    """Up counter (SFB-13): IF R THEN CV := 0 ELSIF CU(edge) AND CV < max THEN CV := CV + 1; Q := CV >= PV."""

    __slots__ = ("CU", "Q", "R", "_cu")
    INPUTS, OUTPUTS, MEMORY = ("CU", "R", "PV"), ("Q", "CV"), ()

    def __init__(self, cv_type: str | None = None) -> None:
        super().__init__(cv_type)
        self.CU = self.R = self.Q = self._cu = False

    def execute(self, now_ms: int) -> None:
        cu = self.CU
        if self.R:
            self.CV = 0
        elif cu and not self._cu and self._max > self.CV:
            self.CV += 1
        self._cu = cu
        self.Q = self.CV >= self.PV


class CTD(_Counter):
    """Down counter (SFB-14): IF LD THEN CV := PV ELSIF CD(edge) AND CV > min THEN CV := CV - 1; Q := CV <= 0."""

    __slots__ = ("CD", "LD", "Q", "_cd")
    INPUTS, OUTPUTS, MEMORY = ("CD", "LD", "PV"), ("Q", "CV"), ()

    def __init__(self, cv_type: str | None = None) -> None:
        super().__init__(cv_type)
        self.CD = self.LD = self.Q = self._cd = False

    def execute(self, now_ms: int) -> None:
        cd = self.CD
        if self.LD:
            self.CV = self.PV
        elif cd and not self._cd and self._min < self.CV:
            self.CV -= 1
        self._cd = cd
        self.Q = self.CV <= 0


class CTUD(_Counter):
    """Up/down counter (SFB-15): R over LD over counting; edges of CU and CD in one call cancel."""

    __slots__ = ("CD", "CU", "LD", "QD", "QU", "R", "_cd", "_cu")
    INPUTS, OUTPUTS, MEMORY = ("CU", "CD", "R", "LD", "PV"), ("QU", "QD", "CV"), ()

    def __init__(self, cv_type: str | None = None) -> None:
        super().__init__(cv_type)
        self.CU = self.CD = self.R = self.LD = self.QU = self.QD = self._cu = self._cd = False

    def execute(self, now_ms: int) -> None:
        cu, cd = self.CU, self.CD
        up, down = cu and not self._cu, cd and not self._cd
        self._cu, self._cd = cu, cd
        if self.R:
            self.CV = 0
        elif self.LD:
            self.CV = self.PV
        elif up and not down:
            if self._max > self.CV:
                self.CV += 1
        elif down and not up and self._min < self.CV:
            self.CV -= 1
        self.QU = self.CV >= self.PV
        self.QD = self.CV <= 0


class _Timer(FunctionBlock):
    """IN, PT, Q, ET plus the start time of the running interval."""

    __slots__ = ("ET", "IN", "PT", "Q", "_running", "_start")
    INPUTS, OUTPUTS = ("IN", "PT"), ("Q", "ET")

    def __init__(self) -> None:
        self.IN = self.Q = self._running = False
        self.PT = self.ET = self._start = 0


class TON(_Timer):
    """On-delay (SFB-17): Q rises when IN has been TRUE for PT; IN FALSE resets Q and ET at once."""

    __slots__ = ()

    def execute(self, now_ms: int) -> None:
        if not self.IN:
            self._running = self.Q = False
            self.ET = 0
            return
        if not self._running:
            self._running, self._start = True, now_ms
        elapsed, pt = now_ms - self._start, self.PT
        if elapsed >= pt:
            self.Q, self.ET = True, pt if pt > 0 else 0
        else:
            self.Q, self.ET = False, elapsed


class TOF(_Timer):
    """Off-delay (SFB-18): Q follows IN up at once and falls PT after IN falls."""

    __slots__ = ()

    def execute(self, now_ms: int) -> None:
        if self.IN:
            self._running, self.Q, self.ET = False, True, 0
            return
        if not self.Q:  # cold start, or the delay is over: ET keeps its value
            return
        if not self._running:
            self._running, self._start = True, now_ms
        elapsed, pt = now_ms - self._start, self.PT
        if elapsed >= pt:
            self._running = self.Q = False
            self.ET = pt if pt > 0 else 0
        else:
            self.ET = elapsed


class TP(_Timer):
    """Pulse (SFB-16): a rising IN starts a pulse of exactly PT that nothing retriggers or cuts short."""

    __slots__ = ("_in",)

    def __init__(self) -> None:
        super().__init__()
        self._in = False

    def execute(self, now_ms: int) -> None:
        edge = self.IN and not self._in
        self._in = self.IN
        if self._running:
            elapsed, pt = now_ms - self._start, self.PT
            if elapsed < pt:
                self.ET = elapsed
                return
            self._running = self.Q = False
            self.ET = (pt if pt > 0 else 0) if self.IN else 0
        elif edge:
            self._running, self.Q, self._start, self.ET = True, True, now_ms, 0
            if self.PT <= 0:  # a zero-length pulse ends in the call that started it
                self._running = self.Q = False
        elif not self.IN:
            self.ET = 0


def _typed_counters() -> dict[str, type[_Counter]]:
    """CTU_INT .. CTUD_ULINT (IEC 3rd edition names; spec ST-23 also uses CTD_DINT)."""
    typed: dict[str, type[_Counter]] = {}
    for base in (CTU, CTD, CTUD):
        for cv_type in TYPED_COUNTER_TYPES:
            name = f"{base.__name__}_{cv_type}"
            typed[name] = type(name, (base,), {"__slots__": (), "CV_TYPE": cv_type, "__doc__": base.__doc__})
    return typed


STANDARD_FBS: dict[str, type[FunctionBlock]] = {
    cls.__name__: cls for cls in (SR, RS, R_TRIG, F_TRIG, CTU, CTD, CTUD, TP, TON, TOF)
}
STANDARD_FBS.update(_typed_counters())
