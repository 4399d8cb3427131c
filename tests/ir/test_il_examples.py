"""The IL worked examples of both seeds, lowered to the IR and run scan by scan (IL-xx, EX-30..EX-34).

Expected values are the ones the manuals state (seed 000 chapter 8, seed 003 §3.3.1-3.3.2), or derived by hand
in the spec (``[DERIVED]``); each test names its item.
"""

from __future__ import annotations

import pytest

from ladderlab.engine.simulation import Simulation
from tests.ir.helpers import errors, lower_ok, lower_with_tasks


def program(declarations: str, body: str, extra: str = "") -> Simulation:
    return Simulation(lower_ok(f"PROGRAM P\nVAR\n{declarations}\nEND_VAR\n{body}\nEND_PROGRAM\n{extra}"))


def scan(sim: Simulation, **inputs: object) -> Simulation:
    for name, value in inputs.items():
        sim.write(f"P.{name}", value)
    sim.cycle()
    assert sim.fault is None
    return sim


IL_02 = """
    LD    {load}
    ST    lvar      (* comment *)
    GE    5
    JMPC  next
    LD    idword
    EQ    istruct.sdword
    STN   test
next:
"""
IL_02_DECLS = "lvar : LINT; idword : DWORD; istruct : S; test : BOOL := TRUE;"
IL_02_TYPES = "TYPE S : STRUCT sdword : DWORD; END_STRUCT; END_TYPE"


def test_reference_program_jumps_when_17_ge_5_il02():
    """IL-02: acc 17 -> lvar := 17 -> acc := 17 >= 5 = TRUE -> jump -> test unchanged. (The seed's LINT variable
    is called ``lint``, a type name, which cannot name a variable (KW-02): it is ``lvar`` here.)"""
    sim = scan(program(IL_02_DECLS, IL_02.format(load=17), IL_02_TYPES), idword=1)
    assert (sim.read("P.lvar"), sim.read("P.test")) == (17, True)


@pytest.mark.parametrize("idword, sdword, test", [(1, 1, False), (1, 2, True)])
def test_reference_program_variant_ld_3_falls_through_il02(idword, sdword, test):
    """IL-02 variant ``LD 3``: 3 >= 5 is FALSE -> no jump -> test := NOT (idword = istruct.sdword)."""
    sim = scan(program(IL_02_DECLS, IL_02.format(load=3), IL_02_TYPES), idword=idword, **{"istruct.sdword": sdword})
    assert (sim.read("P.lvar"), sim.read("P.test")) == (3, test)


def test_parentheses_change_the_result_il06():
    """IL-06: ``LD 2 / MUL 2 / ADD 3`` -> 7; ``LD 2 / MUL ( 2 / ADD 3 / )`` -> 10 (MUL waits for ')')."""
    sim = scan(
        program(
            "ERG : INT; ERG2 : INT;",
            "LD 2\nMUL 2\nADD 3\nST ERG\nLD 2\nMUL ( 2\nADD 3\n)\nST ERG2",
        )
    )
    assert (sim.read("P.ERG"), sim.read("P.ERG2")) == (7, 10)


IL_07 = """
LD    TRUE
ANDN  BOOL1     (* AND with the inverted value of BOOL1 *)
JMPC  mark
LDN   BOOL2
ST    ERG
mark:
"""


@pytest.mark.parametrize(
    "bool1, bool2, erg",
    [(False, False, None), (False, True, None), (True, False, True), (True, True, False)],
)
def test_modifier_example_il07(bool1, bool2, erg):
    """IL-07: BOOL1=FALSE -> jump, ERG unchanged; BOOL1=TRUE -> ERG := NOT BOOL2. ERG starts as a marker the jump
    leaves alone (its unchanged value must survive the scan)."""
    sim = program("BOOL1, BOOL2 : BOOL; ERG : BOOL;", IL_07)
    for marker in (False, True):  # "unchanged" is seen with both starting values
        sim.write("P.ERG", marker)
        scan(sim, BOOL1=bool1, BOOL2=bool2)
        assert sim.read("P.ERG") == (marker if erg is None else erg)


