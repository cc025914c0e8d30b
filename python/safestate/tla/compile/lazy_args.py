"""Operator arguments passed unevaluated, as TLC passes them.

TLC binds an operator's parameters to lazy values (`LazyValue`): an argument is
evaluated where the body first uses it, that value is kept for the rest of the call,
and an argument the body never reaches is never evaluated.  So
``\\E m \\in msgs : Handle(m.dest, m)`` with ``Handle(d, m) == m.method = "join" /\\ ...d...``
meets no error for a message without a `dest` field, and neither may we.

Evaluating an argument before the call cannot be told apart from that when the
argument cannot fail (`cannot_fail`: a bound variable, a constant, an unprimed
variable, a literal, a tuple, set or record of these -- the common case, which stays
as fast as before), or when it is the only argument that can fail and the body
evaluates its parameter before anything else (`first_evaluated`: ``IF k = 0 ...``
for the recursive call ``Sum(k - 1)``).  Every other argument is passed lazily:

* to a body expanded in the caller's frame (inlined operators, action-level and Init
  expansions, LAMBDAs): a `LazyArgLocal` slot, reset to NOTSET at the call and filled
  at the first use (`lazy_read`);
* to a body compiled once and run with a frame of its own (recursive, large and LET
  operators): a `Thunk` in the callee's frame, replaced by its value at the first use
  (`thunk_read`).  A thunk keeps the caller's frame, which nothing writes while the
  callee runs -- except a LET operator's, which shares its frame with its caller: its
  thunks keep a copy.  A parameter passed on as an argument is passed as it is, value
  or thunk, as TLC passes its lazy value on.

Lazy parameters cost every read a check and take the fast paths of `specialise.py`
away from the body, so where the body is a value (not an action) the call is
speculative (`speculative`): it evaluates every argument first, as before, and runs
the body compiled for values; only if an argument fails does it run the body compiled
for lazy arguments, which evaluates what TLC evaluates.  An argument's evaluation has
no effect but its value or its error (arguments that print or set TLC registers are
never speculated), so the two cannot be told apart.  The lazy body is compiled with
`Compiler._lazy_mode` set: calls inside it are lazy, not speculative again.
"""

from __future__ import annotations

from typing import Any

from .. import ast as A
from ..constfold import IMPURE_BUILTINS, NO_VALUE, const_value
from ..env import NOTSET, Code, Env, LazyArgLocal, LazyLocal, SlotLocal, ThunkLocal
from ..modules import ConstSym, DefSym, VarSym
from .syntax import all_names


class Thunk:
    """An argument not evaluated yet: its code and the caller's state and frame."""

    __slots__ = ("code", "s", "t", "L")

    def __init__(self, code: Code, s: Any, t: Any, L: list) -> None:
        self.code, self.s, self.t, self.L = code, s, t, L

    def force(self) -> Any:
        return self.code(self.s, self.t, self.L)


def thunk_read(slot: int) -> Code:
    def read(s: Any, t: Any, L: list) -> Any:
        v = L[slot]
        if v.__class__ is Thunk:
            v = L[slot] = v.force()
        return v
    return read


def raw_read(slot: int) -> Code:
    """A `ThunkLocal` parameter passed on unevaluated: its value or its thunk."""
    return lambda s, t, L: L[slot]


def _reset(s: Any, t: Any, L: list) -> Any:
    return NOTSET


def cannot_fail(c: Any, a: A.Expr, env: Env) -> bool:
    """Can evaluating `a` neither raise an error nor cost more than reading a value?"""
    if isinstance(a, (A.Num, A.Str, A.Bool, A.At)):
        return True
    if isinstance(a, A.Name):
        local = env.locals.get(a.name)
        if local is not None:
            return isinstance(local, SlotLocal) and not (env.primed and local.source is not None)
        sym = env.scope.lookup(a.name)
        sym = c.sym_overrides.get(id(sym), sym)
        if hasattr(sym, "value"):
            return True
        if isinstance(sym, ConstSym):
            return a.name in c.constants
        if isinstance(sym, VarSym):
            return not (env.primed or env.init_mode)
        return False
    if isinstance(a, (A.TupleLit, A.SetEnum)):
        return all(cannot_fail(c, x, env) for x in a.elems)
    if isinstance(a, A.RecLit):
        return all(cannot_fail(c, x, env) for _, x in a.fields)
    # A constant the compiler evaluates now (``D + 1``), unless evaluating it fails.
    return c.folder.is_constant(a, env) and const_value(c.expr(a, env)) is not NO_VALUE


