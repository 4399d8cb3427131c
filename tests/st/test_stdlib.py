"""The standard function / FB catalogue: IEC pin names, generic families, extensibility (FUN-xx, SFB-xx)."""

from ladderlab.iec import stdlib


def test_sfb01_fb_pins_are_the_iec_names():
    pins = {
        name: ([p.name for p in fb.inputs], [p.name for p in fb.outputs])
        for name, fb in stdlib.FUNCTION_BLOCKS.items()
        if name.count("_") == 0 or name.endswith("TRIG")
    }
    assert pins == {
        "SR": (["S1", "R"], ["Q1"]),
        "RS": (["S", "R1"], ["Q1"]),
        "R_TRIG": (["CLK"], ["Q"]),
        "F_TRIG": (["CLK"], ["Q"]),
        "CTU": (["CU", "R", "PV"], ["Q", "CV"]),
        "CTD": (["CD", "LD", "PV"], ["Q", "CV"]),
        "CTUD": (["CU", "CD", "R", "LD", "PV"], ["QU", "QD", "CV"]),
        "TP": (["IN", "PT"], ["Q", "ET"]),
        "TON": (["IN", "PT"], ["Q", "ET"]),
        "TOF": (["IN", "PT"], ["Q", "ET"]),
    }
    assert stdlib.function_block("ctu").inputs[0].edge == "R_EDGE"


def test_st23_typed_counters_have_their_cv_type_and_match_the_runtime():
    from ladderlab.engine.stdlib import STANDARD_FBS

    ctd = stdlib.function_block("CTD_DINT")
    assert [(p.name, p.type) for p in ctd.inputs + ctd.outputs] == [
        ("CD", "BOOL"),
        ("LD", "BOOL"),
        ("PV", "DINT"),
        ("Q", "BOOL"),
        ("CV", "DINT"),
    ]
    assert set(stdlib.FUNCTION_BLOCKS) == set(STANDARD_FBS)


def test_fun10_conversions_cover_all_pairs_in_long_and_short_spellings():
    assert stdlib.function("INT_TO_REAL").result == "REAL"
    assert stdlib.function("DT_TO_TOD").inputs[0].type == "DATE_AND_TIME"
    assert stdlib.function("DATE_AND_TIME_TO_TIME_OF_DAY").result == "TIME_OF_DAY"
    assert stdlib.function("INT_TO_INT") is None
    conversions = [f for f in stdlib.FUNCTIONS.values() if "_TO_" in f.name and f.name not in stdlib.ED3_CONVERSIONS]
    # 24 types + WSTRING + the TOD, DT, LTOD and LDT spellings = 29 names; drop pairs naming one type twice (21
    # singles, 4 x 4 alias pairs)
    assert len(conversions) == 29 * 29 - 21 - 4 * 4
    assert stdlib.function("WSTRING_TO_STRING").inputs[0].type == "WSTRING"
    assert stdlib.function("LDT_TO_LTOD").result == "LTIME_OF_DAY"


def test_fun03_extensible_inputs_are_numbered_on():
    add = stdlib.function("ADD")
    assert (add.extensible, add.input_name(2), add.pin("IN9").type) == (True, "IN3", "ANY_NUM")
    mux = stdlib.function("MUX")
    assert [mux.input_name(i) for i in range(4)] == ["K", "IN0", "IN1", "IN2"]
    assert stdlib.function("SUB").input_name(2) is None and stdlib.function("SUB").pin("IN3") is None


def test_fun05_formal_names_and_families():
    assert [(p.name, p.type, p.generic) for p in stdlib.function("LIMIT").inputs] == [
        ("MN", "ANY", True),
        ("IN", "ANY", True),
        ("MX", "ANY", True),
    ]
    assert [(p.name, p.type) for p in stdlib.function("SHL").inputs] == [("IN", "ANY_BIT"), ("N", "ANY_INT")]
    assert stdlib.function("EXPT").inputs[1].generic is False
    assert stdlib.function("MULTIME").result == stdlib.function("MUL_TIME").result == "TIME"


def test_every_entry_has_a_description_for_the_box_picker():
    entries = [*stdlib.FUNCTIONS.values(), *stdlib.FUNCTION_BLOCKS.values()]
    assert all(e.description and e.spec for e in entries)