@pytest.mark.parametrize("x", [False, True])
@pytest.mark.parametrize("a", [False, True])
@pytest.mark.parametrize("b", [False, True])
def test_deferred_and_of_an_or_ex31_il13(x, a, b):
    """EX-31 / IL-13: ``AND ( a / OR b / )`` is ``result := result AND (a OR b)``, all 8 cases."""
    sim = scan(program("x, a, b, r : BOOL;", "LD x\nAND (      a\nOR        b\n)\nST r"), x=x, a=a, b=b)
    assert sim.read("P.r") == (x and (a or b))


@pytest.mark.parametrize("x, a, b", [(x, a, b) for x in (0, 1) for a in (0, 1) for b in (0, 1)])
def test_andn_deferred_negates_the_bracket_il21(x, a, b):
    """IL-21 / IL-13: ``ANDN(`` is ``result AND NOT ( ... )``; ``ORN(`` and ``XORN(`` alike."""
    sim = program(
        "x, a, b, r1, r2, r3 : BOOL;",
        "LD x\nANDN( a\nOR b\n)\nST r1\nLD x\nORN( a\nAND b\n)\nST r2\nLD x\nXORN(\nLD a\n)\nST r3",
    )
    scan(sim, x=bool(x), a=bool(a), b=bool(b))
    assert sim.read("P.r1") == bool(x and not (a or b))
    assert sim.read("P.r2") == bool(x or not (a and b))
    assert sim.read("P.r3") == bool(x ^ (not a))


def test_nested_parentheses_il06():
    """IL-06: nesting is a stack: 2 * (3 + (4 * 5)) = 46."""
    sim = scan(program("r : INT;", "LD 2\nMUL( 3\nADD( 4\nMUL 5\n)\n)\nST r"))
    assert sim.read("P.r") == 46


EX_30 = """
Step1: LD      %X1.2 // load byt from input
      AND     tmp1  (* AND temporary variable *)
      ST      %Y2.0 (* store to PLC output *)
              (* empty instruction *)
Step2:
      LDN     tmp2
      ST      seen
"""


def test_program_in_il_labels_and_comments_ex30():
    """EX-30 (Ex 4.1): labels on an instruction and alone, both comment styles; %Y2.0 := %X1.2 AND tmp1 stays
    FALSE as tmp1 is never written; ``LDN tmp2`` leaves the CR TRUE (stored into ``seen`` to observe it; the
    engine needs named direct variables)."""
    sim = program(
        "tmp1, tmp2 : BOOL; seen : BOOL;",
        EX_30,
        "VAR_GLOBAL x12 AT %X1.2 : BOOL; y20 AT %Y2.0 : BOOL; END_VAR",
    )
    sim.write("x12", True)
    scan(sim)
    assert (sim.read("y20"), sim.read("P.seen")) == (False, True)
    sim.write("P.tmp1", True)
    scan(sim)
    assert sim.read("y20") is True


USER_FUN = """
FUNCTION UserFun : INT
  VAR_INPUT
    val      :   INT;           // input value
    minVal   :   INT;           // minimum
    maxVal   :   INT;           // maximum
  END_VAR

      LD      val
      GE      minVal
      JMPC    NXT_TST
      LD      minVal
      JMP     VAL_OK
NXT_TST:
      LD      val
      GT      maxVal
      JMPC    USE_MAX
      LD      val
      JMP     VAL_OK
USE_MAX:
      LD      maxVal
VAL_OK: ST      UserFun
END_FUNCTION
"""


@pytest.mark.parametrize("val, result", [(50, 100), (100, 100), (500, 500), (1000, 1000), (2000, 1000)])
def test_user_function_in_il_ex32_il32(val, result):
    """EX-32 (corrected fixture): UserFun(val, 100, 1000) limits val to 100..1000; ``ST UserFun`` sets the result."""
    sim = scan(program("val, r : INT;", "LD val\nUserFun 100, 1000\nST r", USER_FUN), val=val)
    assert sim.read("P.r") == result


