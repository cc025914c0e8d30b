"""Specialised closures for the commonest expression shapes.

Every compiled expression is a closure ``f(s, t, L)``; a call costs far more than
the work inside small ones such as ``L[3]`` or ``"IDLE"``.  The compiler tags the
closures of leaf expressions (a bound variable ``L[slot]``, a state variable
``s[i]``, a LET definition, a constant -- see `constfold.py`), and the builders
below read those leaves directly instead of calling them:

* ``x = c`` / ``x # c`` with a constant ``c`` (guards, CASE arms);
* ``r.f`` on a bound variable, a LET definition or a state variable;
* ``v \\in S`` with a constant set S.

Each builder returns a closure equivalent to the general one (same values, same
errors), only with fewer Python calls.
"""

from __future__ import annotations

from typing import Any, Callable

from .constfold import NO_VALUE, const_value
from .env import NOTSET, Code
from .errors import EvalError, Loc
from .values import FnValue, IntervalSet, ModelValue, fmt, interval_member, member, values_equal

# Types whose Python equality is TLA+ equality when both sides have the type.
_SIMPLE = (str, int, bool, ModelValue)


def slot_read(slot: int) -> Code:
    def read(s: Any, t: Any, L: list) -> Any:
        return L[slot]
    read.slot = slot  # type: ignore[attr-defined]
    return read


def var_read(i: int) -> Code:
    def read(s: Any, t: Any, L: list) -> Any:
        return s[i]
    read.var = i  # type: ignore[attr-defined]
    return read


def lazy_read(slot: int, code: Code) -> Code:
    def lazy(s: Any, t: Any, L: list) -> Any:
        v = L[slot]
        if v is NOTSET:
            v = L[slot] = code(s, t, L)
        return v
    lazy.lazy = (slot, code)  # type: ignore[attr-defined]
    return lazy


def _eq_error(x: Any, y: Any, loc: Loc) -> bool:
    try:
        return values_equal(x, y)
    except EvalError as err:
        err.with_loc(loc)
        raise


def eq_code(a: Code, b: Code, loc: Loc, negate: bool) -> Code | None:
    """``a = b`` (or ``a # b``) when one side is a constant of a simple type."""
    c = const_value(b)
    other = a
    if c is NO_VALUE or type(c) not in _SIMPLE:
        c = const_value(a)
        other = b
        if c is NO_VALUE or type(c) not in _SIMPLE:
            return None
        # TLC's error names the left operand first: 1 = <<1>> is "integer 1 with non-integer".
        def slow(x: Any) -> bool:
            return _eq_error(c, x, loc)
    else:
        def slow(x: Any) -> bool:
            return _eq_error(x, c, loc)
    ct = type(c)
    slot = getattr(other, "slot", None)
    if slot is not None:
        if negate:
            def neq_slot(s: Any, t: Any, L: list) -> bool:
                x = L[slot]
                if type(x) is ct:
                    return x != c
                return not slow(x)
            return neq_slot

        def eq_slot(s: Any, t: Any, L: list) -> bool:
            x = L[slot]
            if type(x) is ct:
                return x == c
            return slow(x)
        return eq_slot
    if negate:
        def neq_const(s: Any, t: Any, L: list) -> bool:
            x = other(s, t, L)
            if type(x) is ct:
                return x != c
            return not slow(x)
        return neq_const

    def eq_const(s: Any, t: Any, L: list) -> bool:
        x = other(s, t, L)
        if type(x) is ct:
            return x == c
        return slow(x)
    return eq_const


def _no_field(rv: Any, name: str, loc: Loc) -> EvalError:
    if type(rv) is FnValue:
        return EvalError(f"Attempted to access nonexistent field '{name}' of record\n{fmt(rv)}", loc)
    return EvalError(f"Attempted to access field '{name}' of the non-record {fmt(rv)}", loc)


def dot_code(r: Code, name: str, loc: Loc, fast: bool = True) -> Code:
    """``r.name``, reading `r` directly when it is a bound variable, a LET
    definition or a state variable."""
    slot = getattr(r, "slot", None) if fast else None
    if slot is not None:
        def dot_slot(s: Any, t: Any, L: list) -> Any:
            rv = L[slot]
            try:
                return rv.d[name]
            except (AttributeError, KeyError, TypeError):
                raise _no_field(rv, name, loc) from None
        return dot_slot
    lazy = getattr(r, "lazy", None) if fast else None
    if lazy is not None:
        lslot, lcode = lazy

        def dot_lazy(s: Any, t: Any, L: list) -> Any:
            rv = L[lslot]
            if rv is NOTSET:
                rv = L[lslot] = lcode(s, t, L)
            try:
                return rv.d[name]
            except (AttributeError, KeyError, TypeError):
                raise _no_field(rv, name, loc) from None
        return dot_lazy
    var = getattr(r, "var", None) if fast else None
    if var is not None:
        def dot_var(s: Any, t: Any, L: list) -> Any:
            rv = s[var]
            try:
                return rv.d[name]
            except (AttributeError, KeyError, TypeError):
                raise _no_field(rv, name, loc) from None
        return dot_var

    def dot(s: Any, t: Any, L: list) -> Any:
        rv = r(s, t, L)
        try:
            return rv.d[name]
        except (AttributeError, KeyError, TypeError):
            raise _no_field(rv, name, loc) from None
    return dot


