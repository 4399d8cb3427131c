"""The ``ladderlab`` command line: serve, check, run, test, compile, export, doc, import, schema."""

from __future__ import annotations

import argparse
import ipaddress
import json
import os
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import TYPE_CHECKING

from ..collector import frozen_start
from ..engine.variants import VARIANTS
from ..model import has_errors
from ..simulation.registry import SimulationRegistry, SimulationSettings
from ..storage import StorageError, load_project_path
from ..storage.atomic import write_atomic
from ..storage.load import load_project_with_warnings
from ..storage.project_folder import revision_of
from ..storage.text_files import CLI_HINT, xml_for_parser
from .doc import add_doc_command
from .encoding import add_encoding_option, encoding_of
from .libraries import add_library_option, using_libraries
from .test import add_test_command

if TYPE_CHECKING:  # the server and the compiler are imported only by the commands that use them (issue 27)
    import uvicorn

    from ..model import Project
    from ..server.security import Security
    from ..simulation.build import Build
    from .run import Row

EXIT_OK, EXIT_ERRORS, EXIT_USAGE, EXIT_RUNTIME, EXIT_NOT_REACHED, EXIT_INTERNAL = 0, 1, 2, 3, 4, 70
#: ``schema --name``: the files of ``model.schema.SCHEMA_MODELS``, which imports the monitor's models when the command
#: runs (not to serve: startup, issue 27).
SCHEMA_FILES = ("monitor.schema.json", "project.schema.json")
#: How many scans ``--until`` runs at most when neither --cycles nor --for says.
UNTIL_LIMIT = 1_000_000


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    try:
        code: int = args.func(args)
        return code
    except StorageError as err:
        for diagnostic in err.diagnostics:
            print(diagnostic.format(), file=sys.stderr)
        return EXIT_USAGE
    except UnicodeDecodeError as err:  # a file in another encoding (its own located message where it is read)
        print(
            f"ladderlab: the input is not UTF-8 text: {err.reason} at byte {err.start}; save it as UTF-8",
            file=sys.stderr,
        )
        return EXIT_USAGE
    except OSError as err:  # a file that cannot be read or written: the user's to fix, not a bug
        print(f"ladderlab: {err.filename or ''}{': ' if err.filename else ''}{err.strerror or err}", file=sys.stderr)
        return EXIT_USAGE
    except KeyboardInterrupt:
        return 130
    except Exception as err:  # a bug: one line, not a traceback (LADDERLAB_TRACEBACK=1 shows it)
        if os.environ.get("LADDERLAB_TRACEBACK"):
            raise
        print(f"ladderlab: internal error: {type(err).__name__}: {err} (please report it)", file=sys.stderr)
        return EXIT_INTERNAL


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="ladderlab", description="IEC 61131-3 LD/FBD/ST editor and simulator")
    sub = parser.add_subparsers(dest="command", required=True)

    serve = sub.add_parser("serve", help="start the web app and API server")
    serve.add_argument("--host", default="127.0.0.1")
    serve.add_argument("--port", type=int, default=8000)
    serve.add_argument(
        "--workspace", type=Path, default=None, help="project folder (default: $LADDERLAB_WORKSPACE or ./workspace)"
    )
    serve.add_argument(
        "--allow-remote",
        action="store_true",
        help="serve other machines (or a TLS proxy): binding another address is allowed and everyone must sign in "
        "with the token printed at start ($LADDERLAB_TOKEN fixes it) or the --password-file",
    )
    serve.add_argument(
        "--password-file",
        type=Path,
        default=None,
        help="sign in with the first line of this file instead of a token (keep it readable by you only)",
    )
    serve.add_argument(
        "--allowed-host",
        action="append",
        default=[],
        metavar="NAME",
        help="a host name the server is reached under besides 127.0.0.1, localhost and [::1] (repeatable; "
        "'*' for any, with --allow-remote only)",
    )
    serve.add_argument(
        "--allowed-origin",
        action="append",
        default=[],
        metavar="ORIGIN",
        help="a browser origin allowed to use the API besides the served one, e.g. https://plc.example.com "
        "behind a TLS proxy (repeatable)",
    )
    serve.add_argument(
        "--secure-cookies", action="store_true", help="mark the session cookie Secure (behind a TLS proxy)"
    )
    serve.add_argument(
        "--history-mb",
        type=_non_negative,
        default=SimulationSettings.history_mb,
        metavar="MB",
        help="scan history kept per simulation: checkpoints and input log, the oldest dropped first "
        f"(default {SimulationSettings.history_mb}; 0: none)",
    )
    serve.set_defaults(func=_serve)

    check = sub.add_parser("check", help="load and check a project, print diagnostics")
    check.add_argument("project", type=Path, help="project folder, project .json file or .st / .il file")
    add_encoding_option(check)
    add_library_option(check)
    check.add_argument("--format", choices=["text", "json"], default="text")
    check.set_defaults(func=_check)

    run = sub.add_parser("run", help="run a project on the virtual clock and print watched values per scan")
    run.add_argument("project", type=Path, help="project folder, project .json file or .st / .il file")
    add_encoding_option(run)
    add_library_option(run)
    length = run.add_mutually_exclusive_group()
    length.add_argument("--cycles", type=int, default=None, metavar="N", help="number of scans (default 1)")
    length.add_argument(
        "--for",
        dest="for_",
        default=None,
        metavar="DURATION",
        help="run every scan due within this virtual time, e.g. 2s or T#500ms",
    )
    run.add_argument(
        "--set",
        dest="sets",
        action="append",
        default=[],
        metavar="PATH=VALUE[@SCAN]",
        help="write VALUE (IEC literal) to PATH before scan SCAN (default 0); repeatable",
    )
    run.add_argument(
        "--watch",
        action="append",
        default=[],
        metavar="PATH",
        help="print this variable after every scan (MAIN.x, GVL.y, y, MAIN.T1.Q, MAIN.a[3]); default: every variable",
    )
    run.add_argument(
        "--events",
        type=Path,
        default=None,
        metavar="FILE",
        help="replay input events (JSON lines with the scan each applies before, as a simulation's "
        "'Download inputs' gives them: panel presses, writes, forces, faults, resets)",
    )
    run.add_argument(
        "--fault",
        dest="faults",
        action="append",
        default=[],
        metavar="PATH=MODE[@SCAN]",
        help="inject a fault into a signal before scan SCAN: stuck_true, stuck_false, open, noisy, stuck:VALUE",
    )
    run.add_argument("--seed", type=int, default=0, help="the seed of --fault ...=noisy (default 0)")
    run.add_argument(
        "--until",
        default=None,
        metavar="CONDITION",
        help="stop after the first scan where CONDITION holds (Motor, NOT Alarm, Tank.Level >= 80); "
        f"exit {EXIT_NOT_REACHED} when it never did within --cycles/--for (default: {UNTIL_LIMIT:,} scans)",
    )
    run.add_argument("--format", choices=["table", "jsonl"], default="table")
    run.add_argument(
        "--record",
        type=Path,
        default=None,
        metavar="FILE",
        help="write a recording of this run (project path and revision, inputs, scans): ladderlab replay FILE",
    )
    run.set_defaults(func=_run)

    replay = sub.add_parser("replay", help="print a recorded run's rows again, exactly (ladderlab run --record)")
    replay.add_argument("recording", type=Path, help="the file ladderlab run --record wrote")
    replay.add_argument("--project", type=Path, default=None, help="the project (default: its recorded path)")
    replay.add_argument("--seek", type=int, default=None, metavar="N", help="scans 0..N only: the last row is scan N")
    replay.add_argument(
        "--watch", action="append", default=[], metavar="PATH", help="print these variables (default: as recorded)"
    )
    replay.add_argument("--format", choices=["table", "jsonl"], default="table")
    replay.set_defaults(func=_replay)

    add_test_command(sub)

    compile_ = sub.add_parser("compile", help="check and compile a project; optionally print the generated Python")
    compile_.add_argument("project", type=Path, help="project folder, project .json file or .st / .il file")
    add_encoding_option(compile_)
    add_library_option(compile_)
    compile_.add_argument("--emit-python", action="store_true", help="print the generated Python module")
    compile_.add_argument("--variant", choices=list(VARIANTS), default="fast")
    compile_.set_defaults(func=_compile)

    export = sub.add_parser("export", help="export a project as PLCopen XML or IEC ST text")
    export.add_argument("format", choices=["plcopen", "st"])
    export.add_argument("project", type=Path, help="project folder, project .json file or .st / .il file")
    add_encoding_option(export)
    add_library_option(export)
    export.add_argument("--pou", default=None, help="st: only this POU (default: the whole project)")
    export.add_argument(
        "--sfc-text",
        action="store_true",
        help="st: SFC POUs as IEC textual SFC (INITIAL_STEP, TRANSITION ...) instead of the ST of their scan",
    )
    export.add_argument("-o", "--output", type=Path, default=None, help="file to write (default: standard output)")
    export.add_argument(
        "--with-plants",
        action="store_true",
        help="keep the project's plants (as programs run by a task PLANTS); by default only the control program",
    )
    export.set_defaults(func=_export)

    add_doc_command(sub)

    import_ = sub.add_parser("import", help="import a PLCopen XML project into a workspace")
    import_.add_argument("format", choices=["plcopen"])
    import_.add_argument("file", type=Path)
    add_encoding_option(import_)
    import_.add_argument(
        "--into", type=Path, default=None, help="workspace folder (default: $LADDERLAB_WORKSPACE or ./workspace)"
    )
    import_.add_argument("--name", default=None, help="project name (default: the document's, else the file name)")
    import_.set_defaults(func=_import)

    schema = sub.add_parser("schema", help="print the JSON Schema of the project model")
    schema.add_argument("--name", choices=SCHEMA_FILES, default="project.schema.json")
    schema.set_defaults(func=_schema)
    return parser


