"""Unit tests of PLC programs (docs/testing.md): test files in a project, run on the scan engine.

``run.py`` runs the tests of one file, each in a fresh simulation; ``host.py`` carries out the test verbs
for the generated code; ``suite.py`` finds a project's test files and runs them all (in worker processes
when there are many); ``report.py`` writes text, jsonl and JUnit XML; ``coverage.py`` collects what the
tests never executed or energised; ``grade.py`` scores exercises. Shared by the CLI and the server.
"""

#: Scans one test may run at most (here, not in run.py: the command line shows it without the compiler).
DEFAULT_SCAN_BUDGET = 1_000_000
