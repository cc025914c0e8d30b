"""Sets: enumeration, filter, map, the product ``\\X``, and membership tests compiled
without building the set (intervals, function and record sets, SUBSET, Seq).
"""

from __future__ import annotations

from typing import Any, Callable

from .. import ast as A
from ..constfold import NO_VALUE, const_value
from ..env import Code, Env
from ..errors import EvalError, Loc
from ..modules import BuiltinSym, DefSym
from ..specialise import membership_const
from ..stdlib import non_integer_error
from ..values import (FilteredSet, FnValue, IntervalSet, LazySet, ProductSet, as_set, check_set_kinds, interval_member,
                      is_set, member, tlc_equals)
from .binders import _enum_checked, _assign, _comprehension
from .closures import Value, check_bool, _guard
from .host import CompilerHost


def _lazy_filter(base: LazySet, pred: Code, slots: list[int], is_tuple: bool, sloc: Loc, ploc: Loc,
                 s: Any, t: Any, L: list) -> FilteredSet:
    """{x \\in S : P} over an infinite S: membership tests x \\in S and P(x) (TLC's
    SetPredValue), enumeration is an error."""
    def test(v: Value) -> bool:
        if not base.contains(v):
            return False
        _assign(L, slots, is_tuple, v, sloc)
        return check_bool(pred(s, t, L), ploc, "set filter")
    return FilteredSet(test, f"{{x \\in {base.describe()} : ...}}")


def _kinds_checked(elems: list, loc: Loc) -> frozenset:
    """The set of `elems`, or TLC's error for elements of incomparable kinds."""
    try:
        return check_set_kinds(elems, frozenset(elems))
    except EvalError as err:
        raise err.with_loc(loc) from None


def _domain_is(D: Value, n: int, d: dict | None) -> bool:
    if type(D) is IntervalSet:
        return d is None and D.lo == 1 and D.hi == n or (d is not None and D.size() == n and all(
            type(k) is int and D.lo <= k <= D.hi for k in d))
    S = as_set(D)
    if len(S) != n:
        return False
    if d is None:
        return all(i in S for i in range(1, n + 1))
    return all(k in S for k in d)


