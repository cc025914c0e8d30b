"""Infix and prefix operators: equality, implication, the core set operators, integer
arithmetic with its fast closures, ``..``, SUBSET, UNION, DOMAIN, ENABLED and UNCHANGED.
Separate because the tables of operator closures (`_CORE_BINARY`, `_FAST_INT`) are
shared with operator arguments (`calls.py`).
"""

from __future__ import annotations

import operator
from typing import TYPE_CHECKING, Any, Callable, cast

from .. import ast as A
from ..constfold import const_value
from ..env import Code, Env
from ..errors import EvalError, JavaOverrideError, Loc, UnsupportedError
from ..modules import BuiltinSym, DefSym
from ..specialise import eq_code, member_const
from ..stdlib import (NATURALS, TLC_MAX_INT, TLC_MIN_INT, cap, cup, domain, non_integer_error, overflow, setminus,
                      subseteq, union)
from ..values import IntervalSet, LazySet, PowerSet, as_set, fmt, member, values_equal
from .closures import Value, check_bool, _guard, _python_error, _need_set
from .host import CompilerHost

if TYPE_CHECKING:
    from ..compiler import Compiler


def _subset(a: Value, b: Value) -> bool:
    return subseteq(a, b) and as_set(a) != as_set(b)


_CORE_BINARY: dict[str, Callable[[Value, Value], Value]] = {
    "\\cup": cup, "\\cap": cap, "\\": setminus, "\\subseteq": subseteq,
    "\\supseteq": lambda a, b: subseteq(b, a), "\\subset": _subset, "\\supset": lambda a, b: _subset(b, a),
    "=": lambda a, b: values_equal(a, b), "/=": lambda a, b: not values_equal(a, b),
    "\\in": lambda a, b: member(a, b), "\\notin": lambda a, b: not member(a, b),
}


def _int_op(op: str, f: Callable[[int, int], Value]) -> Callable[[Code, Code, Loc], Code]:
    if op in ("+", "-", "*"):
        return _arith_op(op, f)

    def make(a: Code, b: Code, loc: Loc) -> Code:
        def slow(x: Value, y: Value) -> Value:
            first = type(x) is not int
            raise non_integer_error(op, x if first else y, first).with_loc(loc)
        c = const_value(b)
        if type(c) is int:
            # `x + 1`, `n - 1`, `i <= N`: the right operand is a constant.
            def code_c(s: Any, t: Any, L: list) -> Value:
                x = a(s, t, L)
                if type(x) is int:
                    return f(x, c)
                return slow(x, c)
            return code_c

        def code(s: Any, t: Any, L: list) -> Value:
            x = a(s, t, L)
            y = b(s, t, L)
            if type(x) is int and type(y) is int:
                return f(x, y)
            return slow(x, y)
        return code
    return make


def _arith_op(op: str, f: Callable[[int, int], int]) -> Callable[[Code, Code, Loc], Code]:
    """`_int_op` for + - *: the result must fit TLC's 32-bit ints (its overflow error
    otherwise), checked with one chained comparison on the fast path."""
    lo, hi = TLC_MIN_INT, TLC_MAX_INT

    def make(a: Code, b: Code, loc: Loc) -> Code:
        def slow(x: Value, y: Value) -> Value:
            if type(x) is int and type(y) is int:
                raise overflow(x, op, y).with_loc(loc)
            first = type(x) is not int
            raise non_integer_error(op, x if first else y, first).with_loc(loc)
        c = const_value(b)
        if type(c) is int:
            def code_c(s: Any, t: Any, L: list) -> Value:
                x = a(s, t, L)
                if type(x) is int:
                    r = f(x, c)
                    if lo <= r <= hi:
                        return r
                return slow(x, c)
            return code_c

        def code(s: Any, t: Any, L: list) -> Value:
            x = a(s, t, L)
            y = b(s, t, L)
            if type(x) is int and type(y) is int:
                r = f(x, y)
                if lo <= r <= hi:
                    return r
            return slow(x, y)
        return code
    return make


