"""The ladderlab command line, run as a real process."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

from ladderlab.cli import SCHEMA_FILES
from ladderlab.model.schema import SCHEMA_MODELS
from ladderlab.server.app import create_app
from ladderlab.storage import Workspace, load_project_path
from tests.support import EXAMPLES, api_client


def ladderlab(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "ladderlab.cli", *args], capture_output=True, text=True, timeout=60)


def test_check_example_exits_zero() -> None:
    result = ladderlab("check", str(EXAMPLES / "motor"))
    assert result.returncode == 0, result.stdout + result.stderr
    assert "motor: 3 POUs, 0 errors" in result.stdout


def test_check_broken_copy_names_file_and_json_path(tmp_path: Path) -> None:
    folder = tmp_path / "motor"
    shutil.copytree(EXAMPLES / "motor", folder)
    path = folder / "pous" / "Main.ld.json"
    data = json.loads(path.read_text())
    data["body"]["networks"][0]["elements"][1]["mode"] = "sideways"
    path.write_text(json.dumps(data))
    result = ladderlab("check", str(folder))
    assert result.returncode != 0
    assert (
        "pous/Main.ld.json, $.body.networks[0].elements[1].mode: error BAD-FILE: "
        "expected 'no', 'nc', 'p' or 'n', got 'sideways'" in result.stderr
    )


def test_check_reports_model_errors_with_nonzero_exit(tmp_path: Path) -> None:
    project = load_project_path(EXAMPLES / "motor")
    project.tasks[0].programs.append("Blinker")
    path = tmp_path / "motor.json"
    path.write_text(project.model_dump_json())
    result = ladderlab("check", str(path))
    assert result.returncode == 1
    assert (
        "$.tasks[0].programs[2], POU Blinker: error NOT-A-PROGRAM: task MainTask can only run programs; "
        "Blinker is a function block"
    ) in result.stdout


def test_check_accepts_st_file(tmp_path: Path) -> None:
    path = tmp_path / "demo.st"
    path.write_text("PROGRAM Main\nVAR x : INT; END_VAR\nx := x + 1;\nEND_PROGRAM\n")
    result = ladderlab("check", str(path))
    assert result.returncode == 0, result.stderr
    assert "demo: 1 POUs, 0 errors" in result.stdout


def test_check_missing_path() -> None:
    result = ladderlab("check", "/nonexistent/project")
    assert result.returncode == 2
    assert "/nonexistent/project: error BAD-PATH: no such file or folder" in result.stderr


def test_schema_prints_project_schema() -> None:
    result = ladderlab("schema")
    schema = json.loads(result.stdout)
    assert schema["title"] == "Project"
    assert {"name", "format", "types", "globals", "pous", "tasks"} <= set(schema["properties"])


def test_schema_names_are_the_schema_models() -> None:
    """``schema --name`` offers exactly the files model/schema.py makes (the CLI names them without importing it)."""
    assert tuple(sorted(SCHEMA_MODELS)) == SCHEMA_FILES


def test_the_command_line_imports_no_web_framework() -> None:
    """check, run, test, export... never serve: FastAPI and uvicorn come with ``serve`` only (ladderlab doc finds the
    print view through ``server.STATIC_DIR``, not the app's module; issue 27, startup)."""
    code = "import sys, ladderlab.cli; print(sorted({m.split('.')[0] for m in sys.modules} & {'fastapi', 'starlette', 'uvicorn'}))"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60, check=True)
    assert done.stdout.strip() == "[]"


def test_serve_refuses_remote_bind_without_flag() -> None:
    result = ladderlab("serve", "--host", "0.0.0.0", "--port", "1")
    assert result.returncode == 2
    assert "pass --allow-remote" in result.stderr


def test_health_endpoint(tmp_path: Path) -> None:
    client = api_client(create_app(Workspace(tmp_path)))
    assert client.get("/api/health").json()["status"] == "ok"
    assert "LadderLab" in client.get("/").text


def test_project_list_endpoint(tmp_path: Path) -> None:
    workspace = Workspace(tmp_path)
    revision = workspace.create(load_project_path(EXAMPLES / "motor"))
    rows = api_client(create_app(workspace)).get("/api/projects").json()
    assert [(r["name"], r["revision"], r["pou_count"]) for r in rows] == [("motor", revision, 3)]
    assert rows[0]["modified"].endswith("Z") or rows[0]["modified"].endswith("+00:00")


def test_check_reports_st_diagnostics_with_location(tmp_path: Path) -> None:
    path = tmp_path / "demo.st"
    path.write_text("PROGRAM Main\nVAR Start : BOOL; x : INT; END_VAR\nx := Strat;\nEND_PROGRAM\n")
    result = ladderlab("check", str(path))
    assert result.returncode == 1
    assert "unknown variable 'Strat' - did you mean 'Start'?" in result.stdout
    assert "Main/body" in result.stdout


def test_st_file_configuration_becomes_the_project_configuration(tmp_path: Path) -> None:
    path = tmp_path / "plant.st"
    path.write_text(
        "PROGRAM Fast\nVAR n : INT; END_VAR\nn := n + 1;\nEND_PROGRAM\n"
        "PROGRAM Slow\nVAR n : INT; END_VAR\nn := n + 1;\nEND_PROGRAM\n"
        "CONFIGURATION Plant\n  RESOURCE Cpu ON PLC\n"
        "    TASK T1 (INTERVAL := T#5ms, PRIORITY := 1);\n"
        "    TASK T2 (INTERVAL := T#20ms, PRIORITY := 2);\n"
        "    PROGRAM fast_inst WITH T1 : Fast;\n    PROGRAM slow_inst WITH T2 : Slow;\n"
        "  END_RESOURCE\nEND_CONFIGURATION\n"
    )
    project = load_project_path(path)
    assert project.tasks == [] and project.configuration.name == "Plant"
    (resource,) = project.configuration.resources
    assert (resource.name, resource.on) == ("Cpu", "PLC")
    assert [(t.name, t.interval, t.priority, [(p.name, p.type) for p in t.programs]) for t in resource.tasks] == [
        ("T1", "T#5ms", 1, [("fast_inst", "Fast")]),
        ("T2", "T#20ms", 2, [("slow_inst", "Slow")]),
    ]


def test_st_file_syntax_error_is_located_in_the_file(tmp_path: Path) -> None:
    path = tmp_path / "broken.st"
    path.write_text("PROGRAM Main\nVAR x : INT; END_VAR\nx := ;\nEND_PROGRAM\n")
    result = ladderlab("check", str(path))
    assert result.returncode != 0
    assert "broken.st:3:6" in result.stdout + result.stderr
