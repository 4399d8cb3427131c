"""Rules for the names that become identifiers, file names and folder names."""

from __future__ import annotations

import re

IEC_IDENTIFIER = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*\Z")  # \Z: "$" would accept a final newline
TEST_FILE_NAME = re.compile(r"^[A-Za-z0-9][A-Za-z0-9_-]*\Z")
PROJECT_NAME = re.compile(r"^[A-Za-z0-9][A-Za-z0-9 _.-]*\Z")
MAX_NAME_LENGTH = 64


def pou_name_problem(name: str) -> str | None:
    """Why ``name`` is not a valid POU name (IEC identifier, at most 64 characters: DIA-03), or None."""
    if not IEC_IDENTIFIER.match(name):
        return "use letters, digits and '_' and start with a letter or '_'"
    if "__" in name:
        return "IEC identifiers may not contain two '_' in a row"
    if len(name) > MAX_NAME_LENGTH:
        return f"at most {MAX_NAME_LENGTH} characters"
    return None


def project_name_problem(name: str) -> str | None:
    """Why ``name`` cannot be a project (folder) name, or None: no separators, '..' or hidden names."""
    if not name or len(name) > MAX_NAME_LENGTH:
        return f"use 1 to {MAX_NAME_LENGTH} characters"
    if not PROJECT_NAME.match(name) or name.endswith((".", " ")):
        return (
            "use letters, digits, spaces, '_', '-' and '.', start with a letter or digit, "
            "and do not end with '.' or a space"
        )
    return None


def test_file_name_problem(name: str) -> str | None:
    """Why ``name`` cannot name a test file (``tests/<name>.st``), or None."""
    if not name or len(name) > MAX_NAME_LENGTH:
        return f"use 1 to {MAX_NAME_LENGTH} characters"
    if not TEST_FILE_NAME.match(name):
        return "use letters, digits, '_' and '-', starting with a letter or digit"
    return None
