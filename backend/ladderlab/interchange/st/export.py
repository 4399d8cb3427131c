"""ST export of a POU: the complete IEC text of an LD/FBD POU that behaves like the diagram (issue 8), or of an
IL POU (``il.py``).

``export_pou_st(project, name)`` returns the POU's text, a source map (text line
-> network and element) and diagnostics. ST POUs export as their text
unchanged. A diagram POU is exported only when it lowers without errors (the
export follows what the engine runs, docs/diagrams.md); the text is the user's
declarations, the variables the export adds (temporaries, edge triggers, ENO
flags) in their own VAR blocks, and one statement group per network. The result
is checked by the project's own ST checker before it is returned.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from ...ir.diagram_checks import canonical_label
from ...ir.lower_project import lower_pou
from ...model import Diagnostic, Pou, Project, has_errors
from ...model.fbd import FbdJump, FbdNetwork
from ...model.sfc import SfcBody
from ...st.checker import check_project
from ...st.columns import align_declarations
from ...st.sfc_text import sfc_to_text
from ...st.symbols import CheckResult
from ...storage.project_folder import OO_KEYS
from ...storage.st_text import compose_pou_text
from .body import Network, body_lines, comment, network_title
from .elements import PouScope
from .fbd import fbd_network
from .il import il_to_st
from .ld import ld_network
from .names import Names
from .network import Declarations, Planned, chart_segments, plan
from .sfc import st_sfc_pou

SourceMap = list[tuple[int, str, str | None]]


@dataclass
class StExport:
    """``text``: complete IEC text ("" when the diagnostics hold an error); ``source_map``: (1-based line of
    ``text``, network id, element id or None) for every line that comes from a network."""

    text: str
    source_map: SourceMap = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)


def export_pou_st(project: Project, pou_name: str, *, sfc_text: bool = False) -> StExport:
    """``sfc_text``: an SFC POU as IEC textual SFC (steps, transitions, actions) instead of the ST of its scan."""
    pou = project.pou(pou_name)
    if pou is None:
        return StExport("", [], [Diagnostic(code="EXPORT-UNKNOWN-POU", message=f"the project has no POU '{pou_name}'")])
    if pou.language == "st":
        return StExport(compose_pou_text(pou))
    if sfc_text and pou.language == "sfc":
        return textual_sfc(project, pou)
    checked = check_project(project)
    exported = st_pou(project, pou, checked)
    if has_errors(exported.diagnostics):
        return StExport("", [], exported.diagnostics)
    problems = verify(project, exported.pou)
    if problems:
        return StExport("", [], exported.diagnostics + problems)
    text = compose_pou_text(exported.pou)
    offset = text.count("\n", 0, text.index(exported.pou.body)) if exported.pou.body else 0
    source_map = [(offset + line, network, element) for line, network, element in exported.source_map]
    return StExport(text, source_map, exported.diagnostics)


@dataclass
class ExportedPou:
    """A diagram POU as an ST ``Pou`` (body lines numbered from 1 in ``source_map``)."""

    pou: Pou | None
    source_map: SourceMap
    diagnostics: list[Diagnostic]


#: A POU's object orientation, ST text already: an exported POU keeps it as it is.
_OBJECT_FIELDS = (*OO_KEYS, "extends")


def st_pou(project: Project, pou: Pou, checked: CheckResult) -> ExportedPou:
    """The ST version of the diagram or IL POU ``pou`` with its METHODs, PROPERTYs, ACTIONs and EXTENDS / IMPLEMENTS
    / ABSTRACT / FINAL (ST already: an FB's or a program's), or diagnostics saying why it cannot be exported."""
    exported = _st_body(project, pou, checked)
    if exported.pou is not None:
        exported.pou = exported.pou.model_copy(update={key: getattr(pou, key) for key in _OBJECT_FIELDS})
    return exported


def _st_body(project: Project, pou: Pou, checked: CheckResult) -> ExportedPou:
    info = checked.pou(pou.name)
    diagnostics: list[Diagnostic] = [
        d for d in checked.diagnostics if d.pou is None or d.pou.upper() == pou.name.upper()
    ]
    if info is None or has_errors(diagnostics):
        return ExportedPou(None, [], _refused(pou, diagnostics))
    if pou.language == "sfc":
        made = st_sfc_pou(project, pou, checked, diagnostics)
        if made.pou is None:
            return ExportedPou(None, [], _refused(pou, made.diagnostics))
        return ExportedPou(made.pou, [], made.diagnostics)
    if pou.language == "il":
        exported_il, problems = il_to_st(pou, checked)
        return ExportedPou(exported_il, [], problems + [d for d in diagnostics if d.severity != "error"])
    lowered = lower_pou(pou, info, checked, diagnostics)
    if has_errors(diagnostics):
        return ExportedPou(None, [], _refused(pou, diagnostics))
    declarations = Declarations(Names.for_pou(checked, pou.name))
    scope = PouScope(checked, info, declarations)
    networks: list[Network] = []
    if pou.language == "cfc":
        networks, labels = _chart(scope, pou.body.chart, lowered, declarations)
    for index, network in enumerate(pou.body.networks if pou.language != "cfc" else []):
        if pou.language == "ld":
            code = ld_network(scope, network, index + 1)
        else:
            code = fbd_network(scope, network, lowered)
        lines = network_title(index + 1, network.label, network.comment)
        controls = [(c.label, c.element) for c in code.controls]
        networks.append(Network(network.id, lines, plan(code, declarations), controls))
    if pou.language != "cfc":
        labels = {canonical_label(n.label): index for index, n in enumerate(pou.body.networks) if n.label}
    lines = body_lines(networks, labels, declarations)
    body = "\n".join(line.text for line in lines)
    source_map = [
        (number, line.network, line.element) for number, line in enumerate(lines, 1) if line.network is not None
    ]
    return ExportedPou(
        Pou(
            name=pou.name,
            kind=pou.kind,
            language="st",
            return_type=pou.return_type,
            declarations=_declarations(pou.declarations, declarations),
            body=body,
        ),
        source_map,
        [d for d in diagnostics if d.severity != "error"],
    )


def _chart(
    scope: PouScope, chart: FbdNetwork, lowered: Any, declarations: Declarations
) -> tuple[list[Network], dict[str, int]]:
    """A CFC chart as the networks ``body_lines`` writes: its statements in execution order (CFC-02), cut at its
    labels and after its jumps, so a jump is a network's jump to a labelled network - forward and nested, ``IF NOT
    cond THEN`` around what it skips; otherwise the state machine (docs/diagrams.md, "CFC")."""
    if any(isinstance(node, FbdJump) for node in chart.nodes):
        declarations.temp_class = "VAR"  # a skipped producer's value is read later as it was left
    planned = plan(fbd_network(scope, chart, lowered, explicit=True), declarations)
    networks: list[Network] = []
    labels: dict[str, int] = {}
    for index, (statements, label, jump) in enumerate(chart_segments(planned)):
        title = [comment("CFC chart: its elements in their execution order (CFC-02)")] if index == 0 else []
        if label is not None:
            labels[label.label] = index
        controls = [(jump[0], jump[2])] if jump else []
        conditions = [jump[1]] if jump else []
        networks.append(Network(chart.id, title, Planned(statements, conditions), controls))
    return networks, labels


def textual_sfc(project: Project, pou: Pou) -> StExport:
    """An SFC POU in IEC textual SFC, refused (located) when it has errors or what the text cannot say."""
    diagnostics = [d for d in check_project(project).diagnostics if (d.pou or "").upper() == pou.name.upper()]
    if has_errors(diagnostics):
        return StExport("", [], _refused(pou, diagnostics))
    assert isinstance(pou.body, SfcBody)
    body, problems = sfc_to_text(pou.name, pou.body)
    if problems:
        return StExport("", [], problems)
    text = compose_pou_text(pou.model_copy(update={"language": "st", "body": body}))
    return StExport(text, [], diagnostics)


def _declarations(user: str, declarations: Declarations) -> str:
    """The user's declarations, then the export's variables (persistent ones, then temporaries), all aligned in
    columns (``st.columns``)."""
    blocks = [user] if user.strip() else []
    for var_class in ("VAR", "VAR_TEMP"):
        items = [(name, type_text) for name, type_text, kind in declarations.items if kind == var_class]
        if items:
            lines = [f"{var_class} {comment('generated by the ST export')}"]
            lines += [f"    {name} : {type_text};" for name, type_text in items]
            blocks.append("\n".join(lines + ["END_VAR"]))
    return align_declarations("\n".join(blocks))


def _refused(pou: Pou, diagnostics: list[Diagnostic]) -> list[Diagnostic]:
    return diagnostics + [
        Diagnostic(
            code="EXPORT-INVALID", pou=pou.name, message=f"{pou.name} has errors: fix them before exporting it as ST"
        )
    ]


def verify(project: Project, exported: Pou) -> list[Diagnostic]:
    """The exported POU in place of the diagram must check without errors; else say so (never silently)."""
    replaced = project.model_copy(update={"pous": [exported if p.name == exported.name else p for p in project.pous]})
    problems = [
        d
        for d in check_project(replaced).diagnostics
        if d.severity == "error" and (d.pou or "").upper() == exported.name.upper()
    ]
    return [
        Diagnostic(
            code="EXPORT-INTERNAL",
            pou=exported.name,
            severity="error",
            message=f"the exported ST of {exported.name} does not check: {d.format()}",
        )
        for d in problems
    ]
