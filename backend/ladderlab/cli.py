"""The ``ladderlab`` command line: serve, check, schema (more subcommands arrive with later parts)."""

from __future__ import annotations

import argparse
import ipaddress
import json
import os
import sys
from pathlib import Path

from .check import check_project
from .model import has_errors
from .model.schema import SCHEMA_MODELS, schema_of
from .storage import StorageError, load_project_path

EXIT_OK, EXIT_ERRORS, EXIT_USAGE = 0, 1, 2


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    try:
        return args.func(args)
    except StorageError as err:
        for diagnostic in err.diagnostics:
            print(diagnostic.format(), file=sys.stderr)
        return EXIT_USAGE


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="ladderlab", description="IEC 61131-3 LD/FBD/ST editor and simulator")
    sub = parser.add_subparsers(dest="command", required=True)

    serve = sub.add_parser("serve", help="start the web app and API server")
    serve.add_argument("--host", default="127.0.0.1")
    serve.add_argument("--port", type=int, default=8000)
    serve.add_argument("--workspace", type=Path, default=None,
                       help="project folder (default: $LADDERLAB_WORKSPACE or ./workspace)")
    serve.add_argument("--allow-remote", action="store_true",
                       help="required to bind to an address other than loopback")
    serve.set_defaults(func=_serve)

    check = sub.add_parser("check", help="load and check a project, print diagnostics")
    check.add_argument("project", type=Path, help="project folder, project .json file or .st file")
    check.add_argument("--format", choices=["text", "json"], default="text")
    check.set_defaults(func=_check)

    schema = sub.add_parser("schema", help="print the JSON Schema of the project model")
    schema.add_argument("--name", choices=sorted(SCHEMA_MODELS), default="project.schema.json")
    schema.set_defaults(func=_schema)
    return parser


def _check(args: argparse.Namespace) -> int:
    project = load_project_path(args.project)
    diagnostics = check_project(project)
    if args.format == "json":
        print(json.dumps([d.model_dump(exclude_none=True) for d in diagnostics], indent=2))
    else:
        for diagnostic in diagnostics:
            print(diagnostic.format())
        errors = sum(d.severity == "error" for d in diagnostics)
        print(f"{project.name}: {len(project.pous)} POUs, {errors} errors, {len(diagnostics) - errors} warnings")
    return EXIT_ERRORS if has_errors(diagnostics) else EXIT_OK


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

    from .examples import seed_workspace
    from .server.app import create_app
    from .storage import Workspace

    if not _is_loopback(args.host):
        if not args.allow_remote:
            print(f"refusing to bind to {args.host}: pass --allow-remote to serve other machines", file=sys.stderr)
            return EXIT_USAGE
        print(f"WARNING: serving on {args.host}; anyone who can reach it can edit and run projects",
              file=sys.stderr)
    workspace = Workspace(args.workspace or Path(os.environ.get("LADDERLAB_WORKSPACE", "workspace")))
    seeded = seed_workspace(workspace)
    if seeded:
        print(f"workspace was empty: added the example project {seeded!r}")
    print(f"LadderLab on http://{args.host}:{args.port}/ (workspace {workspace.root})")
    uvicorn.run(create_app(workspace), host=args.host, port=args.port, log_level="warning")
    return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
