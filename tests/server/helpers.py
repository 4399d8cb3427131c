"""Small helpers for the server tests."""

from __future__ import annotations

from pathlib import Path

from httpx import Response


def folder_bytes(folder: Path) -> dict[str, bytes]:
    """Every file under ``folder`` by relative path: compared before and after a refused save."""
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


def detail(response: Response) -> dict:
    """The error ``detail`` object; every error response must have one with a message."""
    body = response.json()
    assert isinstance(body["detail"], dict), body
    assert isinstance(body["detail"]["message"], str) and body["detail"]["message"], body
    return body["detail"]


def st_program(name: str, declarations: str = "", body: str = "") -> dict:
    return {"name": name, "kind": "program", "language": "st", "declarations": declarations, "body": body}