def _load(args: argparse.Namespace) -> Project:
    """The PROJECT argument, its files read in ``--encoding``, with the ``--library`` options. A .st file is parsed
    under the ``--typing`` rules (CODESYS's ``END_IF`` without ``;`` before a statement only warns)."""
    from ..st.types import typing_rules

    with typing_rules(getattr(args, "typing", None) or "iec"):
        project, warnings = load_project_with_warnings(args.project, encoding_of(args))
    for warning in warnings:  # a .st file's: not the command's result, so beside any error, never failing it
        print(warning.format(), file=sys.stderr)
    return using_libraries(project, args)


def _check(args: argparse.Namespace) -> int:
    from ..simulation.check import check_project

    project = _load(args)
    diagnostics = check_project(project)
    if args.format == "json":
        print(json.dumps([d.model_dump(exclude_none=True) for d in diagnostics], indent=2))
    else:
        for diagnostic in diagnostics:
            print(diagnostic.format())
        errors = sum(d.severity == "error" for d in diagnostics)
        print(f"{project.name}: {len(project.pous)} POUs, {errors} errors, {len(diagnostics) - errors} warnings")
    return EXIT_ERRORS if has_errors(diagnostics) else EXIT_OK


def _build(args: argparse.Namespace, variant: str = "fast") -> Build | None:
    """Load and build the project; prints the diagnostics and returns None when it has errors."""
    return _built(_load(args), variant)


