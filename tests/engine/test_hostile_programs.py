"""Programs that broke the build path (issue 18): each builds and runs, or is refused with a located error.

Every test builds through ``simulation.build_project`` (what the server and the CLI use) in all three
variants and runs scans; expected values are worked out by hand from the program text.
"""

from __future__ import annotations

import threading

import pytest

from ladderlab.engine.codegen.layout import PAGE_SIZE
from ladderlab.model import Pou, Project, Task
from ladderlab.simulation.build import build_project

VARIANTS = ("fast", "monitor", "debug")


def st(name: str, declarations: str, body: str, kind: str = "program", return_type: str | None = None) -> Pou:
    return Pou(name=name, kind=kind, language="st", declarations=declarations, body=body, return_type=return_type)


def run(project: Project, variant: str, scans: int, *paths: str) -> list[object]:
    build = build_project(project, variant)
    assert build.compiled is not None, [d.format() for d in build.diagnostics]
    assert [d for d in build.diagnostics if d.severity == "error"] == []
    sim = build.simulation()
    assert sim.cycle(scans) == scans
    assert sim.fault is None
    return [sim.read(path) for path in paths]


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_type_named_like_a_generated_struct_class_builds(variant: str) -> None:
    """Issue 18: TYPE STRUCT_2 plus two anonymous STRUCT variables gave two generated classes one name and
    the code generator looped forever (40 such requests stopped the server)."""
    project = Project(
        name="p",
        types="TYPE STRUCT_2 : STRUCT p : INT; q : INT; END_STRUCT; END_TYPE",
        pous=[
            st(
                "Main",
                "VAR c : STRUCT_2; a : STRUCT x : INT; END_STRUCT; b : STRUCT y : INT; END_STRUCT; "
                "STRUCT_1 : STRUCT z : INT; END_STRUCT; END_VAR",
                "a.x := a.x + 1; b.y := a.x * 10; c.q := b.y + 1; STRUCT_1.z := c.q + 1;",
            )
        ],
    )
    result: list[object] = []
    worker = threading.Thread(target=lambda: result.append(run(project, variant, 3, *PATHS)), daemon=True)
    worker.start()
    worker.join(60)
    assert not worker.is_alive(), "the build hangs"
    assert result == [[3, 30, 31, 32]]


PATHS = ("Main.a.x", "Main.b.y", "Main.c.q", "Main.STRUCT_1.z")


@pytest.mark.parametrize("variant", VARIANTS)
@pytest.mark.parametrize("language", ["ld", "fbd"])
def test_an_empty_diagram_pou_builds_and_runs(variant: str, language: str) -> None:
    """Issue 18: an empty LD/FBD POU (what a new diagram starts as) crashed the code generator, even unused."""
    project = Project(
        name="p",
        pous=[
            st("Main", "VAR n : INT; f : EmptyFb; END_VAR", "f(); n := n + 1 + EmptyFn(1);"),
            Pou(name="EmptyFb", kind="function_block", language=language, body={"networks": []}),
            Pou(
                name="EmptyFn",
                kind="function",
                language=language,
                return_type="INT",
                body={"networks": []},
                declarations="VAR_INPUT x : INT; END_VAR",
            ),
            Pou(name="EmptyProgram", kind="program", language=language, body={"networks": []}),
        ],
        tasks=[Task(name="T", programs=["Main", "EmptyProgram"])],
    )
    # an empty FUNCTION returns its result's initial value, 0: n counts one per scan
    assert run(project, variant, 4, "Main.n") == [4]


# ----------------------------------------------------------------- nesting (issue 18: Python's limits surfaced)


def nested(opening: str, closing: str, depth: int, inner: str) -> str:
    return opening * depth + inner + closing * depth


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_long_sum_and_deep_unary_chains_compute_their_values(variant: str) -> None:
    """A 250-term sum, 300 nested NOT and 300 nested ABS gave RecursionError (500 or a traceback)."""
    project = Project(
        name="p",
        pous=[
            st(
                "Main",
                "VAR s : DINT; big : DINT; b : BOOL; a : DINT; END_VAR",
                "s := " + " + ".join(str(k) for k in range(1, 251)) + ";\n"
                "big := " + " + ".join(["2147483647"] * 3) + ";\n"  # wraps twice in DINT
                "b := " + "NOT " * 300 + "TRUE;\n"
                "a := " + nested("ABS(", ")", 300, "-5") + ";",
            )
        ],
    )
    # 1 + ... + 250 = 250 * 251 / 2; 3 * (2^31 - 1) = 6442450941 wraps to 6442450941 - 2 * 2^32 = 2147483645
    assert run(project, variant, 1, "Main.s", "Main.big", "Main.b", "Main.a") == [31375, 2147483645, True, 5]


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_deep_expression_keeps_the_left_to_right_order_of_calls_and_reads(variant: str) -> None:
    """Deep expressions are computed part by part; a function that changes a global between two reads of it
    must see and leave the same values as the nested evaluation: g, Bump(), g, Bump(), ... left to right."""
    project = Project(
        name="p",
        globals="VAR_GLOBAL g : DINT; END_VAR",
        pous=[
            st("Bump", "VAR_EXTERNAL g : DINT; END_VAR", "g := g + 1; Bump := g;", "function", "DINT"),
            st("Main", "VAR r : DINT; END_VAR", "g := 0; r := " + " + ".join(["g", "Bump()"] * 60) + ";"),
        ],
    )
    # term pairs (k, k + 1) for k = 0..59: the sum of the odd numbers 1..119 = 60^2
    assert run(project, variant, 1, "Main.r", "g") == [3600, 60]