def test_printed_user_function_is_rejected_at_its_label_ex32_il25():
    """EX-32 / IL-25: the printed version reaches VAL_OK with an INT CR (JMP) and a BOOL CR (GT, JMPCN)."""
    printed = USER_FUN.replace(
        "      JMPC    USE_MAX\n      LD      val\n      JMP     VAL_OK\nUSE_MAX:\n      LD      maxVal\n",
        "      JMPCN   VAL_OK\n      LD      maxVal\n",
    )
    found = errors(f"PROGRAM P\nVAR r : INT; END_VAR\nLD 5\nUserFun 1, 2\nST r\nEND_PROGRAM\n{printed}")
    assert any("IL-CR-TYPE" in e and "VAL_OK" in e and "INT" in e and "BOOL" in e for e in found), found


EX_33 = """
  // calling function, first parameter is current result
  LD      Count
  UserFun 100, 1000
  ST      r1

  // calling function using an informal call
  UserFun( Count, 100, 1000)
  ST      r2

  // calling function using a formal call
  UserFun( val := Count, minVal := 100, maxVal := 1000)
  ST      r3
"""


@pytest.mark.parametrize("count, result", [(0, 100), (500, 500)])
def test_three_function_call_forms_ex33_il30_il31(count, result):
    """EX-33: the three call forms store UserFun(Count, 100, 1000): 100 for Count = 0, 500 for 500."""
    sim = scan(program("count : INT; r1, r2, r3 : INT;", EX_33, USER_FUN), count=count)
    assert [sim.read(f"P.r{i}") for i in (1, 2, 3)] == [result] * 3


def test_informal_call_does_not_use_the_accumulator_il31():
    """IL-31 [DERIVED]: form 2 ignores the CR: with 7 loaded, ``UserFun(500, 100, 1000)`` is still 500."""
    sim = scan(program("r : INT;", "LD 7\nUserFun(500, 100, 1000)\nST r", USER_FUN))
    assert sim.read("P.r") == 500


LIM_RET = """
FUNCTION Lim : INT
  VAR_INPUT val, lo, hi : INT; END_VAR
      LD      val
      ST      Lim
      LT      lo
      JMPCN   NOT_LOW
      LD      lo
      ST      Lim
      RET
NOT_LOW:
      LD      val
      GT      hi
      RETCN
      LD      hi
      ST      Lim
END_FUNCTION
"""


@pytest.mark.parametrize("count, result", [(50, 101), (500, 501), (2000, 1001)])
def test_the_value_stored_in_the_function_name_is_the_new_cr_after_ret_or_the_end_il32(count, result):
    """IL-32: inside an IL function ``ST Lim`` sets the return value; ``RET``/``RETCN`` and the physical end
    return it, and it becomes the caller's CR (``ADD 1`` works on it): 50 -> 100 (RET), 500 -> 500 (RETCN),
    2000 -> 1000 (end), each plus 1."""
    sim = scan(program("count, r : INT;", "LD count\nLim 100, 1000\nADD 1\nST r", LIM_RET), count=count)
    assert sim.read("P.r") == result


EX_34_STYLES = {
    "instance memory": """
  LD   in1
  ST   timer.IN
  LD   T#10m12s
  ST   timer.PT
  CAL  timer
  LD   timer.ET
  ST   timerValue
  LD   timer.Q
  ST   out1""",
    "formal": "  CAL  timer( IN := in1, PT := T#10m12s, Q => out1, ET => timerValue)",
    "combined": """
  LD   in1
  ST   timer.IN
  CAL  timer( PT := T#10m12s, ET => timerValue)
  LD   timer.Q
  ST   out1""",
    "input operators": """
  LD   T#10m12s
  PT   timer
  LD   in1
  IN   timer
  LD   timer.ET
  ST   timerValue
  LD   timer.Q
  ST   out1""",
}