def first_evaluated(e: A.Expr, scope: Any = None) -> str | None:
    """The parameter (a name not defined in `scope`, the scope of `e`) whose value
    evaluating `e` reads before anything else, if any.  Looks through the first
    operand of operators, the condition of IF and CASE, a LET definition used first,
    and into the body of a user operator applied first (where that body's first
    parameter stands for the argument given for it)."""
    return _first(e, scope, 0)


_FIRST_MEMO: dict[tuple[int, int], tuple[Any, str | None]] = {}


def _first(e: Any, scope: Any, depth: int) -> str | None:
    key = (id(e), id(scope))
    hit = _FIRST_MEMO.get(key)
    if hit is not None and hit[0] is e:
        return hit[1]
    r = _first_uncached(e, scope, depth)
    _FIRST_MEMO[key] = (e, r)  # the node kept alive: its id stays its own
    return r


def _first_uncached(e: Any, scope: Any, depth: int) -> str | None:
    while depth < 24:
        depth += 1
        if isinstance(e, A.Name):
            if scope is None or scope.lookup(e.name) is None:
                return e.name
            return None
        if isinstance(e, A.Apply):
            sym = scope.lookup(e.name) if scope is not None else None
            if not isinstance(sym, DefSym) or sym.recursive or sym.defn.fn_bounds is not None \
                    or len(sym.defn.params) != len(e.args) or any(p.arity for p in sym.defn.params):
                return None
            q = _first(sym.defn.body, sym.scope, depth)
            names = [p.name for p in sym.defn.params]
            if q not in names:
                return None
            e = e.args[names.index(q)]
        elif isinstance(e, A.Let):
            q = _first(e.body, scope, depth)
            defs = {d.name: d for d in e.defs if isinstance(d, A.OpDef)}
            if q not in defs:
                # a name the LET does not define (an INSTANCE in it: give up)
                return q if len(defs) == len(e.defs) else None
            d = defs[q]
            if d.params or d.fn_bounds is not None:
                return None
            e = d.body
        elif isinstance(e, A.Dot):
            e = e.rec
        elif isinstance(e, A.FnApp):
            e = e.fn
        elif isinstance(e, A.Except):
            e = e.base
        elif isinstance(e, A.Binary) and e.op == "=" and isinstance(e.lhs, A.Prime) \
                and isinstance(e.lhs.arg, A.Name) and scope is not None \
                and isinstance(scope.lookup(e.lhs.arg.name), VarSym):
            e = e.rhs  # x' = e: an assignment evaluates e (reading an assigned x' cannot fail)
        elif isinstance(e, A.Binary):
            e = e.lhs
        elif isinstance(e, A.Unary) and e.op in ("~", "-", "-.", "DOMAIN", "SUBSET", "UNION"):
            e = e.arg
        elif isinstance(e, (A.And, A.Or, A.TupleLit, A.SetEnum)) and (e.items if isinstance(e, (A.And, A.Or))
                                                                     else e.elems):
            e = e.items[0] if isinstance(e, (A.And, A.Or)) else e.elems[0]
        elif isinstance(e, A.If):
            e = e.cond
        elif isinstance(e, A.Case) and e.arms:
            e = e.arms[0][0]
        else:
            return None
    return None


def passed_by_value(c: Any, params: list[A.Param], args: list[A.Expr], body: A.Expr | None, body_scope: Any,
                    env: Env) -> list[bool]:
    """For each argument: may it be evaluated before the call (see the module doc)?"""
    eager = [p.arity > 0 or cannot_fail(c, a, env) for p, a in zip(params, args)]
    risky = [i for i, ok in enumerate(eager) if not ok]
    if len(risky) == 1 and body is not None and first_evaluated(body, body_scope) == params[risky[0]].name:
        eager[risky[0]] = True
    return eager