def _built(project: Project, variant: str = "fast") -> Build | None:
    """Build ``project``; prints the diagnostics and returns None when it has errors."""
    from ..simulation.build import build_project

    build = build_project(project, variant)
    for diagnostic in build.diagnostics:
        print(diagnostic.format(), file=sys.stderr)
    return build if build.compiled is not None else None


def _run(args: argparse.Namespace) -> int:
    from ..engine.inputs import AppliedInput
    from ..simulation.conditions import BadCondition, parse_condition
    from ..simulation.events import parse_events
    from ..simulation.recording import Recording
    from .run import parse_duration, parse_fault, parse_set, run_scans

    try:
        sets = [parse_set(text) for text in args.sets]
        for_ms = parse_duration(args.for_) if args.for_ is not None else None
        events = [parse_fault(text, args.seed) for text in args.faults]
        if args.events is not None:
            events += parse_events(_read_events(args.events), str(args.events))
    except (ValueError, OSError) as error:
        print(f"ladderlab run: {error}", file=sys.stderr)
        return EXIT_USAGE
    build = _build(args)
    if build is None:
        return EXIT_ERRORS
    sim = build.simulation()
    until = None
    if args.until is not None:
        try:
            until = parse_condition(args.until, sim)
        except BadCondition as error:
            print(f"ladderlab run: --until {error}", file=sys.stderr)
            return EXIT_USAGE
    watch = args.watch or list(sim.snapshot())
    limited = args.cycles is not None or for_ms is not None
    cycles = args.cycles if limited else (UNTIL_LIMIT if until is not None else 1)
    applied: list[AppliedInput] = []
    sim.on_input = applied.append
    rows = run_scans(sim, watch=watch, sets=sets, events=events, cycles=cycles, for_ms=for_ms, until=until)
    code = _print_rows(rows, watch, args.format, "run")
    if code != EXIT_OK:
        return code
    if args.record is not None:
        recording = Recording(
            str(args.project.resolve()),
            revision_of(load_project_path(args.project)),
            sim.scan_count,
            args.watch or None,
            [line.to_json() for line in applied],
        )
        try:
            write_atomic(args.record, recording.to_bytes())
        except OSError as error:
            print(f"ladderlab run: --record {args.record}: {error.strerror or error}", file=sys.stderr)
            return EXIT_USAGE
    if sim.fault is not None:
        print(sim.fault.diagnostic().format(), file=sys.stderr)
        return EXIT_RUNTIME
    if until is not None and not until.holds(sim):
        print(f"ladderlab run: {until.text} did not hold within {sim.scan_count} scans", file=sys.stderr)
        return EXIT_NOT_REACHED
    return EXIT_OK


