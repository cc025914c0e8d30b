"""Compiles TLA+ expressions into Python closures ``f(s, t, L) -> value``.

Names are resolved once, at compile time, to state slots, frame slots, constants
or compiled operators, so evaluation never dispatches on AST node types.  Each
user operator is compiled once per scope; operators whose body is action-level
(contains primes, UNCHANGED or ENABLED) are expanded at their call site instead,
because the action compiler (`actions.py`) must see their structure.

Semantics follow TLC: ``=`` between values of different kinds is an error (model
values excepted), arithmetic on non-integers is an error, sets are enumerated in
TLC's normalised order (CHOOSE picks the first witness in that order).

The compiler is one class composed of a mixin per expression family (the modules of
`tla/compile/`); this module keeps the entry points, the dispatch on node types with
constant folding, and the literals.
"""

from __future__ import annotations

from typing import Any, Callable

from . import ast as A
from .compile.analysis import SEARCH_STATE, AnalysisMixin, Info
from .compile.binders import BindersMixin, _assign, _comprehension, _enum_checked
from .compile.calls import CallsMixin, CompiledDef
from .compile.closures import EMPTY, Value, _guard, _prefix, check_bool, enum
from .compile.conditionals import ConditionalsMixin
from .compile.expansion import ExpansionMixin
from .compile.functions import FunctionsMixin
from .compile.instances import InstancesMixin
from .compile.let import LetMixin
from .compile.logic import LogicMixin
from .compile.names import NamesMixin
from .compile.operators import OperatorsMixin
from .compile.primes import PrimesMixin
from .compile.recursive_functions import RecursiveFunction, RecursiveFunctionsMixin
from .compile.sets import SetsMixin
from .compile.syntax import _children, _subterms, all_names
from .constfold import ConstFolder, const_code, fold
from .env import Code, Env, Frame
from .errors import Loc, TlaError, UnsupportedError
from .fold_memo import FoldMemo
from .modules import Scope
from .op_memo import OpMemo

# Names other modules import from here (actions.py, inline.py, op_memo.py, resolve.py,
# checker/, the tests): this module stays their import path.
__all__ = ["Compiler", "CompiledDef", "EMPTY", "Info", "RecursiveFunction", "SEARCH_STATE", "Value",
           "_assign", "_children", "_comprehension", "_enum_checked", "_guard", "_prefix", "_subterms",
           "all_names", "check_bool", "enum"]

_LITERALS = (A.Num, A.Str, A.Bool)


class Compiler(AnalysisMixin, NamesMixin, CallsMixin, ExpansionMixin, InstancesMixin, LetMixin,
               RecursiveFunctionsMixin, BindersMixin, LogicMixin, ConditionalsMixin, OperatorsMixin, SetsMixin,
               FunctionsMixin, PrimesMixin):
    """Compiles expressions of one model (fixed constants) to closures."""

    # Constant folding, inlining and the specialised closures (constfold.py,
    # inline.py, specialise.py).  The tests turn them off to compare with the
    # general closures.
    fast_paths = True
    memoise_operators = True  # op_memo.py; off only to compare with the plain calls

    def __init__(self, constants: dict[str, Value], overrides: dict[str, Any]) -> None:
        # CONSTANT name -> value (from the .cfg); `overrides` maps names to symbols for `C <- Op`.
        self.constants = constants
        self.overrides = overrides
        # id(symbol) -> replacing symbol, for `C <- Op` and definitions given values
        self.sym_overrides: dict[int, Any] = {}
        self._inline_depth = 0
        self._inlined_nodes = 0  # body nodes inlined so far (inline.MAX_INLINED_NODES)
        # > 0 while compiling a body that runs re-entrantly on a shared frame (see inline.py).
        self._no_inline = 0
        self.folder = ConstFolder(self)
        self.fold_memo = FoldMemo(self.folder)
        self.op_memo = OpMemo(self)
        # (id of a LET's INSTANCE, id of the enclosing scope) -> the LET body's scope
        self._let_scopes: dict[tuple[int, int], Scope] = {}
        self._lazy_defs: dict[int, tuple[Any, Any]] = {}  # compile/calls.py: _compiled_def(lazy=True)
        self._lazy_mode = 0  # compiling a body for lazy arguments (compile/lazy_args.py)

    # ================================================================ entry points
    def compile_unit(self, e: A.Expr, scope: Scope) -> tuple[Code, int]:
        """Compile a top-level expression; returns (code, frame size)."""
        frame = Frame()
        code = self.expr(e, Env(scope, frame))
        return code, frame.size

    def evaluator(self, e: A.Expr, scope: Scope) -> Callable[[Any, Any], Value]:
        code, size = self.compile_unit(e, scope)
        if size == 0:
            return lambda s, t: code(s, t, EMPTY)
        return lambda s, t: code(s, t, [None] * size)

    # ================================================================ resolution
    def _resolve(self, name: str, scope: Scope) -> Any:
        return scope.lookup(name)

    def _unknown(self, name: str, loc: Loc) -> TlaError:
        return TlaError("semantic", f"Unknown operator: `{name}'.", loc)

    # ================================================================ expressions
    def expr(self, e: A.Expr, env: Env) -> Code:
        method = getattr(self, "c_" + type(e).__name__, None)
        if method is None:
            raise UnsupportedError(f"unsupported expression {type(e).__name__}", e.loc)
        if self.fast_paths and type(e) not in _LITERALS and self.folder.is_constant(e, env):
            return self.fold_memo.fold(e, env, self._inline_depth,
                                       lambda: fold(method(e, env), env.frame.size))
        return method(e, env)

    def c_Num(self, e: A.Num, env: Env) -> Code:
        return const_code(e.value)

    def c_Str(self, e: A.Str, env: Env) -> Code:
        return const_code(e.value)

    def c_Bool(self, e: A.Bool, env: Env) -> Code:
        return const_code(e.value)

    def c_Unsupported(self, e: A.Unsupported, env: Env) -> Code:
        raise UnsupportedError(f"unsupported construct: {e.what}", e.loc)
