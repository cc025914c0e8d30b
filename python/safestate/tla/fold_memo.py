"""Memoised constant folding: a constant expression is compiled and folded once per
meaning, not once per use.

Operators expanded at their call sites (everything in Init, action-level operators,
small inlined operators) compile their bodies again at every site, and a constant
piece of such a body was compiled and evaluated again each time: HydraulicPress's
``PressParent`` (a 37-state function built with CHOOSE) 4,491 times while loading.

A constant expression's value depends only on the expression, the scope its names
resolve in and what its free local names are bound to (by-name arguments, which are
constant expressions of their own).  That is the memo's key:

* the expression by identity, except literals (by value) and names bound to a
  by-name argument (by the argument's own key), so ``Op(1)`` at two sites and
  ``Up(s)`` with ``s`` bound to the same expression share one entry;
* the scope by identity (the compiler's constants and ``C <- Op`` overrides are
  fixed for its lifetime; the memo belongs to one compiler).

Only successful folds are kept: an expression whose evaluation fails keeps its
ordinary closure (which reads its own frame slots) and is compiled afresh at each
site, so the error is still reported when, and only if, evaluation reaches it.
Compile-time errors cannot be skipped either: a site with the same key compiles the
same way, except for the expansion depth limit, which is checked against the depth
the first compile reached below its site.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Hashable

from . import ast as A
from .constfold import NO_VALUE, ConstFolder, const_value
from .env import ByNameLocal, Code, Env

# Expansion depth at which an operator expansion is refused: a guard for the Python
# stack only (a chain of definitions D_i == D_(i-1) + 1 nests one expansion per
# definition, and TLC accepts any such chain).  A recursion is caught long before it,
# by the nesting of one definition inside itself (`ExpansionMixin.enter_expansion`).
EXPANSION_LIMIT = 5000


@dataclass
class _Folded:
    code: Code          # the constant closure (`const_code`)
    reach: int          # expansion depth the compile reached below its site
    keep: list          # the objects whose ids are in the key (ids must not be reused)


class FoldMemo:
    """Constant closures of one compiler, by expression meaning (see the module docstring)."""

    def __init__(self, folder: ConstFolder) -> None:
        self.folder = folder
        self._memo: dict[Hashable, _Folded] = {}
        self.hits = 0
        # Deepest expansion reached while compiling (see `Compiler.enter_expansion`).
        self.depth_peak = 0

    def key(self, e: A.Expr, env: Env, keep: list) -> Hashable:
        """The meaning of the constant expression `e` in `env`."""
        if isinstance(e, (A.Num, A.Str, A.Bool)):  # leaf classes: no subclasses
            return (type(e).__name__, e.value)
        if isinstance(e, A.Name):
            local = env.locals.get(e.name)
            if isinstance(local, ByNameLocal):
                return self.key(local.expr, local.env, keep)
        keep.append(e)
        keep.append(env.scope)
        names = self.folder.free_names(e) or ()
        bound = tuple((n, self.key(local.expr, local.env, keep)) for n in sorted(names)
                      if isinstance(local := env.locals.get(n), ByNameLocal))
        return (id(e), id(env.scope), bound)

    def fold(self, e: A.Expr, env: Env, depth: int, compile_and_fold: Callable[[], Code]) -> Code:
        """The folded closure of the constant `e` at expansion depth `depth`:
        memoised, or made by `compile_and_fold`."""
        keep: list = []
        key = self.key(e, env, keep)
        hit = self._memo.get(key)
        if hit is not None and depth + hit.reach <= EXPANSION_LIMIT:
            self.hits += 1
            return hit.code
        outer_peak = self.depth_peak
        self.depth_peak = depth
        try:
            code = compile_and_fold()
        finally:
            reach = self.depth_peak - depth
            self.depth_peak = max(outer_peak, self.depth_peak)
        if const_value(code) is not NO_VALUE:
            self._memo[key] = _Folded(code, reach, keep)
        return code
