"""Structured Text front end: parser, AST, checker, printer."""