def _checked(op: str, fn: Callable, fast: Callable[[int, int], int], ok: Callable[[int], bool]) -> Callable[[Code, Code, Loc], Code]:
    """``%`` and ``\\div``: integers with a valid divisor take the fast path; anything
    else goes through the standard-library function for TLC's error message."""
    def make(a: Code, b: Code, loc: Loc) -> Code:
        def code(s: Any, t: Any, L: list) -> Value:
            try:
                x = a(s, t, L)
                y = b(s, t, L)
                if type(x) is int and type(y) is int and ok(y):
                    return fast(x, y)
                return fn(x, y)
            except EvalError as err:
                err.with_loc(loc)
                raise
            except (TypeError, RecursionError) as err:
                raise EvalError(_python_error(err), loc) from None
        c = const_value(b)
        if type(c) is int and ok(c):
            def code_c(s: Any, t: Any, L: list) -> Value:
                try:
                    x = a(s, t, L)
                except EvalError as err:
                    err.with_loc(loc)
                    raise
                except (TypeError, RecursionError) as err:
                    raise EvalError(_python_error(err), loc) from None
                if type(x) is int:
                    return fast(x, c)
                try:
                    return fn(x, c)
                except EvalError as err:
                    err.with_loc(loc)
                    raise
            return code_c
        return code
    return make


_FAST_INT = {
    "+": _int_op("+", operator.add), "-": _int_op("-", operator.sub),
    "*": _int_op("*", operator.mul), "<": _int_op("<", operator.lt),
    "<=": _int_op("<=", operator.le), ">": _int_op(">", operator.gt),
    ">=": _int_op(">=", operator.ge), "..": _int_op("..", IntervalSet),
    "%": _checked("%", NATURALS["%"].fn, operator.mod, (0).__lt__),
    # A divisor of -1 takes the slow path: MIN_INT \\div -1 is TLC's overflow error.
    "\\div": _checked("\\div", NATURALS["\\div"].fn, operator.floordiv, lambda y: y != 0 and y != -1),
}