def _print_rows(rows: Iterator[Row], watch: list[str], form: str, command: str) -> int:
    from .run import jsonl_line, table_lines

    try:
        lines = (jsonl_line(row) for row in rows) if form == "jsonl" else table_lines(rows, watch)
        for line in lines:
            print(line)
    except (KeyError, ValueError) as error:  # unknown path, value that does not fit its variable
        print(f"ladderlab {command}: {error.args[0] if error.args else error}", file=sys.stderr)
        return EXIT_USAGE
    return EXIT_OK


def _replay(args: argparse.Namespace) -> int:
    """The rows of a recorded run again: the same project revision, the same inputs at the same scans."""
    from ..simulation.recording import read_recording
    from .run import run_scans

    try:
        recording = read_recording(args.recording)
        events = recording.scheduled(str(args.recording))
    except ValueError as error:
        print(f"ladderlab replay: {error}", file=sys.stderr)
        return EXIT_USAGE
    if args.seek is not None and not 0 <= args.seek < recording.scans:
        print(
            f"ladderlab replay: --seek {args.seek}: the recording has scans 0 to {recording.scans - 1}", file=sys.stderr
        )
        return EXIT_USAGE
    args.project = args.project or Path(recording.project)
    project = load_project_path(args.project)
    revision = revision_of(project)
    if revision != recording.revision:
        print(
            f"ladderlab replay: {args.project} is at revision {revision}, the recording was made at revision "
            f"{recording.revision}: replay it with the project as it was (--project)",
            file=sys.stderr,
        )
        return EXIT_USAGE
    build = _built(project)
    if build is None:
        return EXIT_ERRORS
    sim = build.simulation()
    watch = args.watch or recording.watch or list(sim.snapshot())
    cycles = recording.scans if args.seek is None else args.seek + 1
    code = _print_rows(run_scans(sim, watch=watch, events=events, cycles=cycles), watch, args.format, "replay")
    if code == EXIT_OK and sim.fault is not None:
        print(sim.fault.diagnostic().format(), file=sys.stderr)
        return EXIT_RUNTIME
    return code


