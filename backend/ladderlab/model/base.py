"""``Model``: the base of LadderLab's pydantic models, whose validators are built at their first use.

Pydantic builds a model's validator and serializer when the class is defined unless told to wait
(``defer_build``); for the ~100 models of the project files and the API that is ~0.1 s of CPU at every
start of ``ladderlab serve``, most of it for models the first answers never use (startup, issue 27).
The fork server builds them all before it forks workers (simulation/preload.py), so a worker never pays.
"""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict


class Model(BaseModel):
    """A pydantic model built at first use; a subclass's own ``model_config`` adds to this one."""

    model_config = ConfigDict(defer_build=True)


def build_all() -> int:
    """Build every model defined so far (the fork server, before forking); returns how many were built."""
    built = 0
    pending = [Model]
    while pending:
        model = pending.pop()
        pending.extend(model.__subclasses__())
        if model is not Model and not model.__pydantic_complete__:
            model.model_rebuild()
            built += 1
    return built
