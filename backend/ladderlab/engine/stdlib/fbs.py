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


class ACTION_CONTROL(FunctionBlock):
    """IEC 61131-3 (ed. 2, 2003) figure 15, the action control with the final scan: one input per qualifier (S0 is
    S), T the time of L, D, SD, DS and SL; Q the action flag, A TRUE while the action runs: Q, the one call after
    Q falls (the final run), and the one call of a P1 or P0 pulse (with Q FALSE). The body, with its own blocks:

        S_FF(S := S0, R1 := R);  L_TMR(IN := L, PT := T);  D_TMR(IN := D, PT := T);  P_TRIG(CLK := P);
        SD_FF(S := SD, R1 := R);  SD_TMR(IN := SD_FF.Q1, PT := T);
        DS_TMR(IN := DS, PT := T);  DS_FF(S := DS_TMR.Q, R1 := R);
        SL_FF(S := SL, R1 := R);  SL_TMR(IN := SL_FF.Q1, PT := T);
        P1_TRIG(CLK := P1);  P0_TRIG(CLK := P0);
        Q := NOT R AND (N OR (L AND NOT L_TMR.Q) OR D_TMR.Q OR P_TRIG.Q OR S_FF.Q1 OR SD_TMR.Q OR DS_FF.Q1
                        OR (SL_FF.Q1 AND NOT SL_TMR.Q));
        Q_FT(CLK := Q);
        A := Q OR Q_FT.Q OR P1_TRIG.Q OR P0_TRIG.Q;
    """

    __slots__ = (
        "A",
        "D",
        "DS",
        "L",
        "N",
        "P",
        "P0",
        "P1",
        "Q",
        "R",
        "S0",
        "SD",
        "SL",
        "T",
        "_d_tmr",
        "_ds_ff",
        "_ds_tmr",
        "_l_tmr",
        "_p0_trig",
        "_p1_trig",
        "_p_trig",
        "_q_ft",
        "_s_ff",
        "_sd_ff",
        "_sd_tmr",
        "_sl_ff",
        "_sl_tmr",
    )
    INPUTS = ("N", "R", "S0", "L", "D", "P", "P1", "P0", "SD", "DS", "SL", "T")
    OUTPUTS = ("Q", "A")

    def __init__(self) -> None:
        self.N = self.R = self.S0 = self.L = self.D = self.P = self.P1 = self.P0 = False
        self.SD = self.DS = self.SL = self.Q = self.A = False
        self.T = 0
        self._s_ff, self._sd_ff, self._ds_ff, self._sl_ff = RS(), RS(), RS(), RS()
        self._l_tmr, self._d_tmr, self._sd_tmr, self._ds_tmr, self._sl_tmr = TON(), TON(), TON(), TON(), TON()
        self._p_trig, self._p1_trig, self._p0_trig, self._q_ft = R_TRIG(), R_TRIG(), F_TRIG(), F_TRIG()

    def execute(self, now_ms: int) -> None:
        r, t = self.R, self.T
        s_ff = _rs(self._s_ff, self.S0, r)
        l_tmr = _ton(self._l_tmr, self.L, t, now_ms)
        d_tmr = _ton(self._d_tmr, self.D, t, now_ms)
        p_trig = _trig(self._p_trig, self.P)
        sd_ff = _rs(self._sd_ff, self.SD, r)
        sd_tmr = _ton(self._sd_tmr, sd_ff, t, now_ms)
        ds_tmr = _ton(self._ds_tmr, self.DS, t, now_ms)
        ds_ff = _rs(self._ds_ff, ds_tmr, r)
        sl_ff = _rs(self._sl_ff, self.SL, r)
        sl_tmr = _ton(self._sl_tmr, sl_ff, t, now_ms)
        p1 = _trig(self._p1_trig, self.P1)
        p0 = _trig(self._p0_trig, self.P0)
        q = not r and (
            self.N or (self.L and not l_tmr) or d_tmr or p_trig or s_ff or sd_tmr or ds_ff or (sl_ff and not sl_tmr)
        )
        final = _trig(self._q_ft, q)  # (called every time: the F_TRIG must see Q rise)
        self.Q = q
        self.A = q or final or p1 or p0


class SFC_STEP(FunctionBlock):
    """An SFC step (docs/sfc.md): X, the step flag the chart sets and clears; T, how long the step has been active,
    T#0s in its first active scan (so a transition ``S.T >= t`` and a D or L action of time t agree to the scan).
    A call with X FALSE ends the interval and T keeps its value until the next activation (IEC 61131-3 2.6.2)."""

    __slots__ = ("T", "X", "_running", "_start")
    INPUTS, OUTPUTS = ("X",), ("T",)

    def __init__(self) -> None:
        self.X = self._running = False
        self.T = self._start = 0

    def execute(self, now_ms: int) -> None:
        if not self.X:
            self._running = False
            return
        if not self._running:
            self._running, self._start = True, now_ms
        self.T = now_ms - self._start


def _rs(ff: RS, s: bool, r1: bool) -> bool:
    ff.S, ff.R1 = s, r1
    ff.execute(0)
    return ff.Q1


def _ton(timer: TON, run: bool, pt: int, now_ms: int) -> bool:
    timer.IN, timer.PT = run, pt
    timer.execute(now_ms)
    return timer.Q


def _trig(trig: R_TRIG | F_TRIG, clk: bool) -> bool:
    trig.CLK = clk
    trig.execute(0)
    return trig.Q


def _typed_counters() -> dict[str, type[_Counter]]:
    """CTU_INT .. CTUD_ULINT (IEC 3rd edition names; spec ST-23 also uses CTD_DINT)."""
    typed: dict[str, type[_Counter]] = {}
    for base in (CTU, CTD, CTUD):
        for cv_type in TYPED_COUNTER_TYPES:
            name = f"{base.__name__}_{cv_type}"
            typed[name] = type(name, (base,), {"__slots__": (), "CV_TYPE": cv_type, "__doc__": base.__doc__})
    return typed


STANDARD_FBS: dict[str, type[FunctionBlock]] = {
    cls.__name__: cls for cls in (SR, RS, R_TRIG, F_TRIG, CTU, CTD, CTUD, TP, TON, TOF, ACTION_CONTROL, SFC_STEP)
}
STANDARD_FBS.update(_typed_counters())