def _read_events(path: Path) -> str:
    try:
        return path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise ValueError(f"--events {path}: no such file") from None
    except UnicodeDecodeError as error:
        raise ValueError(f"--events {path}: not UTF-8 text ({error.reason})") from None


def _compile(args: argparse.Namespace) -> int:
    build = _build(args, args.variant)
    if build is None or build.compiled is None:
        return EXIT_ERRORS
    if args.emit_python:
        print(build.compiled.source)
    return EXIT_OK


def _export(args: argparse.Namespace) -> int:
    from ..interchange.plants import for_export
    from ..interchange.plcopen.exporter import PlcopenExportError, export_plcopen

    project = _load(args)
    if args.pou is None:
        project = for_export(project, args.with_plants)
    if args.format == "plcopen":
        if args.pou is not None:
            print("ladderlab export plcopen: --pou applies to st only", file=sys.stderr)
            return EXIT_USAGE
        try:
            data = export_plcopen(project)
        except PlcopenExportError as error:
            for diagnostic in error.diagnostics:
                print(diagnostic.format(), file=sys.stderr)
            return EXIT_ERRORS
    else:
        text = _st_export(project, args.pou, args.sfc_text)
        if text is None:
            return EXIT_ERRORS
        data = text
    if args.output is None:
        sys.stdout.write(data.decode("utf-8"))
    else:
        write_atomic(args.output, data)
    return EXIT_OK


def _st_export(project: Project, pou: str | None, sfc_text: bool = False) -> bytes | None:
    from ..interchange.st.export import export_pou_st
    from ..interchange.st.project import export_project_st

    result = (
        export_pou_st(project, pou, sfc_text=sfc_text)
        if pou is not None
        else export_project_st(project, sfc_text=sfc_text)
    )
    for diagnostic in result.diagnostics:
        print(diagnostic.format(), file=sys.stderr)
    return None if has_errors(result.diagnostics) else result.text.encode("utf-8")


def _import(args: argparse.Namespace) -> int:
    from ..interchange.plcopen.importer import import_plcopen
    from ..storage import Workspace

    if not args.file.is_file():
        print(f"{args.file}: error BAD-PATH: no such file", file=sys.stderr)
        return EXIT_USAGE
    data = xml_for_parser(args.file.read_bytes(), args.file.name, encoding_of(args), CLI_HINT)  # exit 2 when not text
    result = import_plcopen(data, name=args.name, file=args.file.name)
    for diagnostic in result.diagnostics:
        print(diagnostic.format(), file=sys.stderr)
    if result.project is None or has_errors(result.diagnostics):
        return EXIT_ERRORS
    workspace = Workspace(args.into or Path(os.environ.get("LADDERLAB_WORKSPACE", "workspace")))
    workspace.create(result.project)
    print(f"imported {result.project.name!r} ({len(result.project.pous)} POUs) into {workspace.root}")
    return EXIT_OK


def _schema(args: argparse.Namespace) -> int:
    from ..model.schema import SCHEMA_MODELS, schema_of

    print(json.dumps(schema_of(SCHEMA_MODELS[args.name]), indent=2, sort_keys=True))
    return EXIT_OK


def _is_loopback(host: str) -> bool:
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def _non_negative(text: str) -> int:
    """An argparse type: a whole number >= 0."""
    try:
        number = int(text)
    except ValueError:
        number = -1
    if number < 0:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number >= 0")
    return number


def _serve(args: argparse.Namespace) -> int:
    with frozen_start():
        server = _server(args)
    if isinstance(server, int):
        return server
    server.run()
    return EXIT_OK


