"""TLA+ front end: parsing (tree-sitter-tlaplus) into a typed AST, module
resolution, native standard modules, values and the closure compiler.

Stable API: ``load_module(path) -> safestate.tla.ast.Module``.
"""

from .errors import EvalError, Loc, TlaError, UnsupportedError
from .modules import load_module

__all__ = ["load_module", "TlaError", "EvalError", "UnsupportedError", "Loc"]
