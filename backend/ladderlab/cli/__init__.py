"""The ``ladderlab`` command line: serve, check, run, test, compile, export, doc, import, schema."""

from __future__ import annotations

import argparse
import ipaddress
import json
import os
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from ..engine.codegen import VARIANTS
from ..model import has_errors
from ..model.schema import SCHEMA_MODELS, schema_of
from ..simulation.build import build_project
from ..simulation.check import check_project
from ..storage import StorageError, load_project_path
from ..storage.atomic import write_atomic
from ..storage.text_files import CLI_HINT, xml_for_parser
from .doc import add_doc_command
from .encoding import add_encoding_option, encoding_of
from .run import jsonl_line, parse_duration, parse_set, run_scans, table_lines
from .test import add_test_command

if TYPE_CHECKING:  # the server is imported only by the commands that start it
    from ..model import Project
    from ..server.security import Security
    from ..simulation.build import Build

EXIT_OK, EXIT_ERRORS, EXIT_USAGE, EXIT_RUNTIME, EXIT_INTERNAL = 0, 1, 2, 3, 70


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
    serve.set_defaults(func=_serve)

    check = sub.add_parser("check", help="load and check a project, print diagnostics")
    check.add_argument("project", type=Path, help="project folder, project .json file or .st / .il file")
    add_encoding_option(check)
    check.add_argument("--format", choices=["text", "json"], default="text")
    check.set_defaults(func=_check)

    run = sub.add_parser("run", help="run a project on the virtual clock and print watched values per scan")
    run.add_argument("project", type=Path, help="project folder, project .json file or .st / .il file")
    add_encoding_option(run)
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
    run.add_argument("--format", choices=["table", "jsonl"], default="table")
    run.set_defaults(func=_run)

    add_test_command(sub)

    compile_ = sub.add_parser("compile", help="check and compile a project; optionally print the generated Python")
    compile_.add_argument("project", type=Path, help="project folder, project .json file or .st / .il file")
    add_encoding_option(compile_)
    compile_.add_argument("--emit-python", action="store_true", help="print the generated Python module")
    compile_.add_argument("--variant", choices=list(VARIANTS), default="fast")
    compile_.set_defaults(func=_compile)

    export = sub.add_parser("export", help="export a project as PLCopen XML or IEC ST text")
    export.add_argument("format", choices=["plcopen", "st"])
    export.add_argument("project", type=Path, help="project folder, project .json file or .st / .il file")
    add_encoding_option(export)
    export.add_argument("--pou", default=None, help="st: only this POU (default: the whole project)")
    export.add_argument("-o", "--output", type=Path, default=None, help="file to write (default: standard output)")
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
    schema.add_argument("--name", choices=sorted(SCHEMA_MODELS), default="project.schema.json")
    schema.set_defaults(func=_schema)
    return parser


def _load(args: argparse.Namespace) -> Project:
    """The PROJECT argument, its files read in ``--encoding``."""
    return load_project_path(args.project, encoding_of(args))


def _check(args: argparse.Namespace) -> int:
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
    project = _load(args)
    build = build_project(project, variant)
    for diagnostic in build.diagnostics:
        print(diagnostic.format(), file=sys.stderr)
    return build if build.compiled is not None else None


def _run(args: argparse.Namespace) -> int:
    try:
        sets = [parse_set(text) for text in args.sets]
        for_ms = parse_duration(args.for_) if args.for_ is not None else None
    except ValueError as error:
        print(f"ladderlab run: {error}", file=sys.stderr)
        return EXIT_USAGE
    build = _build(args)
    if build is None:
        return EXIT_ERRORS
    sim = build.simulation()
    watch = args.watch or list(sim.snapshot())
    cycles = args.cycles if args.cycles is not None or for_ms is not None else 1
    rows = run_scans(sim, watch=watch, sets=sets, cycles=cycles, for_ms=for_ms)
    try:
        lines = (jsonl_line(row) for row in rows) if args.format == "jsonl" else table_lines(rows, watch)
        for line in lines:
            print(line)
    except (KeyError, ValueError) as error:  # unknown path, value that does not fit its variable
        print(f"ladderlab run: {error.args[0] if error.args else error}", file=sys.stderr)
        return EXIT_USAGE
    if sim.fault is not None:
        print(sim.fault.diagnostic().format(), file=sys.stderr)
        return EXIT_RUNTIME
    return EXIT_OK


def _compile(args: argparse.Namespace) -> int:
    build = _build(args, args.variant)
    if build is None or build.compiled is None:
        return EXIT_ERRORS
    if args.emit_python:
        print(build.compiled.source)
    return EXIT_OK


def _export(args: argparse.Namespace) -> int:
    from ..interchange.plcopen.exporter import PlcopenExportError, export_plcopen

    project = _load(args)
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
        text = _st_export(project, args.pou)
        if text is None:
            return EXIT_ERRORS
        data = text
    if args.output is None:
        sys.stdout.write(data.decode("utf-8"))
    else:
        write_atomic(args.output, data)
    return EXIT_OK


def _st_export(project: Project, pou: str | None) -> bytes | None:
    from ..interchange.st.export import export_pou_st
    from ..interchange.st.project import export_project_st

    result = export_pou_st(project, pou) if pou is not None else export_project_st(project)
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
    print(json.dumps(schema_of(SCHEMA_MODELS[args.name]), indent=2, sort_keys=True))
    return EXIT_OK


def _is_loopback(host: str) -> bool:
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def _serve(args: argparse.Namespace) -> int:
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
    config = uvicorn.Config(
        create_app(workspace, limits, security),
        host=args.host,
        port=args.port,
        log_level="warning",
        limit_concurrency=max(64, open_files - 64),  # connections beyond it get a 503, never EMFILE
    )
    install_repeat_filter()  # after uvicorn.Config, which sets up the server's log handlers
    uvicorn.Server(config).run()
    return EXIT_OK


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