@pytest.mark.parametrize("style", EX_34_STYLES)
def test_fb_call_styles_are_equivalent_ex34_il33(style):
    """EX-34 / IL-33 (and IL-24's input operators): out1 follows in1 with an on-delay of T#10m12s (612 s),
    timerValue is the TON's ET. The default task scans every 10 ms; the clock is virtual."""
    sim = program("in1, out1 : BOOL; timer : TON; timerValue : TIME;", EX_34_STYLES[style])
    scan(sim, in1=True)
    assert (sim.read("P.out1"), sim.read("P.timerValue")) == (False, 0)
    for _ in range(100):
        scan(sim)
    assert (sim.read("P.out1"), sim.read("P.timerValue")) == (False, 1000)
    sim.run_for(610_000)  # 611 s after in1 rose
    assert sim.read("P.out1") is False
    sim.run_for(1_000)
    assert (sim.read("P.out1"), sim.read("P.timerValue")) == (True, 612_000)
    scan(sim, in1=False)
    assert (sim.read("P.out1"), sim.read("P.timerValue")) == (False, 0)


FUB = """
FUNCTION Fct : INT
VAR_INPUT PAR1, PAR2, PAR3 : INT; END_VAR
LD PAR1
MUL PAR2
DIV PAR3
ST Fct
END_FUNCTION
FUNCTION_BLOCK FUB
VAR_INPUT PAR1, PAR2 : INT; END_VAR
VAR_OUTPUT MULERG : INT; VERGL : BOOL; END_VAR
LD PAR1
MUL PAR2
ST MULERG
LD PAR1
EQ PAR2
ST VERGL
END_FUNCTION_BLOCK
PROGRAM PRGexample2
VAR_INPUT in_var : INT; END_VAR
VAR_OUTPUT out_var : INT; END_VAR
LD in_var
ADD 1
ST out_var
END_PROGRAM
"""


def test_calls_of_fb_function_and_program_il08():
    """IL-08: ``LD 17 / ST inst1.in1 / CAL inst1``; ``CAL PRGexample2`` then its output; the formal program call;
    the rebuilt fixtures Fct (PAR1 * PAR2 / PAR3) and FUB (MULERG = product, VERGL = comparison)."""
    body = """
LD 17
ST INSTANZ.PAR1
LD 3
ST INSTANZ.PAR2
CAL INSTANZ
LD INSTANZ.MULERG
ST ERG
LD INSTANZ.VERGL
ST QUAD
LD 6
Fct 7, 3
ST F
"""
    sim = scan(program("INSTANZ : FUB; ERG, F : INT; QUAD : BOOL;", body, FUB))
    assert [sim.read(f"P.{n}") for n in ("ERG", "QUAD", "F")] == [51, False, 14]


def test_program_calls_run_the_programs_one_instance_il08():
    """IL-08 (seed 003, example of a program call): ``CAL PRGexample2(in_var := 33, out_var => erg)`` gives
    erg = 33 + 1 = 34; ``LD 5 / ST PRGexample2.in_var / CAL PRGexample2 / LD PRGexample2.out_var / ST ERG`` gives
    6. One instance: the program's variables keep the last call's values for the next caller (seed 003: "at the
    next call its variables have the same values, even when another POU calls it")."""
    body = """
CAL PRGexample2(in_var := 33, out_var => erg)
LD PRGexample2.out_var
ST after_formal
LD 5
ST PRGexample2.in_var
CAL PRGexample2
LD PRGexample2.out_var
ST ERG2
"""
    sim = scan(program("erg, after_formal, ERG2 : INT;", body, FUB))
    assert [sim.read(f"P.{n}") for n in ("erg", "after_formal", "ERG2")] == [34, 34, 6]
    # the DEFAULT task runs PRGexample2 too (after P): in_var is still 5, the value P's last call left
    assert (sim.read("PRGexample2.in_var"), sim.read("PRGexample2.out_var")) == (5, 6)


