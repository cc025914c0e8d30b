"""Bound variables (``x \\in S``, ``<<a, b>> \\in S``): frame slots, enumeration of the
bound set in TLC's order, tuple patterns.  Separate because quantifiers, CHOOSE, set
comprehensions, function literals and the action compiler all bind this way.
"""

from __future__ import annotations

from typing import Any, Callable

from .. import ast as A
from ..env import Code, Env, SlotLocal
from ..errors import EvalError, Loc
from ..values import IntervalSet, LazySet, fmt, kind, make_fn, sorted_elems
from .closures import Value
from .host import CompilerHost


def _enum_checked(S: Value, loc: Loc) -> Any:
    if type(S) is frozenset:
        return sorted_elems(S)
    if type(S) is IntervalSet:
        return range(S.lo, S.hi + 1)
    if isinstance(S, LazySet):
        if not S.finite:
            raise EvalError(f"TLC cannot enumerate the infinite set {S.describe()}", loc)
        return sorted_elems(S)
    raise EvalError(f"Attempted to enumerate the non-set {kind(S)} {fmt(S)}", loc)


def _assign(L: list, slots: list[int], is_tuple: bool, v: Value, loc: Loc) -> None:
    if not is_tuple:
        L[slots[0]] = v
        return
    if type(v) is not tuple or len(v) != len(slots):
        raise EvalError(f"Attempted to match {fmt(v)} against a tuple of {len(slots)} identifiers", loc)
    for sl, x in zip(slots, v):
        L[sl] = x


def _comprehension(binds: list, body: Code, finish: Callable | None, key_of: Callable | None = None) -> Code:
    n = len(binds)

    def run(s: Any, t: Any, L: list) -> Value:
        out: Any = {} if key_of is not None else []

        def rec(i: int) -> None:
            if i == n:
                if key_of is not None:
                    out[key_of(L)] = body(s, t, L)
                else:
                    out.append(body(s, t, L))
                return
            set_code, slots, is_tuple, sloc = binds[i]
            for v in _enum_checked(set_code(s, t, L), sloc):
                _assign(L, slots, is_tuple, v, sloc)
                rec(i + 1)
        rec(0)
        if key_of is not None:
            return make_fn(out)
        return finish(out)  # type: ignore[misc]
    return run


class BindersMixin(CompilerHost):
    """Slots of bound variables."""

    def bind_bounds(self, bounds: list[A.Bound], env: Env) -> tuple[Env, list[tuple[Code, list[int], bool, Loc]]]:
        """Allocate slots for bound variables; returns the body env and, per bound,
        (set code, slots, is-tuple-pattern, loc)."""
        out = []
        inner = env
        for b in bounds:
            set_code = self.expr(b.set, env)
            if b.tuple:
                slots = [env.frame.alloc() for _ in b.names]
                out.append((set_code, slots, True, b.set.loc))
                inner = inner.bind_all({n: SlotLocal(sl) for n, sl in zip(b.names, slots)})
            else:
                for n in b.names:
                    sl = env.frame.alloc()
                    out.append((set_code, [sl], False, b.set.loc))
                    inner = inner.bind(**{n: SlotLocal(sl)})
        return inner, out
