"""The variants the code generator writes a program in (``codegen.module.generate``); a module of its own so the
command line can list them without importing the code generator (startup, issue 27)."""

#: fast: no hooks; monitor: probes record power flow; debug: probes and pause points (generators).
VARIANTS = ("fast", "monitor", "debug")
