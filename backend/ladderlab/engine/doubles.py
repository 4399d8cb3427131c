"""Test doubles in a running simulation (docs/testing.md, MOCK and MOCK_FUNCTION).

A mocked FB instance keeps its variables, so callers still write its inputs and tests set its outputs, but
its body no longer runs: each call is only counted. The instance's class is swapped for a subclass whose
``execute`` counts (same slots, so the object stays what every reference points at); a user FUNCTION is
replaced by any callable in the simulation's namespace (``Simulation.replace_function``).
"""

from __future__ import annotations


class Mocks:
    """The mocked instances of one simulation and how often each was called since it was mocked."""

    def __init__(self) -> None:
        self.calls: dict[int, int] = {}
        self._classes: dict[type, type] = {}

    def mock(self, obj: object) -> None:
        if id(obj) in self.calls:
            return
        self.calls[id(obj)] = 0
        obj.__class__ = self._mocked_class(obj.__class__)

    def count(self, obj: object) -> int | None:
        """Calls of a mocked instance (None: it is not mocked)."""
        return self.calls.get(id(obj))

    def _mocked_class(self, cls: type) -> type:
        mocked = self._classes.get(cls)
        if mocked is None:
            calls = self.calls

            def execute(self, now):
                calls[id(self)] += 1

            mocked = self._classes[cls] = type(cls.__name__, (cls,), {"__slots__": (), "execute": execute})
        return mocked
