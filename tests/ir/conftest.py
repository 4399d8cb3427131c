"""Detailed assertion messages from the shared IR test helpers."""

import pytest

pytest.register_assert_rewrite("tests.ir.helpers", "tests.ir.invariants")
