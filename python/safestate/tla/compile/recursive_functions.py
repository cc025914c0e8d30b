"""Recursive function definitions ``f[x \\in S] == ... f[..] ...``, top-level or in a LET:
applied lazily and memoised (`RecursiveFunction`).  Separate because they are the one
family that builds values referring to themselves.
"""

from __future__ import annotations

from typing import Any, Callable

from .. import ast as A
from ..env import NOTSET, Code, Env, Frame, LazyLocal, SlotLocal
from ..errors import EvalError
from ..modules import DefSym
from ..values import LazySet, ProductSet, exact_key, fmt, make_fn, member
from .binders import _assign
from .closures import Value, enum, _guard, _need_set
from .host import CompilerHost


class RecursiveFunction:
    """``f[x \\in S] == body`` referring to itself: applied lazily, memoised.  Each
    application evaluates `body` on a copy of `frame` (the enclosing LET's frame, or a
    fresh one) after `bind` has stored the argument in its slots."""

    __slots__ = ("dom", "body", "bind", "frame", "memo", "s", "t")

    def __init__(self, dom: Value, body: Code, bind: Callable[[list, Value], None], frame: list,
                 s: Any, t: Any) -> None:
        self.dom, self.body, self.bind, self.frame, self.s, self.t = dom, body, bind, frame, s, t
        self.memo: dict = {}

    def apply(self, x: Value) -> Value:
        # Keyed exactly: f[1] is no answer for f[TRUE] (Python's True == 1).
        tx = type(x)
        key = x if tx is int or tx is str else exact_key(x)
        r = self.memo.get(key, NOTSET)
        if r is NOTSET:
            if not member(x, self.dom):
                raise EvalError(f"Attempted to apply function to argument {fmt(x)}, which is not in its domain")
            L = list(self.frame)
            self.bind(L, x)
            r = self.memo[key] = self.body(self.s, self.t, L)
        return r

    @property
    def domain(self) -> Value:
        return self.dom

    def materialize(self) -> Value:
        return make_fn({x: self.apply(x) for x in enum(self.dom)})

    def __repr__(self) -> str:  # `fmt` of a function that is never enumerated
        return f"[x \\in {fmt(self.dom)} |-> ...]"


class RecursiveFunctionsMixin(CompilerHost):
    """Function definitions that may refer to themselves."""

    def _fn_def_ref(self, sym: DefSym) -> Code:
        """A function definition ``f[x \\in S] == e`` (possibly recursive)."""
        d = sym.defn
        assert d.fn_bounds is not None
        if len(d.fn_bounds) != 1 or len(d.fn_bounds[0].names) != 1 or d.fn_bounds[0].tuple:
            # f[m \in S, n \in T] == ... f[..] ...: as a recursive LET function.
            frame = Frame()
            env, fslot = self._let_recursive_function(d, Env(sym.scope, frame))
            read = self.expr(A.Name(d.loc, d.name), env)
            info = self.def_info(sym)
            constant = not info.vars and not info.action
            cache: list = []  # constant-level: the same function every time

            def several(s: Any, t: Any, L: list) -> Value:
                if cache:
                    return cache[0]
                L2: list[Any] = [None] * frame.size
                L2[fslot] = NOTSET
                v = read(s, t, L2)
                if constant:
                    cache.append(v)
                return v
            return several
        compiled: Any = sym.compiled  # once compiled: [domain code, body code, slot, self slot, frame]
        if compiled is None:
            frame = Frame()
            env = Env(sym.scope, frame)
            dom = self.expr(d.fn_bounds[0].set, env)
            slot = frame.alloc()
            self_slot = frame.alloc()
            compiled = sym.compiled = [dom, None, slot, self_slot, frame]
            compiled[1] = self.expr(d.body, env.bind(**{d.fn_bounds[0].names[0]: SlotLocal(slot),
                                                         d.name: SlotLocal(self_slot)}))
        dom_code, _, slot, self_slot, frame = compiled

        def make(s: Any, t: Any, L: list) -> Value:
            body = compiled[1]
            size = frame.size
            dom = dom_code(s, t, [None] * size)

            def with_self(s2: Any, t2: Any, L2: list) -> Value:
                L2[self_slot] = f
                return body(s2, t2, L2)
            f = RecursiveFunction(dom, with_self, lambda L2, x: L2.__setitem__(slot, x), [None] * size, s, t)
            if isinstance(dom, LazySet) and not dom.finite:
                return f
            return f.materialize()
        return make

    def _let_recursive_function(self, d: A.OpDef, env: Env) -> tuple[Env, int]:
        """``LET f[x \\in S] == ... f[..] ... IN``: a `RecursiveFunction` over a copy of the
        LET's frame, so that the body sees the enclosing bound variables."""
        assert d.fn_bounds is not None
        slot = env.frame.alloc()
        holder: list[Code] = []
        env = env.bind(**{d.name: LazyLocal(slot, lambda s, t, L: holder[0](s, t, L))})
        inner, binds = self.bind_bounds(d.fn_bounds, env)
        body = self.expr(d.body, inner)
        set_codes = [b[0] for b in binds]
        loc = d.loc

        def bind(L: list, x: Value) -> None:
            if len(binds) == 1:
                _assign(L, binds[0][1], binds[0][2], x, loc)
                return
            if type(x) is not tuple or len(x) != len(binds):
                raise EvalError(f"Attempted to apply function {d.name} to argument {fmt(x)}, which is not in "
                                f"its domain", loc)
            for (_, slots, is_tuple, _), v in zip(binds, x):
                _assign(L, slots, is_tuple, v, loc)

        def make(s: Any, t: Any, L: list) -> Value:
            doms = [_need_set(c(s, t, L), "function definition") for c in set_codes]
            dom = doms[0] if len(doms) == 1 else ProductSet(tuple(doms))
            frame = list(L)
            f = RecursiveFunction(dom, body, bind, frame, s, t)
            frame[slot] = f
            if isinstance(dom, LazySet) and not dom.finite:
                return f
            return f.materialize()
        holder.append(_guard(make, loc))
        return env, slot