def _element_type(S: frozenset) -> type | None:
    """The one type of the elements of `S`, if it has one (then a value of that type is
    looked up in `S` by Python alone; any other goes through `member` and its checks
    of TLC's comparisons: ``1 \\in BOOLEAN`` is an error)."""
    types = {type(x) for x in S}
    # Containers are Python-equal across kinds (<<TRUE>> == <<1>>): `member` decides.
    return types.pop() if len(types) == 1 and next(iter(types)) in (bool, int, str) else None


def _member_at(v: Any, S: frozenset, loc: Loc | None) -> bool:
    try:
        return member(v, S)
    except EvalError as err:
        raise (err.with_loc(loc) if loc is not None else err) from None


def _interval_member_at(v: Any, lo: int, hi: int, loc: Loc | None) -> bool:
    try:
        return interval_member(v, lo, hi)
    except EvalError as err:
        raise (err.with_loc(loc) if loc is not None else err) from None


def member_const(lhs: Code, S: Any, negate: bool, loc: Loc | None = None) -> Code | None:
    """``v \\in S`` for a constant finite set or interval S."""
    if type(S) is frozenset:
        T = _element_type(S)
        if negate:
            def notin_set(s: Any, t: Any, L: list) -> bool:
                v = lhs(s, t, L)
                return (v not in S) if type(v) is T else not _member_at(v, S, loc)
            return notin_set

        def in_set(s: Any, t: Any, L: list) -> bool:
            v = lhs(s, t, L)
            return (v in S) if type(v) is T else _member_at(v, S, loc)
        return in_set
    if type(S) is IntervalSet:
        lo, hi = S.lo, S.hi

        def in_interval(s: Any, t: Any, L: list) -> bool:
            v = lhs(s, t, L)
            if type(v) is int:
                return (lo <= v <= hi) is not negate
            return _interval_member_at(v, lo, hi, loc) is not negate
        return in_interval
    return None


def membership_const(S: Any, loc: Loc | None = None) -> Callable | None:
    """A membership test ``test(s, t, L, v)`` for a constant set (see `member_const`)."""
    if type(S) is frozenset:
        T = _element_type(S)
        return lambda s, t, L, v: (v in S) if type(v) is T else _member_at(v, S, loc)
    if type(S) is IntervalSet:
        lo, hi = S.lo, S.hi
        return lambda s, t, L, v: (lo <= v <= hi) if type(v) is int else _interval_member_at(v, lo, hi, loc)
    return None


def except_flat(base: Code, updates: list[tuple[Any, Code]], at_slot: int, general: Code) -> Code:
    """``[f EXCEPT ![k1] = v1, !.g = v2, ...]`` where every path has one step.

    The general closure copies the function once per update; here a record (or a
    tuple) is copied once and updated in place.  `updates` holds (key, value code)
    with the key a constant or, wrapped in a 1-tuple, a closure.  Semantics are
    those of `_update`: keys outside the domain leave the function unchanged, and
    ``@`` is the value after the previous updates.  Other values go to `general`.
    """
    def except_(s: Any, t: Any, L: list) -> Any:
        f = base(s, t, L)
        tf = type(f)
        if tf is FnValue:
            d = f.d
            copied = False
            for key, val in updates:
                k = key[0](s, t, L) if type(key) is tuple else key
                old = d.get(k, NOTSET)
                if old is NOTSET:
                    continue
                L[at_slot] = old
                new = val(s, t, L)
                if not copied:
                    d = dict(d)
                    copied = True
                d[k] = new
            return FnValue(d) if copied else f
        if tf is tuple:
            lst = None
            n = len(f)
            for key, val in updates:
                k = key[0](s, t, L) if type(key) is tuple else key
                if not (type(k) is int and 0 < k <= n):
                    continue
                L[at_slot] = f[k - 1] if lst is None else lst[k - 1]
                new = val(s, t, L)
                if lst is None:
                    lst = list(f)
                lst[k - 1] = new
            return f if lst is None else tuple(lst)
        return general(s, t, L)
    return except_