def for_nest(depth: int, innermost: str) -> str:
    heads = "".join(f"FOR k{level} := 1 TO 1 DO\n" for level in range(depth))
    return "FOR a := 1 TO 3 DO\n" + heads + innermost + "END_FOR;\n" * depth + "END_FOR;\n"


def for_declarations(depth: int) -> str:
    return "VAR a, n, m, after : DINT; " + " ".join(f"k{level} : DINT;" for level in range(depth)) + " END_VAR"


@pytest.mark.parametrize("variant", VARIANTS)
def test_21_nested_for_loops_run_with_exit_and_return_from_the_innermost(variant: str) -> None:
    """21 nested FOR gave 'too many statically nested blocks' (CPython allows 20 per function)."""
    body = for_nest(20, "n := n + 1;\nIF a = 2 THEN EXIT; END_IF;\nm := m + 1;\n")
    exits = Project(name="p", pous=[st("Main", for_declarations(20), body)])
    # a = 1, 2, 3 each reach the innermost once: n counts 3; a = 2 leaves it before m counts
    assert run(exits, variant, 1, "Main.n", "Main.m") == [3, 2]
    body = for_nest(20, "n := n + 1;\nIF a = 3 THEN RETURN; END_IF;\n") + "after := after + 1;\n"
    returns = Project(name="p", pous=[st("Main", for_declarations(20), body)])
    assert run(returns, variant, 2, "Main.n", "Main.after") == [6, 0]


@pytest.mark.parametrize("variant", VARIANTS)
def test_100_nested_ifs_in_a_program_and_in_a_function(variant: str) -> None:
    """100 nested IF gave 'too many levels of indentation' (CPython allows 100)."""
    ifs = nested("IF b THEN\n", "END_IF;\n", 100, "x := x + 7;\n")
    function_ifs = nested("IF b THEN\n", "END_IF;\n", 100, "Deep := b2 + 1;\n")
    project = Project(
        name="p",
        pous=[
            st("Main", "VAR x, y : DINT; b : BOOL := TRUE; END_VAR", ifs + "y := Deep(TRUE, 41);"),
            st("Deep", "VAR_INPUT b : BOOL; b2 : DINT; END_VAR", function_ifs, "function", "DINT"),
        ],
    )
    assert run(project, variant, 2, "Main.x", "Main.y") == [14, 42]


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_case_with_3000_labels_and_an_if_with_3000_branches(variant: str) -> None:
    """A CASE with 3,000 labels gave 'maximum recursion depth exceeded during compilation'."""
    case = "CASE x OF\n" + "".join(f"{k}: y := {2 * k};\n" for k in range(3000)) + "ELSE y := -1;\nEND_CASE;\n"
    chain = "IF x = 0 THEN z := 0;\n" + "".join(f"ELSIF x = {k} THEN z := {3 * k};\n" for k in range(1, 3000))
    chain += "ELSE z := -1;\nEND_IF;\n"
    project = Project(name="p", pous=[st("Main", "VAR x, y, z : DINT; END_VAR", case + chain + "x := x + 1499;")])
    build = build_project(project, variant)
    sim = build.simulation()
    seen = []
    for _ in range(3):  # x = 0, 1499, 2998, then 4497: beyond the labels
        sim.cycle(1)
        seen.append((sim.read("Main.y"), sim.read("Main.z")))
    assert seen == [(0, 0), (2998, 4497), (5996, 8994)]
    sim.cycle(1)
    assert (sim.read("Main.y"), sim.read("Main.z")) == (-1, -1)


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_long_if_chain_in_a_program_of_two_pages_of_slots(variant: str) -> None:
    """An IF with more than 64 branches continues in flat groups behind a flag saying no branch was taken yet; the
    flag was the local ``ll_p1``, which also holds the second page of a large PROGRAM's slots, so the program's
    next read of a slot there failed with an internal error."""
    filler = ", ".join(f"f{i}" for i in range(PAGE_SIZE))
    chain = "IF k = 0 THEN y := 1;\n" + "".join(f"ELSIF k = {i} THEN y := y + {i};\n" for i in range(1, 80))
    body = chain + "END_IF;\ny := y + 1;\nk := k + 1;"
    project = Project(name="p", pous=[st("Main", f"VAR k : INT := 70; {filler} : BOOL; y : INT; END_VAR", body)])
    assert run(project, variant, 1, "Main.y", "Main.k") == [71, 71]  # the ELSIF k = 70 branch, then y + 1
    assert run(project, variant, 2, "Main.y", "Main.k") == [71 + 71 + 1, 72]


