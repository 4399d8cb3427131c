"""Errors raised by storage, each carrying located diagnostics for the CLI and the server."""

from __future__ import annotations

from typing import Any

from pydantic import ValidationError
from pydantic_core import ErrorDetails

from ..json_guard import json_problem
from ..model import Diagnostic


class StorageError(Exception):
    """Base class; ``diagnostics`` says what is wrong and where."""

    def __init__(self, diagnostics: list[Diagnostic]) -> None:
        self.diagnostics = diagnostics
        super().__init__("\n".join(d.format() for d in diagnostics))


class ProjectLoadError(StorageError):
    """A project file or folder does not parse; nothing was changed."""


class StorageFullError(StorageError):
    """The disk (or the user's quota) is full: the save was not made and the stored project is unchanged."""

    def __init__(self, name: str, reason: str) -> None:
        super().__init__(
            [
                Diagnostic(
                    code="DISK-FULL",
                    message=f"project {name!r} was not saved: {reason}. The stored project is unchanged; "
                    "free some disk space and save again",
                )
            ]
        )


class InvalidNameError(StorageError):
    def __init__(self, what: str, name: str, reason: str) -> None:
        super().__init__([Diagnostic(code="BAD-NAME", message=f"invalid {what} name {name!r}: {reason}")])


class NotFoundError(StorageError):
    def __init__(self, what: str, name: str) -> None:
        super().__init__([Diagnostic(code="NOT-FOUND", message=f"{what} {name!r} does not exist")])


class AlreadyExistsError(StorageError):
    def __init__(self, what: str, name: str) -> None:
        super().__init__([Diagnostic(code="EXISTS", message=f"{what} {name!r} already exists")])


class ConflictError(StorageError):
    """A save based on an old revision: someone else saved in between."""

    def __init__(self, name: str, base_revision: str | None, current_revision: str) -> None:
        self.base_revision = base_revision
        self.current_revision = current_revision
        super().__init__(
            [
                Diagnostic(
                    code="CONFLICT",
                    message=(
                        f"project {name!r} was changed by someone else: this save is based on revision "
                        f"{base_revision}, the saved project is now at revision {current_revision}"
                    ),
                )
            ]
        )


def json_path(data: Any, loc: tuple[int | str, ...]) -> str:
    """Turn a pydantic error location into a JSON path of the input (``$.pous[0].body``).

    Pydantic adds union tags and model names to ``loc``; walking the real data
    keeps only the segments that exist in the document.
    """
    path = "$"
    node = data
    for part in loc:
        if isinstance(node, list) and isinstance(part, int) and 0 <= part < len(node):
            path += f"[{part}]"
            node = node[part]
        elif isinstance(node, dict) and part in node:
            path += f".{part}"
            node = node[part]
        elif isinstance(node, (dict, list)) and isinstance(part, str) and not _is_tag(node, part):
            path += f".{part}"
            node = None
    return path


def _is_tag(node: Any, part: str) -> bool:
    """Whether ``part`` names a union member (a model name or a discriminator value) rather than a key."""
    return part[:1].isupper() or (isinstance(node, dict) and node.get("type") == part) or "[" in part


def validation_diagnostics(error: ValidationError, data: Any, file: str) -> list[Diagnostic]:
    """One diagnostic per pydantic error, naming the file, the JSON path and what was expected."""
    out = []
    for err in error.errors():
        path = json_path(data, tuple(err["loc"]))
        out.append(Diagnostic(code="BAD-FILE", file=file, json_path=path, message=expectation(err)))
    return out


def expectation(err: ErrorDetails) -> str:
    kind = err["type"]
    ctx = err.get("ctx") or {}
    if kind == "missing":
        return f"missing required field '{err['loc'][-1]}'"
    if kind == "extra_forbidden":
        return f"unknown field '{err['loc'][-1]}'"
    if kind == "union_tag_invalid":
        return f"unknown type {ctx.get('tag')!r}: expected one of {ctx.get('expected_tags')}"
    if kind == "union_tag_not_found":
        return "missing field 'type' that says what kind of element this is"
    if kind == "literal_error":
        return f"expected {ctx.get('expected')}, got {err.get('input')!r}"
    message: str = err["msg"].removeprefix("Value error, ")
    if "input" in err and not isinstance(err["input"], (dict, list)):
        message += f" (got {err['input']!r})"
    return message


def json_text_problem(text: str | bytes, file: str | None) -> Diagnostic | None:
    """The located refusal of JSON text nested too deeply or holding a lone surrogate (json_guard.py)."""
    problem = json_problem(text)
    if problem is None:
        return None
    message, line, column = problem
    return Diagnostic(code="BAD-JSON", file=file, line=line, column=column, message=message)
