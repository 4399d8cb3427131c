"""``deep_call``: run a build step on a stack deep enough for the documented nesting limits.

The parser, checker, lowering and code generator recurse once (or a few times) per nesting level
of an expression or statement. CPython's default recursion limit (1,000 frames) and the default
thread stack (8 MB, less on macOS and Windows) end a 250-term sum or 300 nested ``NOT`` in a
RecursionError. ``limits.EXPRESSION_DEPTH`` and ``limits.STATEMENT_DEPTH`` bound the nesting of
what is accepted (st/nesting.py refuses deeper text with a located diagnostic), so a fixed
number of frames per level suffices: each call runs in a fresh thread with a stack sized for the
limits and the interpreter's recursion limit raised to match (it is never lowered again: it is
one number for all threads, and the inputs other threads recurse over are bounded too - JSON and
XML depth, LD nesting).
"""

from __future__ import annotations

import sys
import threading
from collections.abc import Callable
from typing import Any, Literal, TypeVar

from . import limits

T = TypeVar("T")

#: Frames one nesting level may take in the deepest-recursing pass, and the frames below it.
FRAMES_PER_LEVEL = 12
BASE_FRAMES = 2_000
#: C stack per frame budgeted (a Python-to-Python call takes none in 3.11; calls through C take ~0.5-2 KB).
STACK_PER_FRAME = 2_048
MIN_STACK = 32 * 1024 * 1024

_lock = threading.Lock()


def raise_recursion_limit() -> int:
    """Raise the interpreter's recursion limit to what the nesting limits need (never lower it)."""
    frames = budget()[0]
    if sys.getrecursionlimit() < frames:
        sys.setrecursionlimit(frames)
    return frames


def budget() -> tuple[int, int]:
    """(recursion limit, thread stack bytes) for the current nesting limits."""
    levels = limits.EXPRESSION_DEPTH.value + limits.STATEMENT_DEPTH.value + limits.DIAGRAM_DEPTH.value
    frames = BASE_FRAMES + FRAMES_PER_LEVEL * levels
    return frames, max(MIN_STACK, frames * STACK_PER_FRAME)


def deep_call(function: Callable[..., T], *args: Any, **kwargs: Any) -> T:
    """``function(*args, **kwargs)`` in a thread with the stack and recursion limit the nesting limits need;
    its result, or its exception re-raised here."""
    stack = budget()[1]
    outcome: list[tuple[Literal[True], T] | tuple[Literal[False], BaseException]] = []

    def run() -> None:
        try:
            outcome.append((True, function(*args, **kwargs)))
        except BaseException as error:  # handed to the caller's thread
            outcome.append((False, error))

    with _lock:
        raise_recursion_limit()
        previous = threading.stack_size(stack)
        try:
            worker = threading.Thread(target=run, name="ladderlab-deep", daemon=True)
            worker.start()
        finally:
            threading.stack_size(previous)
    worker.join()
    result = outcome[0]
    if result[0]:
        return result[1]
    raise result[1]


raise_recursion_limit()  # at import, not in the middle of someone's recursion
