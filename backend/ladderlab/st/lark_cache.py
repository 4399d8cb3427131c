"""LALR parsers whose tables come from a cache file, so a process builds them once per grammar, not per start.

Building the LALR tables of the ST grammar takes ~0.3 s, more than parsing a typical project; lark can save
them (``cache=``) and load them in a fraction of that. The file lives in the user's cache directory
(``platformdirs``; ``LADDERLAB_CACHE_DIR`` overrides it), named by a digest of the grammar, the options, lark's
and Python's versions, so installs of different versions never read each other's tables. A cache directory that
cannot be written (a read-only home, a sandbox) only means the tables are built in memory as before.
"""

from __future__ import annotations

import hashlib
import os
import pathlib
import sys
from typing import Any

import lark
from lark import Lark
from platformdirs import user_cache_dir

CACHE_ENV = "LADDERLAB_CACHE_DIR"


def cache_dir() -> pathlib.Path:
    return pathlib.Path(os.environ.get(CACHE_ENV) or user_cache_dir("ladderlab", appauthor=False))


def cache_file(name: str, grammar: str, options: dict[str, Any]) -> pathlib.Path:
    """Where the tables of ``grammar`` built with ``options`` are kept (the transformer does not change them)."""
    key = repr(sorted((k, v) for k, v in options.items() if k != "transformer"))
    digest = hashlib.sha256(f"{grammar}\0{key}\0{lark.__version__}\0{sys.version_info[:2]}".encode()).hexdigest()
    return cache_dir() / f"{name}-{digest[:20]}.lark"


def cached_lark(name: str, grammar: str, **options: Any) -> Lark:
    """``Lark(grammar, parser="lalr", **options)`` with its tables loaded from (or saved to) the cache file."""
    path = cache_file(name, grammar, options)
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        writable = os.access(path.parent, os.W_OK)
    except OSError:
        writable = False
    if not writable and not path.exists():
        return Lark(grammar, parser="lalr", **options)
    return Lark(grammar, parser="lalr", cache=str(path), **options)