def test_conditional_program_call_il08_il14():
    """``CALC PRGexample2`` runs the program only with a TRUE CR (IL-14): a counting program counts the scans
    with go = TRUE (the project's one task runs only P, so P's calls are the program's only runs)."""
    counter = "PROGRAM Counter\nVAR_OUTPUT n : INT; END_VAR\nLD n\nADD 1\nST n\nEND_PROGRAM\n"
    source = f"PROGRAM P\nVAR go : BOOL; END_VAR\nLD go\nCALC Counter\nEND_PROGRAM\n{counter}"
    sim = Simulation(lower_with_tasks(source, {"T": ["P"]}))
    counts = []
    for go in (True, False, True, True, False):
        scan(sim, go=go)
        counts.append(sim.read("Counter.n"))
    assert counts == [1, 1, 2, 3, 3]


def test_program_called_from_il_and_st_by_a_function_is_refused_il08():
    """Seed 003: "Нельзя вызывать программу из функции" (a function cannot call a program), POU-32."""
    found = errors(f"FUNCTION G : INT\nCAL PRGexample2\nEND_FUNCTION\nPROGRAM P\nEND_PROGRAM\n{FUB}")
    assert found == ["G/body:2:5, POU G: error ST-NOT-CALLABLE: a function cannot call the program PRGexample2"]


def test_conditional_call_and_return_il14_il23():
    """IL-14 / IL-23: CALC runs only with a TRUE CR, CALCN only with FALSE; RETC leaves the POU when TRUE."""
    body = """
LD go
CALC up(CU := TRUE)
CALCN down(CU := TRUE)
LD stop
RETC
LD 1
ST after
"""
    sim = program("go, stop : BOOL; up, down : CTU; after : INT;", body)
    scan(sim, go=True, stop=True)
    scan(sim, go=False)
    scan(sim, go=True)
    assert (sim.read("P.up.CV"), sim.read("P.down.CV"), sim.read("P.after")) == (1, 1, 0)
    scan(sim, stop=False)
    assert sim.read("P.after") == 1


def test_set_and_reset_act_only_on_a_true_accumulator_il20():
    """IL-20 / IL-05: S sets, R resets the operand only when the CR is TRUE; the CR is unchanged by S/R/ST."""
    sim = program("a, b, x, cr : BOOL;", "LD a\nS x\nLD b\nR x\nST cr")
    assert scan(sim, a=True).read("P.x") is True
    assert scan(sim, a=False).read("P.x") is True
    assert scan(sim, b=True).read("P.x") is False
    assert (scan(sim, b=False).read("P.x"), sim.read("P.cr")) == (False, False)


def test_not_and_fb_set_reset_input_operators_il24():
    """IL-24: ``NOT`` negates the CR; ``S1 rs`` and ``R rs`` call an RS instance with that input := CR."""
    body = "LD a\nNOT\nST na\nLD a\nS1 latch\nLD b\nR latch\nLD latch.Q1\nST q"
    sim = program("a, b, na, q : BOOL; latch : SR;", body)
    assert (scan(sim, a=True).read("P.q"), sim.read("P.na")) == (True, False)
    assert scan(sim, a=False).read("P.q") is True
    assert (scan(sim, b=True).read("P.q"), sim.read("P.na")) == (False, True)


def test_breakpoints_and_single_steps_stop_on_il_lines_il09():
    """IL-09 / IL-26: every IL line is a pause point (the engine's statement points): a breakpoint on a line
    halts before it with the accumulator readable. Single steps (ON-04) stop at the next load, jump or call in
    execution order - the JMPC on line 7, the loads on lines 8 and 10 - jumps included (``JMPC`` taken in the
    second scan: line 8 is skipped)."""
    body = "LD a\nADD 1\nST a\nGT 1\nJMPC done\nLD a\nST r\ndone: LD a\nST s"
    sim = Simulation(lower_ok(f"PROGRAM P\nVAR a, r, s : INT; END_VAR\n{body}\nEND_PROGRAM\n"), variant="debug")
    sim.set_breakpoint("P", line=5)
    for expected_lines, r in (([5, 7, 8, 10], 1), ([5, 7, 10], 1)):
        sim.cycle()
        assert (sim.halted.origin.line, sim.read("P.__CR_INT")) == (5, sim.read("P.a") + 1)
        lines = []
        halt = sim.halted
        while halt is not None:
            lines.append(halt.origin.line)
            halt = sim.step("statement")
        assert lines == expected_lines
        assert (sim.read("P.r"), sim.read("P.s")) == (r, sim.read("P.a"))


