"""Functions, records and tuples: literals, application, function and record sets, field
access, and EXCEPT with its ``@``.  Tuples are functions on 1..n, so they live here too.

A function literal over an infinite domain (``[i \\in Int |-> i + 2]``) is a lazy
function value, as TLC's FcnLambdaValue: applied pointwise (domain membership, then the
body), ``DOMAIN`` is the infinite set; TLC fails only where it must enumerate it (the
value stored in a state, see checker/storable.py).
"""

from __future__ import annotations

from typing import Any, cast

from .. import ast as A
from ..constfold import NO_VALUE, const_code, const_value
from ..env import NOTSET, Code, Env, SlotLocal
from ..errors import EvalError, Loc, TlaError
from ..specialise import except_flat, dot_code
from ..values import (FnSetValue, FnValue, IntervalSet, LazySet, ModelValue, ProductSet, RecSetValue, fmt, kind, make_fn,
                      member_kind_check, same_kinds)
from .binders import _assign, _enum_checked, _comprehension
from .closures import Value, _guard, _need_set
from .recursive_functions import RecursiveFunction
from .host import CompilerHost


def _update(f: Value, keys: list, i: int, val: Code, s: Any, t: Any, L: list, at_slot: int, loc: Loc) -> Value:
    k = keys[i]
    if type(f) is tuple:
        if not (type(k) is int and 0 < k <= len(f)):
            return f
        old = f[k - 1]
    elif type(f) is FnValue:
        old = f.d.get(k, NOTSET)
        if old is NOTSET:
            return f
    else:
        raise EvalError(f"Attempted to apply EXCEPT to the non-function {fmt(f)}", loc)
    if i + 1 == len(keys):
        L[at_slot] = old
        new = val(s, t, L)
    else:
        new = _update(old, keys, i + 1, val, s, t, L, at_slot, loc)
    if type(f) is tuple:
        return f[:k - 1] + (new,) + f[k:]
    d = dict(f.d)
    d[k] = new
    return FnValue(d)


def _check_argument_kind(fv: FnValue, k: Value, loc: Loc) -> None:
    """TLC's error where applying `fv` to `k` compares values of incomparable kinds
    (``[b \\in BOOLEAN |-> 0][1]``): it looks `k` up in the sorted domain."""
    if not fv.d:
        return
    dom = frozenset(fv.d)
    try:
        if all(type(x) is int for x in dom) and type(k) is not ModelValue and type(k) is not int:
            # TLC keeps a function over an interval of integers as an array.
            lo, hi = min(dom), max(dom)
            if hi - lo + 1 == len(dom):
                raise EvalError(f"Attempted to apply function with integer domain to the non-integer argument {fmt(k)}")
        member_kind_check(k, dom)
        if k in fv.d and not same_kinds(k, next(x for x in fv.d if x == k)):
            raise EvalError(f"Attempted to apply function:\n{fmt(fv)}\nto argument {fmt(k)}, which is "
                            f"not in the domain of the function.")
    except EvalError as err:
        raise err.with_loc(loc) from None