@pytest.mark.parametrize("variant", VARIANTS)
def test_deep_conditions_of_elsif_and_while_are_evaluated_each_time(variant: str) -> None:
    """A deep condition is computed on lines before its test: after an ELSIF and in a WHILE it must still be
    evaluated only when, and every time, the nested form would be."""
    deep_true = nested("NOT (", ")", 60, "FALSE")  # 60 NOTs of FALSE: FALSE
    deep_lt = "i < " + nested("(", ")", 1, " + ".join(["1"] * 5))  # i < 5, as a sum of 5 ones
    deep_lt = "(" + deep_lt + ") AND " + nested("NOT (", ")", 60, "FALSE") + " = FALSE"
    body = (
        f"IF n = 0 THEN hit := 1; ELSIF {deep_true} = FALSE THEN hit := 2; ELSE hit := 3; END_IF;\n"
        f"i := 0; WHILE {deep_lt} DO i := i + 1; END_WHILE;\n"
        "n := n + 1;"
    )
    project = Project(name="p", pous=[st("Main", "VAR n, hit, i : DINT; END_VAR", body)])
    assert run(project, variant, 1, "Main.hit", "Main.i") == [1, 5]
    assert run(project, variant, 2, "Main.hit", "Main.i") == [2, 5]


def test_nesting_beyond_the_documented_limits_is_a_located_error(monkeypatch: pytest.MonkeyPatch) -> None:
    """Deeper than the limit: refused where it crosses it, naming the limit and its setting."""
    statements = nested("IF b THEN\n", "END_IF;\n", 201, "x := 1;\n")
    project = Project(name="p", pous=[st("Main", "VAR x : DINT; b : BOOL; END_VAR", statements)])
    build = build_project(project, "fast")
    assert build.compiled is None
    [error] = [d for d in build.diagnostics if d.severity == "error"]
    assert (error.code, error.pou, error.line, error.column) == ("ST-TOO-DEEP", "Main", 201, 1)
    assert error.message == (
        "this statement nests deeper than the limit of 200 levels for the nesting of statements "
        "(the setting LADDERLAB_MAX_STATEMENT_DEPTH raises it)"
    )
    monkeypatch.setenv("LADDERLAB_MAX_STATEMENT_DEPTH", "250")
    assert build_project(project, "fast").compiled is not None
    expression = Project(name="p", pous=[st("Main", "VAR x : DINT; END_VAR", "x := " + "1 + " * 1000 + "1;")])
    [error] = [d for d in build_project(expression, "fast").diagnostics if d.severity == "error"]
    assert (error.code, error.line) == ("ST-TOO-DEEP", 1)
    assert error.message.startswith("this expression nests deeper than the limit of 1,000 levels")


@pytest.mark.parametrize(
    ("setting", "body", "code_line"),
    [
        # the tightest texts: one character per expression level, 15 per statement level (the parser skips
        # the nesting walk for texts too short to cross a limit: st/parser.py, _nesting_needs)
        ("LADDERLAB_MAX_EXPRESSION_DEPTH", "x:=" + "-" * 12 + "1;", 1),
        ("LADDERLAB_MAX_STATEMENT_DEPTH", "IF b THEN " * 11 + "END_IF;" * 11, 1),
        ("LADDERLAB_MAX_STATEMENT_DEPTH", "IF(b)THEN\n" * 11 + "END_IF\n" * 11, 11),
    ],
)
def test_the_shortest_texts_beyond_a_lowered_limit_are_refused(
    monkeypatch: pytest.MonkeyPatch, setting: str, body: str, code_line: int
) -> None:
    monkeypatch.setenv(setting, "10")
    project = Project(name="p", pous=[st("Main", "VAR x : DINT; b : BOOL; END_VAR", body)])
    [error] = [d for d in build_project(project, "fast").diagnostics if d.severity == "error"]
    assert (error.code, error.line) == ("ST-TOO-DEEP", code_line)


# ----------------------------------------------------------------- size limits (issue 18 item 5)


def errors_of(project: Project) -> list[tuple[str, str | None, int | None, str]]:
    build = build_project(project, "fast")
    assert build.compiled is None
    return [(d.code, d.pou, d.line, d.message) for d in build.diagnostics if d.severity == "error"]