@pytest.mark.parametrize("a, b", [(False, False), (False, True), (True, False), (True, True)])
def test_n_negates_the_operand_il12(a, b):
    """IL-12: ``ORN b`` is ``result := result OR NOT b``; ``LDN a`` is ``NOT a``; ``STN x`` stores ``NOT result``."""
    sim = scan(program("a, b, r1, r2, r3 : BOOL;", "LD a\nORN b\nST r1\nLDN a\nST r2\nLD a\nSTN r3"), a=a, b=b)
    assert [sim.read(f"P.r{i}") for i in (1, 2, 3)] == [a or not b, not a, not a]


@pytest.mark.parametrize("i, expected", [(31, True), (32, False), (33, False)])
def test_comparison_puts_the_cr_left_and_gives_bool_il11(i, expected):
    """IL-11: ``LT %IW32``-style: TRUE when CR < operand (here CR = i, operand 32); the CR is then BOOL."""
    sim = scan(program("i, limit : INT := 32; r : BOOL;", "LD i\nLT limit\nST r"), i=i)
    assert sim.read("P.r") is expected


def test_function_with_the_cr_as_first_argument_il30_il04():
    """IL-30 / IL-04: ``LD -8 / LIMIT A, 5 / ST X`` is ``X := LIMIT(-8, A, 5)``; ``LD 7 / Fct 2, 4`` is
    ``Fct(7, 2, 4)`` (a user function: 7 * 2 / 4 = 3 in INT)."""
    fct = "FUNCTION Fct : INT\nVAR_INPUT P1, P2, P3 : INT; END_VAR\nLD P1\nMUL P2\nDIV P3\nST Fct\nEND_FUNCTION\n"
    sim = scan(program("A, X, Result : INT;", "LD -8\nLIMIT A, 5\nST X\nLD 7\nFct 2, 4\nST Result", fct), A=-20)
    assert (sim.read("P.X"), sim.read("P.Result")) == (-8, 3)


def test_il_bodies_use_the_declaration_sections_of_st_seed000_il04():
    """Seed 000 IL-04 (Ex 4.1, 4.2): an IL FB with VAR_INPUT, VAR_IN_OUT, VAR_OUTPUT, VAR, VAR CONSTANT and
    VAR_TEMP, called from an IL program through VAR_EXTERNAL: scan k adds 3 * 2 to g (10 + 6k) and counts k."""
    source = """
VAR_GLOBAL g : INT := 10; END_VAR
FUNCTION_BLOCK Acc
VAR_INPUT step : INT; END_VAR
VAR_IN_OUT total : INT; END_VAR
VAR_OUTPUT calls : INT; END_VAR
VAR n : INT; END_VAR
VAR CONSTANT k : INT := 2; END_VAR
VAR_TEMP t : INT; END_VAR
LD step
MUL k
ST t
LD total
ADD t
ST total
LD n
ADD 1
ST n
ST calls
END_FUNCTION_BLOCK
PROGRAM P
VAR_EXTERNAL g : INT; END_VAR
VAR a : Acc; c : INT; END_VAR
CAL a(step := 3, total := g, calls => c)
END_PROGRAM
"""
    sim = Simulation(lower_ok(source))
    for k in range(1, 4):
        scan(sim)
        assert (sim.read("g"), sim.read("P.c")) == (10 + 6 * k, k)
