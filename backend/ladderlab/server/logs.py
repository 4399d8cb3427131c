"""One log line per condition, not per event.

A server under a flood (1,200 websocket connections exhausting file descriptors logged 514,000
tracebacks in 41 s) must not fill the disk with one record per failed event. ``RepeatFilter``
lets the first record of a kind through (same logger, level, message template and exception type)
and drops the repeats for ``window_s``; the first one after that says how many were dropped.
"""

from __future__ import annotations

import logging
import threading
import time

WINDOW_S = 60.0
#: Loggers with handlers of their own (the ASGI server's); ours and asyncio's reach the root's.
SERVER_LOGGERS = ("uvicorn", "uvicorn.error", "uvicorn.access")


class RepeatFilter(logging.Filter):
    def __init__(self, window_s: float = WINDOW_S) -> None:
        super().__init__()
        self.window_s = window_s
        self._seen: dict[
            tuple[object, ...], tuple[float, int]
        ] = {}  # kind -> (when it was last let through, dropped since)
        self._lock = threading.Lock()

    def filter(self, record: logging.LogRecord) -> bool:
        exc = record.exc_info[0].__name__ if record.exc_info and record.exc_info[0] else None
        kind = (record.name, record.levelno, str(record.msg), exc)
        now = time.monotonic()
        with self._lock:
            last, dropped = self._seen.get(kind, (None, 0))
            if last is not None and now - last < self.window_s:
                self._seen[kind] = (last, dropped + 1)
                return False
            self._seen[kind] = (now, 0)
            if len(self._seen) > 10_000:  # kinds are few; a flood of distinct messages must not grow this
                self._seen = {kind: (now, 0)}
        if dropped:
            # (``last`` is set whenever ``dropped`` is)
            record.msg = f"{record.msg} (and {dropped} more like it in the last {int(now - last)} s)"  # type: ignore[operator]  # see above
        return True


def install_repeat_filter(window_s: float = WINDOW_S) -> RepeatFilter:
    """Attach one shared filter to every handler that writes the server's log (after the ASGI server has
    configured its own), giving the root logger a stderr handler when it has none."""
    repeat = RepeatFilter(window_s)
    root = logging.getLogger()
    if not root.handlers:
        stream = logging.StreamHandler()
        stream.setFormatter(logging.Formatter("%(levelname)s: %(name)s: %(message)s"))
        root.addHandler(stream)
    for logger in (root, *(logging.getLogger(name) for name in SERVER_LOGGERS)):
        for handler in logger.handlers:
            handler.addFilter(repeat)
    return repeat
