"""The LD/FBD POUs of the external PLCopen fixtures (Beremiz, OpenPLC, RuSTy CFC; ../shared/external) export to
ST that checks, and - where the imported project builds - runs like the diagrams (st_support.same_traces)."""

from __future__ import annotations

import pytest

from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.interchange.st.export import export_pou_st
from ladderlab.simulation.build import build_project
from tests.interchange.plcopen_helpers import FOLDERS
from tests.interchange.st_support import same_traces
from tests.support import EXTERNAL, external


def _fixtures() -> list[str]:
    if not EXTERNAL.is_dir():
        return []
    return sorted(
        p.relative_to(EXTERNAL).as_posix()
        for folder in FOLDERS
        if (EXTERNAL / folder).is_dir()
        for p in (EXTERNAL / folder).rglob("*")
        if p.suffix in (".xml", ".cfc")
    )


def _project(path: str):
    return import_plcopen(external(path).read_bytes(), file=path).project


BUILDING = [
    path
    for path in _fixtures()
    if build_project(_project(path)).compiled is not None and any(pou.language != "st" for pou in _project(path).pous)
]


def test_enough_fixtures_build_to_make_the_comparison_worth_it():
    if not _fixtures():
        pytest.skip("../shared/external is not present")
    assert len(BUILDING) >= 8


@pytest.mark.parametrize("path", BUILDING)
def test_exported_fixture_pous_run_like_the_imported_diagrams(path):
    project = _project(path)
    if any(pou.kind == "program" for pou in project.pous):
        same_traces(project)
    for pou in project.pous:
        if pou.language != "st":
            result = export_pou_st(project, pou.name)
            assert result.text and [d.code for d in result.diagnostics if d.severity == "error"] == []


@pytest.mark.parametrize("path", _fixtures())
def test_every_fixture_pou_either_exports_or_is_refused_for_its_own_errors(path):
    """Never EXPORT-INTERNAL: a POU that checks exports to ST that checks, even in a project with other errors."""
    project = _project(path)
    for pou in project.pous:
        if pou.language == "st":
            continue
        result = export_pou_st(project, pou.name)
        codes = [d.code for d in result.diagnostics if d.severity == "error"]
        assert "EXPORT-INTERNAL" not in codes
        assert bool(result.text) == (codes == [])
        if codes:
            assert codes[-1] == "EXPORT-INVALID" and all(d.pou in (None, pou.name) for d in result.diagnostics)