class FunctionsMixin(CompilerHost):
    """Functions, records, tuples and EXCEPT."""

    def c_FnLit(self, e: A.FnLit, env: Env) -> Code:
        inner, binds = self.bind_bounds(e.bounds, env)
        body = self.expr(e.body, inner)
        if len(binds) == 1 and not binds[0][2]:
            set_code, (slot,), _, sloc = binds[0]

            def fnlit(s: Any, t: Any, L: list) -> Value:
                S = set_code(s, t, L)
                if isinstance(S, LazySet) and not S.finite:
                    return RecursiveFunction(S, body, lambda L2, x: L2.__setitem__(slot, x), list(L), s, t)
                if type(S) is IntervalSet and S.lo == 1:
                    out = []
                    for i in range(1, S.hi + 1):
                        L[slot] = i
                        out.append(body(s, t, L))
                    return tuple(out)
                d = {}
                for v in _enum_checked(S, sloc):
                    L[slot] = v
                    d[v] = body(s, t, L)
                return make_fn(d)
            return fnlit
        # Several bound variables: the domain is a product, keys are tuples.
        n_keys = sum(len(sl) if not tup else 1 for _, sl, tup, _ in binds)

        def key_of(L: list) -> Value:
            parts = []
            for _, slots, tup, _ in binds:
                if tup:
                    parts.append(tuple(L[sl] for sl in slots))
                else:
                    parts.append(L[slots[0]])
            return tuple(parts)
        del n_keys
        finite = _comprehension(binds, body, None, key_of)
        set_codes = [b[0] for b in binds]
        loc = e.loc

        def bind(L: list, x: Value) -> None:
            # x is in the product of the domains: one component per bound
            for (_, slots, is_tuple, _), v in zip(binds, x):
                _assign(L, slots, is_tuple, v, loc)

        def fnlit_n(s: Any, t: Any, L: list) -> Value:
            doms = [c(s, t, L) for c in set_codes]
            if any(isinstance(d, LazySet) and not d.finite for d in doms):
                return RecursiveFunction(ProductSet(tuple(doms)), body, bind, list(L), s, t)
            return finite(s, t, L)
        return fnlit_n

    def c_FnApp(self, e: A.FnApp, env: Env) -> Code:
        f = self.expr(e.fn, env)
        loc = e.loc
        if len(e.args) == 1:
            x = self.expr(e.args[0], env)
        else:
            parts = [self.expr(a, env) for a in e.args]
            x = lambda s, t, L: tuple([p(s, t, L) for p in parts])  # noqa: E731

        def app(s: Any, t: Any, L: list) -> Value:
            fv = f(s, t, L)
            k = x(s, t, L)
            if type(fv) is tuple:
                if type(k) is int and 0 < k <= len(fv):
                    return fv[k - 1]
            elif type(fv) is FnValue:
                r = fv.d.get(k, NOTSET)
                if r is not NOTSET:
                    tk = type(k)
                    if tk is str or tk is ModelValue or tk is type(next(iter(fv.d))):
                        return r
                    _check_argument_kind(fv, k, loc)
                    return r
                _check_argument_kind(fv, k, loc)
            elif type(fv) is RecursiveFunction:
                try:
                    return fv.apply(k)
                except EvalError as err:
                    err.with_loc(loc)
                    raise
            elif type(fv) is str and type(k) is int and 0 < k <= len(fv):
                return fv[k - 1]
            else:
                raise EvalError(f"A non-function ({kind(fv)} {fmt(fv)}) was applied as a function.", loc)
            raise EvalError(f"Attempted to apply function:\n{fmt(fv)}\nto argument {fmt(k)}, which is "
                            f"not in the domain of the function.", loc)
        return app

    def c_FnSet(self, e: A.FnSet, env: Env) -> Code:
        d, r = self.expr(e.domain, env), self.expr(e.range, env)
        return _guard(lambda s, t, L: FnSetValue(_need_set(d(s, t, L), "[ -> ]"), _need_set(r(s, t, L), "[ -> ]")),
                      e.loc)

    def c_RecLit(self, e: A.RecLit, env: Env) -> Code:
        names = [n for n, _ in e.fields]
        codes = [self.expr(x, env) for _, x in e.fields]
        return lambda s, t, L: FnValue(dict(zip(names, [c(s, t, L) for c in codes])))

    def c_RecSet(self, e: A.RecSet, env: Env) -> Code:
        names = [n for n, _ in e.fields]
        codes = [self.expr(x, env) for _, x in e.fields]
        return _guard(lambda s, t, L: RecSetValue(tuple(zip(names, [_need_set(c(s, t, L), "[a : S]")
                                                                       for c in codes]))), e.loc)

    def c_Dot(self, e: A.Dot, env: Env) -> Code:
        return dot_code(self.expr(e.rec, env), e.field, e.loc, self.fast_paths)

    def c_TupleLit(self, e: A.TupleLit, env: Env) -> Code:
        codes = [self.expr(x, env) for x in e.elems]
        if len(codes) == 2:
            c0, c1 = codes
            return lambda s, t, L: (c0(s, t, L), c1(s, t, L))
        return lambda s, t, L: tuple([c(s, t, L) for c in codes])

    def c_Except(self, e: A.Except, env: Env) -> Code:
        base = self.expr(e.base, env)
        at_slot = env.frame.alloc()
        inner = env.bind(**{"@": SlotLocal(at_slot)})
        updates = []
        for u in e.updates:
            path = []
            for kind_, item in u.path:
                if kind_ == "field":
                    path.append(const_code(item))
                else:
                    exprs = cast("list[A.Expr]", item)  # an ("index", [exprs]) item
                    if len(exprs) == 1:
                        path.append(self.expr(exprs[0], env))
                    else:
                        parts = [self.expr(x, env) for x in exprs]
                        path.append(lambda s, t, L, parts=parts: tuple([p(s, t, L) for p in parts]))
            updates.append((path, self.expr(u.value, inner)))
        loc = e.loc

        def except_(s: Any, t: Any, L: list) -> Value:
            f = base(s, t, L)
            for path, val in updates:
                keys = [p(s, t, L) for p in path]
                f = _update(f, keys, 0, val, s, t, L, at_slot, loc)
            return f
        if self.fast_paths and all(len(path) == 1 for path, _ in updates):
            flat = []
            for (key,), val in updates:
                kv = const_value(key)
                flat.append((kv if kv is not NO_VALUE and type(kv) is not tuple else (key,), val))
            return except_flat(base, flat, at_slot, except_)
        return except_

    def c_At(self, e: A.At, env: Env) -> Code:
        at = env.locals.get("@")
        if not isinstance(at, SlotLocal):
            raise TlaError("semantic", "@ used outside an EXCEPT update", e.loc)
        slot = at.slot
        return lambda s, t, L: L[slot]