def lazy_binding(c: Any, a: A.Expr, env: Env, code: Code | None = None
                 ) -> tuple[tuple[int, Code] | None, LazyArgLocal]:
    """A parameter of a body expanded in the caller's frame, bound to argument `a`
    (compiled: `code`) unevaluated: the (slot, reset) the call runs first, if any,
    and the binding."""
    local = env.locals.get(a.name) if isinstance(a, A.Name) else None
    if isinstance(local, LazyLocal) and not env.primed:
        # A parameter or LET definition passed on: the same lazy slot (reset by the outer
        # call or LET), evaluated at most once.
        if type(local) is LazyArgLocal:
            return None, local
        return None, LazyArgLocal(local.slot, local.code, None, False, local.source)
    slot = env.frame.alloc()
    code = c.expr(a, env) if code is None else code
    return (slot, _reset), LazyArgLocal(slot, code, None, False, c.state_source(a, env))


def thunk_code(c: Any, a: A.Expr, env: Env, copy_frame: bool) -> Code:
    """The code passing `a` unevaluated to a body run with its own frame."""
    local = env.locals.get(a.name) if isinstance(a, A.Name) else None
    if isinstance(local, ThunkLocal) and not env.primed:
        return raw_read(local.slot)
    code = c.expr(a, env)
    if const_value(code) is not NO_VALUE:
        return code
    if isinstance(local, LazyLocal) and not copy_frame:
        # A LET definition or lazy parameter: its value if it has one already.
        slot = local.slot

        def lazy_or_value(s: Any, t: Any, L: list) -> Any:
            v = L[slot]
            return Thunk(code, s, t, L) if v is NOTSET else v
        return lazy_or_value
    if copy_frame:
        return lambda s, t, L: Thunk(code, s, t, L.copy())
    return lambda s, t, L: Thunk(code, s, t, L)


def speculable(c: Any, args: list[A.Expr]) -> bool:
    """May these arguments be evaluated and, on an error, evaluated again lazily?"""
    if c._lazy_mode:
        return False
    for a in args:
        names = c.folder.free_names(a)
        if (names if names is not None else all_names(a)) & IMPURE_BUILTINS:
            return False
    return True


def speculative(eager_pre: list[tuple[int, Code]], by_value: Code, lazy: Code) -> Code:
    """Evaluate the arguments into their slots and run `by_value`; if an argument
    fails, run `lazy` (the body with unevaluated arguments) instead."""
    if len(eager_pre) == 1:
        (sl, a), = eager_pre

        def spec1(s: Any, t: Any, L: list) -> Any:
            try:
                L[sl] = a(s, t, L)
            except Exception:  # noqa: BLE001 - the lazy body raises it if TLC would
                return lazy(s, t, L)
            return by_value(s, t, L)
        return spec1

    def spec(s: Any, t: Any, L: list) -> Any:
        try:
            for sl, a in eager_pre:
                L[sl] = a(s, t, L)
        except Exception:  # noqa: BLE001 - the lazy body raises it if TLC would
            return lazy(s, t, L)
        return by_value(s, t, L)
    return spec


def speculative_call(values: list[Code], by_value: Any, thunks: list[Code], lazy: Any) -> Code:
    """The same for a body run with a frame of its own: `by_value` and `lazy` are the
    two compiled versions (`CompiledDef`: body and frame size, read at the call, as a
    recursive body's size is known only once it is compiled)."""
    n = len(values)

    def spec(s: Any, t: Any, L: list) -> Any:
        try:
            frame = [a(s, t, L) for a in values]
        except Exception:  # noqa: BLE001 - the lazy body raises it if TLC would
            return lazy.body(s, t, [a(s, t, L) for a in thunks] + [None] * (lazy.size - n))
        return by_value.body(s, t, frame + [None] * (by_value.size - n))
    return spec
