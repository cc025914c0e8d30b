"""Constant folding: constant-level sub-expressions are evaluated once, at load time.

An expression is constant when it reads no state variable, no bound variable or
operator argument, no ``@`` and no primed variable, and calls no side-effecting
operator (Print, PrintT, Assert).  The compiler evaluates such an expression right
after compiling it and replaces its closure by one returning the value (tagged
with `const_value` so that enclosing closures can specialise on it, e.g. ``x = "A"``
or ``x \\in {1, 2}``).  If the evaluation fails, the expression keeps its ordinary
closure, so errors are still reported when (and only if) TLC would report them.

Why: a model's guards and updates are full of constant pieces (``D + 1``,
``{"A", "B"} \\cup Operational``, ``NoJog``, ``0..(N - 1)``) that the plain
closures recomputed for every state.
"""

from __future__ import annotations

from typing import Any, Callable

from . import ast as A
from .env import ByNameLocal, Env
from .modules import BuiltinSym, ConstSym, DefSym, VarSym

# Builtins whose evaluation has an effect besides its value.
IMPURE_BUILTINS = frozenset({"Print", "PrintT", "Assert", "TLCGet", "TLCSet"})


def const_code(v: Any) -> Callable:
    """A closure returning the constant `v`, tagged with its value."""
    def const(s: Any, t: Any, L: list) -> Any:
        return v
    const.const_value = v  # type: ignore[attr-defined]
    return const


_NO_VALUE = object()


def const_value(code: Callable) -> Any:
    """The value of a constant closure made by `const_code`, else `NO_VALUE`."""
    return getattr(code, "const_value", _NO_VALUE)


NO_VALUE = _NO_VALUE