class SetsMixin(CompilerHost):
    """Set constructors and membership."""

    def c_SetEnum(self, e: A.SetEnum, env: Env) -> Code:
        codes = [self.expr(x, env) for x in e.elems]
        if all(isinstance(x, (A.Num, A.Str, A.Bool)) for x in e.elems):
            elems = [x.value for x in e.elems]  # type: ignore[attr-defined]
            v = frozenset(elems)
            if len({type(x) for x in elems}) == 1:
                return lambda s, t, L: v
            loc = e.loc
            return lambda s, t, L: _kinds_checked(elems, loc)
        if len(codes) == 1:
            c0 = codes[0]
            return lambda s, t, L: frozenset((c0(s, t, L),))

        loc = e.loc

        def setenum(s: Any, t: Any, L: list) -> frozenset:
            return _kinds_checked([c(s, t, L) for c in codes], loc)
        return setenum

    def _in_enumeration(self, e: A.SetEnum, env: Env) -> Callable[[Any, Any, list, Value], bool]:
        """``v \\in {e1, ..., en}`` as TLC decides it: a set enumeration is not yet
        normalised, so its membership is a scan in the written order with each element's
        ``equals(v)`` (ValueVec.search): elements of other kinds than `v` are an error
        only where the scan reaches them, and none at all once an element equals `v`."""
        codes = [self.expr(x, env) for x in e.elems]
        loc = e.loc

        def in_enum(s: Any, t: Any, L: list, v: Value) -> bool:
            try:
                for c in codes:
                    if tlc_equals(c(s, t, L), v):
                        return True
            except EvalError as err:
                raise err.with_loc(loc) from None
            return False
        # Constant elements of one simple type (`{Idle, Busy}`, names of constants): a value
        # of that type is found by hashing, with the scan's answer; any other goes the scan.
        values = [const_value(c) for c in codes] if self.fast_paths and self.folder.is_constant(e, env) else []
        kinds = {type(x) for x in values}
        if values and NO_VALUE not in values and len(kinds) == 1 and kinds <= {int, str, bool}:
            S, T = frozenset(values), kinds.pop()
            return lambda s, t, L, v: (v in S) if type(v) is T else in_enum(s, t, L, v)
        return in_enum

    def c_SetFilter(self, e: A.SetFilter, env: Env) -> Code:
        inner, binds = self.bind_bounds([e.bound], env)
        pred = self.expr(e.pred, inner)
        set_code, slots, is_tuple, sloc = binds[0]
        ploc = e.pred.loc

        def filt(s: Any, t: Any, L: list) -> Value:
            base = set_code(s, t, L)
            if isinstance(base, LazySet) and not base.finite:
                return _lazy_filter(base, pred, slots, is_tuple, sloc, ploc, s, t, list(L))
            out = []
            for v in _enum_checked(base, sloc):
                _assign(L, slots, is_tuple, v, sloc)
                r = pred(s, t, L)
                if r is True:
                    out.append(v)
                elif r is not False:
                    check_bool(r, ploc, "set filter")
            return frozenset(out)
        return filt

    def c_SetMap(self, e: A.SetMap, env: Env) -> Code:
        inner, binds = self.bind_bounds(e.bounds, env)
        body = self.expr(e.expr, inner)
        loc = e.loc
        if len(binds) == 1 and not binds[0][2]:
            set_code, (slot,), _, sloc = binds[0]

            def smap1(s: Any, t: Any, L: list) -> frozenset:
                out = []
                for v in _enum_checked(set_code(s, t, L), sloc):
                    L[slot] = v
                    out.append(body(s, t, L))
                return _kinds_checked(out, loc) if len(out) > 1 else frozenset(out)
            return smap1
        return _comprehension(binds, body, lambda out: _kinds_checked(out, loc))

    def _product(self, e: A.Apply, env: Env) -> Code:
        codes = [self.expr(x, env) for x in e.args]
        # Factors are checked when the product is used (values.ProductSet), as by TLC.
        return _guard(lambda s, t, L: ProductSet(tuple(c(s, t, L) for c in codes)), e.loc)

    def membership(self, set_expr: A.Expr, env: Env) -> Callable[[Any, Any, list, Value], bool]:
        """Compile ``v \\in set_expr`` without building structured sets."""
        e = set_expr
        if isinstance(e, A.SetEnum) and e.elems and not (len({type(x) for x in e.elems}) == 1
                                                         and isinstance(e.elems[0], (A.Num, A.Str, A.Bool))):
            return self._in_enumeration(e, env)
        if self.fast_paths and self.folder.is_constant(e, env):
            fast = membership_const(const_value(self.expr(e, env)), e.loc)
            if fast is not None:
                return fast
        if isinstance(e, A.Binary) and e.op == ".." and isinstance(env.scope.lookup(".."), BuiltinSym):
            lo = self._interval_bound(e.lhs, self.expr(e.lhs, env), env)
            hi = self._interval_bound(e.rhs, self.expr(e.rhs, env), env)
            loc = e.loc

            def in_interval(s: Any, t: Any, L: list, v: Value) -> bool:
                a, b = lo(s, t, L), hi(s, t, L)
                if type(a) is not int or type(b) is not int:
                    first = type(a) is not int
                    raise non_integer_error("..", a if first else b, first).with_loc(loc)
                if type(v) is int:
                    return a <= v <= b
                try:
                    return interval_member(v, a, b)
                except EvalError as err:
                    raise err.with_loc(loc) from None
            return in_interval
        if isinstance(e, A.FnSet):
            dom = self.expr(e.domain, env)
            rng = self.membership(e.range, env)

            def in_fnset(s: Any, t: Any, L: list, v: Value) -> bool:
                D = dom(s, t, L)
                if type(v) is tuple:
                    if not _domain_is(D, len(v), None):
                        return False
                    vals: Any = v
                elif type(v) is FnValue:
                    if not _domain_is(D, len(v.d), v.d):
                        return False
                    vals = v.d.values()
                else:
                    return False
                for x in vals:
                    if not rng(s, t, L, x):
                        return False
                return True
            return in_fnset
        if isinstance(e, A.RecSet):
            fields = [(n, self.membership(x, env)) for n, x in e.fields]
            nf = len(fields)

            def in_recset(s: Any, t: Any, L: list, v: Value) -> bool:
                if type(v) is not FnValue or len(v.d) != nf:
                    return False
                d = v.d
                for n, test in fields:
                    if n not in d or not test(s, t, L, d[n]):
                        return False
                return True
            return in_recset
        if isinstance(e, A.Unary) and e.op == "SUBSET" and not isinstance(env.scope.lookup("SUBSET"), DefSym):
            base = self.membership(e.arg, env)

            def in_powerset(s: Any, t: Any, L: list, v: Value) -> bool:
                if not is_set(v):
                    return False
                return all(base(s, t, L, x) for x in as_set(v))
            return in_powerset
        if isinstance(e, A.Apply) and e.name == "\\X":
            factors = [self.membership(x, env) for x in e.args]
            n = len(factors)
            return lambda s, t, L, v: (type(v) is tuple and len(v) == n
                                       and all(f(s, t, L, x) for f, x in zip(factors, v)))
        if isinstance(e, A.Apply) and e.name == "Seq" and len(e.args) == 1 and isinstance(
                env.scope.lookup("Seq"), BuiltinSym):
            base = self.membership(e.args[0], env)
            return lambda s, t, L, v: type(v) is tuple and all(base(s, t, L, x) for x in v)
        code = self.expr(e, env)
        return lambda s, t, L, v: member(v, code(s, t, L))
