"""IR -> Python source: the code generator (see docs/runtime.md, "Generated code").

``module.generate(program, variant)`` writes one module per program: a class
per PROGRAM / FUNCTION_BLOCK, a function per FUNCTION, a class per structure
type, the globals. ``engine.compile`` compiles it; ``engine.simulation`` runs it.
"""

from ..variants import VARIANTS
from .module import Generated, generate

__all__ = ["VARIANTS", "Generated", "generate"]