class ConstFolder:
    """Decides which expressions are constant (memoised per AST node and definition)."""

    def __init__(self, compiler: Any) -> None:
        self.c = compiler  # its sym_overrides are filled in after construction
        self._free: dict[int, tuple[Any, frozenset[str] | None]] = {}
        self._defs: dict[int, tuple[Any, bool]] = {}

    # ------------------------------------------------------------ free names
    def free_names(self, e: Any) -> frozenset[str] | None:
        """Names `e` refers to (operators included), or None if `e` contains a
        construct that is never constant (primes, ENABLED, instances, ...)."""
        hit = self._free.get(id(e))
        if hit is not None and hit[0] is e:
            return hit[1]
        r = self._compute_free(e)
        self._free[id(e)] = (e, r)
        return r

    def _union(self, exprs: Any, out: set[str]) -> bool:
        for x in exprs:
            f = self.free_names(x)
            if f is None:
                return False
            out |= f
        return True

    def _compute_free(self, e: Any) -> frozenset[str] | None:
        out: set[str] = set()
        t = type(e)
        if t in (A.Num, A.Str, A.Bool):
            return frozenset()
        if t is A.Name or t is A.OpRef:
            return frozenset((e.name,))
        if t is A.Apply:
            out.add(e.name)
            return frozenset(out) if self._union(e.args, out) else None
        if t is A.At:
            return frozenset(("@",))
        if t is A.Binary:
            out.add(e.op)
            return frozenset(out) if self._union((e.lhs, e.rhs), out) else None
        if t is A.Unary:
            if e.op in ("ENABLED", "UNCHANGED", "[]", "<>"):
                return None
            out.add("-." if e.op == "-" else e.op)
            return frozenset(out) if self._union((e.arg,), out) else None
        if t is A.And or t is A.Or:
            return frozenset(out) if self._union(e.items, out) else None
        if t is A.SetEnum or t is A.TupleLit:
            return frozenset(out) if self._union(e.elems, out) else None
        if t is A.FnApp:
            return frozenset(out) if self._union([e.fn, *e.args], out) else None
        if t is A.FnSet:
            return frozenset(out) if self._union((e.domain, e.range), out) else None
        if t is A.RecLit or t is A.RecSet:
            return frozenset(out) if self._union([x for _, x in e.fields], out) else None
        if t is A.Dot:
            return self.free_names(e.rec)
        if t is A.If:
            return frozenset(out) if self._union((e.cond, e.then, e.other), out) else None
        if t is A.Case:
            parts = [x for arm in e.arms for x in arm]
            if e.other is not None:
                parts.append(e.other)
            return frozenset(out) if self._union(parts, out) else None
        if t in (A.Quant, A.FnLit, A.SetMap):
            if not self._union([b.set for b in e.bounds], out):
                return None
            body = self.free_names(e.expr if t is A.SetMap else e.body)
            if body is None:
                return None
            out |= body - {n for b in e.bounds for n in b.names}
            return frozenset(out)
        if t is A.SetFilter:
            s, p = self.free_names(e.bound.set), self.free_names(e.pred)
            if s is None or p is None:
                return None
            return s | (p - set(e.bound.names))
        if t is A.Choose:
            if e.set is None:
                return None
            s, b = self.free_names(e.set), self.free_names(e.body)
            if s is None or b is None:
                return None
            return s | (b - set(e.names))
        if t is A.Lambda:
            b = self.free_names(e.body)
            return None if b is None else b - set(e.params)
        if t is A.Except:
            if not self._union((e.base,), out):
                return None
            for u in e.updates:
                for kind_, item in u.path:
                    if kind_ != "field" and not self._union(item, out):  # type: ignore[arg-type]
                        return None
                v = self.free_names(u.value)
                if v is None:
                    return None
                out |= v - {"@"}
            return frozenset(out)
        if t is A.Let:
            bound = {d.name for d in e.defs}
            for d in e.defs:
                if isinstance(d, A.InstanceDef) or d.fn_bounds:
                    return None
                b = self.free_names(d.body)
                if b is None:
                    return None
                out |= b - {p.name for p in d.params}
            b = self.free_names(e.body)
            if b is None:
                return None
            return frozenset((out | b) - bound)
        # Prime, StepAction, Fairness, UnboundedQuant, Prefixed, Unsupported, ...
        return None

    # ------------------------------------------------------------ constness
    def is_constant(self, e: Any, env: Env) -> bool:
        names = self.free_names(e)
        if names is None:
            return False
        for n in names:
            local = env.locals.get(n)
            if local is not None:
                if isinstance(local, ByNameLocal) and self.is_constant(local.expr, local.env):
                    continue
                return False
            if not self._symbol_constant(n, env.scope.lookup(n)):
                return False
        return True

    def _symbol_constant(self, name: str, sym: Any) -> bool:
        if sym is None:  # a core operator (\cup, =, SUBSET...) or BOOLEAN / STRING
            return True
        override = self.c.sym_overrides.get(id(sym))
        if override is not None:
            sym = override
        if hasattr(sym, "value") or isinstance(sym, ConstSym):
            return True
        if isinstance(sym, BuiltinSym):
            return sym.builtin.name not in IMPURE_BUILTINS
        if isinstance(sym, DefSym):
            return self.def_constant(sym)
        return False  # VarSym, SubstSym, InstanceSym

    def def_constant(self, sym: DefSym) -> bool:
        """Is the body of `sym` constant given constant arguments?  Recursive
        definitions count as non-constant (the check is conservative)."""
        hit = self._defs.get(id(sym))
        if hit is not None and hit[0] is sym:
            return hit[1]
        self._defs[id(sym)] = (sym, False)  # recursion guard
        r = self._def_constant(sym)
        self._defs[id(sym)] = (sym, r)
        return r

    def _def_constant(self, sym: DefSym) -> bool:
        d = sym.defn
        if sym.recursive or d.fn_bounds is not None or sym.scope.parameterised:
            return False
        names = self.free_names(d.body)
        if names is None:
            return False
        params = {p.name for p in d.params}
        for n in names - params:
            s = sym.scope.lookup(n)
            if isinstance(s, VarSym) or not self._symbol_constant(n, s):
                return False
        return True


def fold(code: Callable, frame_size: int) -> Callable:
    """Evaluate a constant expression's closure now; keep the closure if that fails."""
    if hasattr(code, "const_value"):
        return code
    try:
        v = code(None, None, [None] * frame_size)
    except Exception:  # noqa: BLE001 - the error is reported at run time, as TLC does
        return code
    return const_code(v)
