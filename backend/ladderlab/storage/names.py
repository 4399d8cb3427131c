"""Name checks that refuse, before any file is touched, names that could escape the workspace."""

from __future__ import annotations

from ..model.names import pou_name_problem, project_name_problem, test_file_name_problem
from .errors import InvalidNameError


def check_pou_name(name: str) -> str:
    problem = pou_name_problem(name)
    if problem:
        raise InvalidNameError("POU", name, problem)
    return name


def check_project_name(name: str) -> str:
    problem = project_name_problem(name)
    if problem:
        raise InvalidNameError("project", name, problem)
    return name


def check_test_file_name(name: str) -> str:
    problem = test_file_name_problem(name)
    if problem:
        raise InvalidNameError("test file", name, problem)
    return name
