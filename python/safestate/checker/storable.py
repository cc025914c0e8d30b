"""States TLC cannot store: a variable whose value contains a set it cannot enumerate.

TLC fingerprints every state it keeps, and a fingerprint needs the whole value: an
infinite set (``Nat``, ``STRING``, ``Seq(S)``, ``[Nat -> S]``, ``SUBSET Nat``, a set
built from one) or a function over one (``[i \\in Nat |-> i]``) has none, so TLC stops
with "TLC has found a state in which the value of a variable contains Nat" (or the
message of the enumeration that failed), exit 75.  Such values are legal everywhere
else (``x \\in Nat``, ``f[3]`` of a function over Int), so the check is made where a
state is stored, on new states only: a state that holds one is never stored, so it
can never be met again as a duplicate.
"""

from __future__ import annotations

from typing import Any

from ..tla.compile.recursive_functions import RecursiveFunction
from ..tla.errors import EvalError, Loc, TlaError
from ..tla.values import FilteredSet, FnValue, LazySet, fmt


def unstorable(v: Any) -> str | None:
    """What in `v` has no fingerprint (its printed form), or None if `v` can be stored;
    raises TLC's own error where TLC's Java code throws on such a value (exit 255)."""
    t = type(v)
    if t is int or t is str or t is bool:
        return None
    if t is tuple or t is frozenset:
        for x in v:
            bad = unstorable(x)
            if bad is not None:
                return bad
        return None
    if t is FnValue:
        for k, x in v.d.items():
            bad = unstorable(k)
            if bad is None:
                bad = unstorable(x)
            if bad is not None:
                return bad
        return None
    if isinstance(v, LazySet):
        if type(v) is FilteredSet and v.java_error is not None:
            raise TlaError("general", v.java_error)
        if not v.finite:
            return v.describe()
        try:
            elems = v.materialize()
        except EvalError:
            return v.describe()
        return unstorable(elems)
    if t is RecursiveFunction:
        dom = v.domain
        if isinstance(dom, LazySet) and not dom.finite:
            return f"a function over the infinite set {dom.describe()}"
    return None


def check_storable(st: tuple, names: list[str], loc: Loc) -> None:
    """Raise TLC's evaluation error if a variable of the state `st` cannot be stored."""
    for name, v in zip(names, st):
        t = type(v)
        if t is int or t is str or t is bool:
            continue
        try:
            bad = unstorable(v)
        except TlaError as e:
            raise TlaError(e.kind, e.message, loc) from None
        if bad is not None:
            try:
                shown = f" = {fmt(v)}"
            except EvalError:  # printing a set of infinite sets sorts them
                shown = ""
            raise TlaError("eval", f"TLC has found a state in which the value of a variable contains {bad} "
                           f"(variable {name}{shown}): a state must hold values TLC can enumerate", loc)