def _server(args: argparse.Namespace) -> uvicorn.Server | int:
    """The server ``serve`` runs, its modules imported and its app made; an exit code when the options refuse it."""
    import uvicorn

    from ..examples import seed_workspace
    from ..server.app import create_app
    from ..server.limits import Limits
    from ..server.logs import install_repeat_filter
    from ..storage import Workspace

    if not _is_loopback(args.host) and not args.allow_remote:
        print(f"refusing to bind to {args.host}: pass --allow-remote to serve other machines", file=sys.stderr)
        return EXIT_USAGE
    try:
        security = serve_security(args)
    except ValueError as error:
        print(f"ladderlab serve: {error}", file=sys.stderr)
        return EXIT_USAGE
    workspace = Workspace(args.workspace or Path(os.environ.get("LADDERLAB_WORKSPACE", "workspace")))
    seeded = seed_workspace(workspace)
    if seeded:
        print(f"workspace was empty: added the example project {seeded!r}")
    shown = "localhost" if args.host in ("0.0.0.0", "::") else args.host
    url = f"http://{f'[{shown}]' if ':' in shown else shown}:{args.port}/"
    auth = security.auth
    if auth is not None and auth.kind == "token":
        print(f"LadderLab on {url}?token={auth.secret} (workspace {workspace.root})")
        print("Open that link to sign in; anyone with the token can edit and run projects.")
    else:
        print(f"LadderLab on {url} (workspace {workspace.root})")
    open_files = raise_open_files_limit()
    limits = Limits(max_websockets=min(Limits.max_websockets, open_files // 2))
    app = create_app(workspace, limits, security)
    app.state.simulations = SimulationRegistry(SimulationSettings(history_mb=args.history_mb))
    config = uvicorn.Config(
        app,
        host=args.host,
        port=args.port,
        log_level="warning",
        limit_concurrency=max(64, open_files - 64),  # connections beyond it get a 503, never EMFILE
    )
    install_repeat_filter()  # after uvicorn.Config, which sets up the server's log handlers
    config.load()  # imports the protocols' modules now, under frozen_start
    return uvicorn.Server(config)


def serve_security(args: argparse.Namespace) -> Security:
    """The server's Security from the command line: its names, extra origins and sign-in."""
    from ..server.auth import Auth
    from ..server.security import LOOPBACK_HOSTS, Security

    hosts = set(LOOPBACK_HOSTS) | {name.strip().strip("[]").lower() for name in args.allowed_host}
    if not _is_loopback(args.host) and args.host not in ("0.0.0.0", "::"):
        hosts.add(args.host.strip("[]").lower())
    auth = None
    if args.password_file is not None:
        try:
            password = args.password_file.read_text(encoding="utf-8").splitlines()[0].strip()
        except (OSError, UnicodeDecodeError, IndexError) as error:
            raise ValueError(f"cannot read a password from {args.password_file}: {error}") from None
        if len(password) < 8:
            raise ValueError(f"the password in {args.password_file} is shorter than 8 characters")
        auth = Auth(password, "password", args.secure_cookies)
    elif args.allow_remote:
        token = os.environ.get("LADDERLAB_TOKEN", "").strip()
        auth = Auth(token, "token", args.secure_cookies) if token else Auth.new_token(args.secure_cookies)
    if "*" in hosts and auth is None:
        raise ValueError("--allowed-host '*' needs --allow-remote or --password-file (everyone must sign in)")
    origins = frozenset(origin.strip().rstrip("/") for origin in args.allowed_origin)
    return Security(hosts=frozenset(hosts), origins=origins, auth=auth)


def raise_open_files_limit() -> int:
    """Raise the soft limit of open files to the hard one (Unix); returns it (what connections may use)."""
    try:
        import resource
    except ImportError:  # Windows: no such limit to raise
        return 4096
    soft, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
    wanted = hard if hard != resource.RLIM_INFINITY else max(soft, 65536)
    try:
        resource.setrlimit(resource.RLIMIT_NOFILE, (wanted, hard))
    except (ValueError, OSError):
        wanted = soft
    return wanted