def test_arrays_and_strings_beyond_the_limits_are_located_errors_not_memory_errors() -> None:
    """ARRAY[0..1000000000] OF BOOL gave MemoryError in /api/check; STRING[1000000000] checked clean, then 500."""
    declarations = (
        "VAR\n  big : ARRAY[0..1000000000] OF BOOL;\n  s : STRING[1000000000];\n"
        "  grid : ARRAY[0..9] OF ARRAY[0..200000] OF INT;\n  fine : ARRAY[1..1000000] OF BOOL;\nEND_VAR"
    )
    project = Project(name="p", pous=[st("Main", declarations, "")])
    suffix = " (the setting {} raises it)"
    assert errors_of(project) == [
        (
            "LIMIT-SIZE",
            "Main",
            2,
            "the array has 1,000,000,001 elements, more than the limit of 1,000,000 elements for one array"
            + suffix.format("LADDERLAB_MAX_ARRAY_ELEMENTS"),
        ),
        (
            "LIMIT-SIZE",
            "Main",
            3,
            "STRING[1000000000] holds 1,000,000,000 characters, more than the limit of 255 characters for one STRING"
            + suffix.format("LADDERLAB_MAX_STRING_LENGTH"),
        ),
        (
            "LIMIT-SIZE",
            "Main",
            4,
            "the array has 2,000,010 elements, more than the limit of 1,000,000 elements for one array"
            + suffix.format("LADDERLAB_MAX_ARRAY_ELEMENTS"),
        ),
    ]


def test_the_settings_raise_the_size_limits(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("LADDERLAB_MAX_STRING_LENGTH", "1000")
    project = Project(name="p", pous=[st("Main", "VAR s : STRING[1000]; n : INT; END_VAR", "s := 'x'; n := LEN(s);")])
    assert run(project, "fast", 1, "Main.n") == [1]


def test_the_data_of_a_program_is_bounded_with_its_largest_variable_named() -> None:
    holder = st("Holder", "VAR a : ARRAY[1..1000] OF LREAL; END_VAR", "", "function_block")
    main = st("Main", "VAR many : ARRAY[1..900] OF Holder; more : ARRAY[1..900000] OF INT; END_VAR", "")
    other = st("Other", "VAR x, y : ARRAY[1..999999] OF DINT; END_VAR", "")
    fits = Project(name="p", pous=[holder, main, other])
    assert build_project(fits, "fast").compiled is not None  # 900 * 1,001 + 900,000 + 2 * 999,999 = 3,800,898
    project = fits.model_copy(update={"globals": "VAR_GLOBAL g : ARRAY[1..500000] OF BOOL; END_VAR"})
    [(code, pou, line, message)] = errors_of(project)
    assert (code, pou, line) == ("LIMIT-SIZE", "OTHER", None)
    assert message == (
        "the variables of this program hold 4,300,898 values (the largest, OTHER.X, 999,999), more than the "
        "limit of 4,000,000 values for the data of one program (the setting LADDERLAB_MAX_DATA_VALUES raises it)"
    )


def test_st_text_beyond_the_limit_is_refused_before_it_is_parsed(monkeypatch: pytest.MonkeyPatch) -> None:
    """A 4 MB source peaked at 2.7 GB online: the text is measured first."""
    body = "x := x + 1;\n" * 100_000  # 1,200,000 characters, less the final newline the model strips
    project = Project(name="p", pous=[st("Main", "VAR x : DINT; END_VAR", body)])
    [(code, pou, _, message)] = errors_of(project)  # + 21 characters of declarations
    assert (code, pou) == ("LIMIT-SIZE", "Main")
    assert message == (
        "the project's ST text has 1,200,020 characters (the largest POU, Main, has 1,200,020), more than the "
        "limit of 1,048,576 characters for the ST text of one project (the setting LADDERLAB_MAX_SOURCE_CHARACTERS "
        "raises it)"
    )


@pytest.mark.parametrize("variant", ["fast", "debug"])
def test_nesting_right_at_the_limits_builds_on_the_stack_sized_for_them(variant: str) -> None:
    """The stack of ladderlab/deep.py is sized for the documented limits: 200 nested statements around an
    expression whose sum and calls reach 1,000 levels must build and run (no RecursionError, no crash)."""
    expression = "ABS(" * 400 + "1" + ")" * 400 + " + " + " + ".join(["1"] * 199)  # 800 + 199 + 1 levels
    body = "IF b THEN\n" * 199 + "FOR i := 1 TO 1 DO\n" + f"x := {expression};\n" + "END_FOR;\n" + "END_IF;\n" * 199
    project = Project(name="p", pous=[st("Main", "VAR x : DINT; i : INT; b : BOOL := TRUE; END_VAR", body)])
    assert run(project, variant, 1, "Main.x") == [200]
