"""One log line per condition, not per event (issue 18: 514,000 tracebacks in 41 s)."""

from __future__ import annotations

import logging

import pytest

from ladderlab.server.logs import RepeatFilter


@pytest.fixture
def logged() -> list[logging.LogRecord]:
    return []


def logger_with(repeat: RepeatFilter, records: list[logging.LogRecord]) -> logging.Logger:
    class Keep(logging.Handler):
        def emit(self, record: logging.LogRecord) -> None:
            records.append(record)

    handler = Keep()
    handler.addFilter(repeat)
    logger = logging.getLogger(f"test.repeat.{id(records)}")
    logger.propagate = False
    logger.addHandler(handler)
    return logger


def test_a_flood_of_one_failure_is_one_line_then_a_count(
    logged: list[logging.LogRecord], monkeypatch: pytest.MonkeyPatch
) -> None:
    clock = [1000.0]
    monkeypatch.setattr("ladderlab.server.logs.time.monotonic", lambda: clock[0])
    log = logger_with(RepeatFilter(window_s=60), logged)
    for connection in range(10_000):
        try:
            raise OSError(24, "Too many open files")
        except OSError:
            log.exception("accept failed on connection %d", connection)
    assert len(logged) == 1
    assert logged[0].getMessage() == "accept failed on connection 0"
    clock[0] += 61
    try:
        raise OSError(24, "Too many open files")
    except OSError:
        log.exception("accept failed on connection %d", 10_000)
    assert len(logged) == 2
    assert logged[1].getMessage() == "accept failed on connection 10000 (and 9999 more like it in the last 61 s)"


def test_different_conditions_are_each_logged(logged: list[logging.LogRecord]) -> None:
    log = logger_with(RepeatFilter(window_s=60), logged)
    for _ in range(3):
        log.warning("disk full")
        log.warning("limit reached")
        log.error("disk full")
    assert [(r.levelname, r.getMessage()) for r in logged] == [
        ("WARNING", "disk full"),
        ("WARNING", "limit reached"),
        ("ERROR", "disk full"),
    ]
