"""Memoised calls of constant operators: ``Op(a, b)`` whose body reads no variable.

A constant operator (`ConstFolder.def_constant`: no variable, no prime, no recursion, no
side-effecting builtin) gives the same value for the same arguments wherever and
whenever it is called, so its value is kept per operator, keyed by the argument values.
Why: the state-chain models compute ``SubTree(s)``, ``EnterSet(s)`` or
``Transition(src, dst, active)`` (set comprehensions over every state) again in every
state the search meets, and a random walk meets the same arguments again and again.

Only operators that iterate over a set (a quantifier, ``{x \\in S : P}``, ``{e : x \\in S}``,
CHOOSE, a function constructor, an operator argument such as SelectSeq's LAMBDA, or
a call of such an operator) are memoised: for the rest a lookup costs as much as the
call.  The arguments must be pure too (evaluated once for the key, then again by the
ordinary call on a miss).  Even so a table may not pay (a record argument that is new in
every state, a cheap body): each operator measures its first TRIAL_CALLS calls and goes
back to the plain call unless its hits save at least twice what its keys cost.

Exactness: TRUE and 1 are equal Python values (tla/values.py), so the key carries the
kind of every boolean and integer inside the arguments; a value of another kind (a
lazy set such as ``Nat``) is not memoised.  An evaluation error is never kept: the
ordinary call runs and raises it, with its own location.
"""

from __future__ import annotations

from time import perf_counter_ns
from typing import Any, Callable

from . import ast as A
from .constfold import IMPURE_BUILTINS
from .modules import DefSym
from .values import FnValue, ModelValue

Code = Callable[[Any, Any, list], Any]

# An operator's table is dropped (and the operator called plainly) when it reaches
# MAX_ENTRIES, or when over its first TRIAL_CALLS calls it did not pay (OpMemo.wrap).
MAX_ENTRIES = 200_000
TRIAL_CALLS = 2_000

_ITERATING = (A.Quant, A.SetFilter, A.SetMap, A.Choose, A.FnLit, A.Lambda)
_MISS = object()


def _kinds(v: Any) -> Any:
    """A shape of `v` that tells TRUE from 1 at every depth, or _MISS for a value the
    key cannot hold exactly."""
    t = type(v)
    if t is str or t is ModelValue:
        return 0
    if t is int:
        return 1
    if t is bool:
        return 2
    if t is tuple:
        parts: Any = tuple(_kinds(x) for x in v)
        return _MISS if _MISS in parts else parts
    if t is frozenset:
        parts = frozenset(_kinds(x) for x in v)
        return _MISS if _MISS in parts else parts
    if t is FnValue:
        pairs = [(_kinds(k), _kinds(x)) for k, x in v.d.items()]
        return _MISS if any(_MISS in p for p in pairs) else frozenset(pairs)
    return _MISS


class OpMemo:
    """The memo tables of one compiled model, one per constant operator."""

    def __init__(self, compiler: Any) -> None:
        self.c = compiler
        self._worth: dict[int, tuple[DefSym, bool]] = {}
        self.tables: dict[int, dict] = {}
        self.skip: set[int] = set()  # operators whose ordinary call is being compiled

    def applies(self, sym: DefSym, args: list[A.Expr]) -> bool:
        d = sym.defn
        if (not d.params or d.fn_bounds is not None or any(p.arity for p in d.params)
                or id(sym) in self.skip or not self.c.folder.def_constant(sym) or not self.worth(sym)):
            return False
        for a in args:
            names = self.c.folder.free_names(a)
            if names is None or names & IMPURE_BUILTINS:
                return False
        return True

    def worth(self, sym: DefSym) -> bool:
        """Does the body iterate over a set (itself or through an operator it calls)?"""
        hit = self._worth.get(id(sym))
        if hit is not None and hit[0] is sym:
            return hit[1]
        self._worth[id(sym)] = (sym, False)  # recursion guard
        r = self._iterates(sym.defn.body, sym)
        self._worth[id(sym)] = (sym, r)
        return r

    def _iterates(self, e: Any, sym: DefSym) -> bool:
        from .compiler import _children

        if isinstance(e, _ITERATING):
            return True
        if isinstance(e, (A.Name, A.Apply)):
            callee = sym.scope.lookup(e.name)
            if isinstance(callee, DefSym) and self.worth(callee):
                return True
        if isinstance(e, A.Let):
            if any(self._iterates(x.body, sym) for x in e.defs if isinstance(x, A.OpDef)):
                return True
        return any(self._iterates(x, sym) for x in _children(e))

    def wrap(self, sym: DefSym, plain: Code, arg_codes: list[Code]) -> Code:
        """`plain` (the ordinary call), answered from the operator's table when its
        arguments were seen before.  The first TRIAL_CALLS calls measure what the table
        costs (building keys) and saves (the calls it answers); an operator for which it
        does not pay (the flagship's Safety(s): a record per state, a cheap body) goes
        back to the plain call, as does one whose table reaches MAX_ENTRIES.  Either way
        every value is the plain call's: only the speed depends on the measurement."""
        table = self.tables.setdefault(id(sym), {})
        calls = hits = key_ns = plain_ns = 0
        on = True

        def memoised(s: Any, t: Any, L: list) -> Any:
            nonlocal calls, hits, key_ns, plain_ns, on
            if not on:
                return plain(s, t, L)
            trial = calls < TRIAL_CALLS
            if trial:
                t0 = perf_counter_ns()
            try:
                vals = tuple(a(s, t, L) for a in arg_codes)
            except Exception:  # noqa: BLE001 - the ordinary call reports it as before
                return plain(s, t, L)
            kinds = _kinds(vals)
            if kinds is _MISS:
                return plain(s, t, L)
            key = (vals, kinds)
            calls += 1
            r = table.get(key, _MISS)
            if trial:
                t1 = perf_counter_ns()
                key_ns += t1 - t0
            if r is not _MISS:
                hits += 1
            else:
                r = plain(s, t, L)
                table[key] = r
                if trial:
                    plain_ns += perf_counter_ns() - t1
            if calls == TRIAL_CALLS and hits * plain_ns < 2 * key_ns * (calls - hits) or len(table) >= MAX_ENTRIES:
                # kept only if the calls answered from the table saved at least twice
                # what building every key cost
                on = False
                table.clear()
            return r
        return memoised