class OperatorsMixin(CompilerHost):
    """Binary and unary operators."""

    def c_Binary(self, e: A.Binary, env: Env) -> Code:
        op = e.op
        sym = env.scope.lookup(op)
        if isinstance(sym, DefSym):
            return self._call_def(sym, [e.lhs, e.rhs], env, e.loc)
        if op in ("\\in", "\\notin"):
            if self.fast_paths and self.folder.is_constant(e.rhs, env):
                fast = member_const(self.expr(e.lhs, env), const_value(self.expr(e.rhs, env)), op == "\\notin",
                                    e.loc)
                if fast is not None:
                    return fast
            test = self.membership(e.rhs, env)
            lhs = self.expr(e.lhs, env)
            loc = e.loc
            if op == "\\in":
                return _guard(lambda s, t, L: test(s, t, L, lhs(s, t, L)), loc)
            return _guard(lambda s, t, L: not test(s, t, L, lhs(s, t, L)), loc)
        a, b = self.expr(e.lhs, env), self.expr(e.rhs, env)
        loc = e.loc
        if op in ("=", "/=") and self.fast_paths:
            fast = eq_code(a, b, loc, op == "/=")
            if fast is not None:
                return fast
        if op == "=":
            def eq(s: Any, t: Any, L: list) -> bool:
                x, y = a(s, t, L), b(s, t, L)
                tx = type(x)
                if tx is type(y) and (tx is int or tx is str or tx is bool):
                    return x == y
                try:
                    return values_equal(x, y)
                except EvalError as err:
                    err.with_loc(loc)
                    raise
            return eq
        if op == "/=":
            def neq(s: Any, t: Any, L: list) -> bool:
                x, y = a(s, t, L), b(s, t, L)
                tx = type(x)
                if tx is type(y) and (tx is int or tx is str or tx is bool):
                    return x != y
                try:
                    return not values_equal(x, y)
                except EvalError as err:
                    err.with_loc(loc)
                    raise
            return neq
        if op == "=>":
            la, lb = e.lhs.loc, e.rhs.loc

            def implies(s: Any, t: Any, L: list) -> bool:
                x = a(s, t, L)
                if x is False:
                    return True
                if x is not True:
                    check_bool(x, la)
                y = b(s, t, L)
                return y if (y is True or y is False) else check_bool(y, lb)
            return implies
        if op in ("<=>", "\\equiv"):
            la, lb = e.lhs.loc, e.rhs.loc
            return lambda s, t, L: check_bool(a(s, t, L), la) is check_bool(b(s, t, L), lb)
        core = _CORE_BINARY.get(op)
        if core is not None:
            return _guard(lambda s, t, L: core(a(s, t, L), b(s, t, L)), loc)
        if isinstance(sym, BuiltinSym):
            fast_int = _FAST_INT.get(op) if sym.builtin is NATURALS.get(op) else None
            if fast_int is not None:
                if op == "..":
                    a, b = self._interval_bound(e.lhs, a, env), self._interval_bound(e.rhs, b, env)
                return fast_int(a, b, loc)
            fn = sym.builtin.fn
            return _guard(lambda s, t, L: fn(a(s, t, L), b(s, t, L)), loc)
        if op in ("~>", "-+->"):
            raise UnsupportedError(f"temporal operator {op}", loc)
        if op == "\\cdot":
            raise UnsupportedError("action composition \\cdot", loc)
        raise self._unknown(op, loc)

    def c_Unary(self, e: A.Unary, env: Env) -> Code:
        op = e.op
        if op in ("[]", "<>"):
            raise UnsupportedError(f"temporal operator {op} in an expression evaluated by the checker", e.loc)
        if op == "ENABLED":
            from ..actions import compile_enabled
            return compile_enabled(cast("Compiler", self), e.arg, env)  # a mixin is only ever part of a Compiler
        if op == "UNCHANGED":
            return self._unchanged_expr(e.arg, env)
        user = env.scope.lookup("-." if op == "-" else op)
        if isinstance(user, DefSym):
            return self._call_def(user, [e.arg], env, e.loc)
        a = self.expr(e.arg, env)
        loc = e.loc
        if op == "~":
            aloc = e.arg.loc

            def lnot(s: Any, t: Any, L: list) -> bool:
                v = a(s, t, L)
                if v is True:
                    return False
                if v is False:
                    return True
                return check_bool(v, aloc, "operand of ~")
            return lnot
        if op == "-":
            if not isinstance(user, BuiltinSym):
                raise self._unknown("-", loc)
            fn = user.builtin.fn
            return _guard(lambda s, t, L: fn(a(s, t, L)), loc)
        if op == "SUBSET":
            return _guard(lambda s, t, L: PowerSet(_need_set(a(s, t, L), "SUBSET")), loc)
        if op == "UNION":
            return _guard(lambda s, t, L: union(a(s, t, L)), loc)
        if op == "DOMAIN":
            return _guard(lambda s, t, L: domain(a(s, t, L)), loc)
        if isinstance(user, BuiltinSym):
            fn = user.builtin.fn
            return _guard(lambda s, t, L: fn(a(s, t, L)), loc)
        raise self._unknown(op, loc)

    def _interval_bound(self, e: A.Expr, code: Code, env: Env) -> Code:
        """An operand of `..`.  TLC builds `SUBSET S` without checking S, so with a
        non-set S the error is `..`'s (a Java exception in TLC, `JavaOverrideError`),
        not SUBSET's."""
        if not (isinstance(e, A.Unary) and e.op == "SUBSET"):
            return code
        arg, loc = self.expr(e.arg, env), e.loc

        def bound(s: Any, t: Any, L: list) -> Value:
            v = arg(s, t, L)
            if type(v) is frozenset or isinstance(v, LazySet):
                return PowerSet(v)
            raise JavaOverrideError(f"Attempted to apply the operator .. to SUBSET of the non-set {fmt(v)}", loc)
        return bound
