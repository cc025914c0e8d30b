"""Building blocks of the closures the compiler emits, shared by every expression family:
the boolean check, argument prefixes, error positions, calls of library functions and
operator arguments as Python callables.  Separate because every family module uses them
and none of them compiles syntax.
"""

from __future__ import annotations

from typing import Any, Callable

from ..env import Code
from ..errors import EvalError, Loc
from ..values import IntervalSet, LazySet, fmt, kind, sorted_elems


Value = Any


EMPTY: list = []


def enum(S: Value) -> Any:
    """Elements of a finite set in TLC order (fast paths for frozensets and intervals)."""
    if type(S) is IntervalSet:
        return range(S.lo, S.hi + 1)
    return sorted_elems(S)


def check_bool(v: Value, loc: Loc, what: str = "") -> bool:
    if v is True or v is False:
        return v
    raise EvalError(f"A non-boolean expression ({kind(v)} {fmt(v)}) was used as a "
                    f"{what or 'formula'}", loc)


def _prefix(pre: list[tuple[int, Code]], code: Code) -> Code:
    """Evaluate argument values into their slots, then run `code`."""
    if not pre:
        return code
    if len(pre) == 1:
        (sl, a), = pre

        def pre1(s: Any, t: Any, L: list) -> Value:
            L[sl] = a(s, t, L)
            return code(s, t, L)
        return pre1

    def pren(s: Any, t: Any, L: list) -> Value:
        for sl, a in pre:
            L[sl] = a(s, t, L)
        return code(s, t, L)
    return pren


def _guard(code: Code, loc: Loc) -> Code:
    """Attach `loc` to evaluation errors raised without a position."""
    def guarded(s: Any, t: Any, L: list) -> Value:
        try:
            return code(s, t, L)
        except EvalError as err:
            err.with_loc(loc)
            raise
        except (TypeError, RecursionError) as err:
            raise EvalError(_python_error(err), loc) from None
    return guarded


def _python_error(err: Exception) -> str:
    if isinstance(err, RecursionError):
        return "recursion too deep (an operator or function probably does not terminate)"
    return f"type error: {err}"


def _apply_fn(fn: Callable, codes: list[Code]) -> Code:
    if len(codes) == 1:
        c0, = codes
        return lambda s, t, L: fn(c0(s, t, L))
    if len(codes) == 2:
        c0, c1 = codes
        return lambda s, t, L: fn(c0(s, t, L), c1(s, t, L))
    return lambda s, t, L: fn(*[c(s, t, L) for c in codes])


def _need_set(v: Value, op: str) -> Value:
    if type(v) is frozenset or isinstance(v, LazySet):
        return v
    raise EvalError(f"Attempted to apply {op} to the non-set {fmt(v)}")


def _operator_value(body: Callable, slots: list[int]) -> Callable:
    """A LAMBDA or operator argument as a Python callable: binds its parameters to their
    frame slots for the call and restores them afterwards (the frame is reused)."""
    def make_op(s: Any, t: Any, L: list) -> Callable:
        def op(*vals: Value) -> Value:
            saved = [L[sl] for sl in slots]
            for sl, v in zip(slots, vals):
                L[sl] = v
            try:
                return body(s, t, L)
            finally:
                for sl, v in zip(slots, saved):
                    L[sl] = v
        return op
    return make_op
