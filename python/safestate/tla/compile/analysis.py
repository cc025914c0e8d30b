"""Static facts about an expression (`Info`): the state variables it reads and whether it
is action-level.  Separate from the code generation because every family asks these
questions before choosing how to compile (by value, by name, expanded, memoised).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

from .. import ast as A
from ..env import ByNameLocal, Env, Frame
from ..modules import BuiltinSym, DefSym, SubstSym, VarSym
from .syntax import _children
from .host import CompilerHost


@dataclass
class Info:
    """Static facts about an expression: the state variables it reads, whether it is
    action-level (primes / UNCHANGED / ENABLED / actions), whether it reads any state."""

    vars: frozenset[int]
    action: bool


_NO_INFO = Info(frozenset(), False)


# In Info.vars: the expression reads TLCGet's counters (a pseudo-variable).
SEARCH_STATE = -1


class AnalysisMixin(CompilerHost):
    """Variables read and action level of expressions and definitions."""

    def info(self, e: Any, env: Env) -> Info:
        """Variables read and action level of `e` (names resolved in `env`)."""
        vs: set[int] = set()
        action = [False]
        self._walk(e, env, vs, action, set())
        return Info(frozenset(vs), action[0])

    def def_info(self, sym: DefSym) -> Info:
        if sym.info is None:
            sym.info = _NO_INFO  # recursion guard
            env = Env(sym.scope, Frame())
            vs: set[int] = set()
            action = [False]
            self._walk(sym.defn.body, env, vs, action, {p.name for p in sym.defn.params})
            sym.info = Info(frozenset(vs), action[0])
        return sym.info  # type: ignore[return-value]

    def _walk(self, e: Any, env: Env, vs: set[int], action: list[bool], bound: set[str]) -> None:
        if isinstance(e, A.Unary) and e.op == "ENABLED":
            # ENABLED A is a state predicate: it reads the variables A reads.
            self._walk(e.arg, env, vs, [False], bound)
            return
        if isinstance(e, A.Prime) or (isinstance(e, A.Unary) and e.op == "UNCHANGED"):
            action[0] = True
        if isinstance(e, A.StepAction):
            action[0] = True
        if isinstance(e, (A.Name, A.Apply)):
            name = e.name
            if name not in bound:
                loc = env.locals.get(name)
                if isinstance(loc, ByNameLocal):
                    self._walk(loc.expr, loc.env, vs, action, set())
                elif loc is None:
                    sym = self._resolve(name, env.scope)
                    self._walk_sym(sym, env, vs, action)
        if isinstance(e, A.Prefixed):
            pinfo = self._prefixed_info(e, env)
            vs.update(pinfo.vars)
            action[0] = action[0] or pinfo.action
        if isinstance(e, A.Let):
            bound = bound | {d.name for d in e.defs if d.name is not None}
            for d in e.defs:
                if isinstance(d, A.InstanceDef):
                    env = replace(env, scope=self.let_scope(d, env))
                    bound = bound - {d.name}
                    continue
                self._walk(d.body, env, vs, action, bound | {p.name for p in d.params})
            self._walk(e.body, env, vs, action, bound)
            return
        if isinstance(e, A.Lambda):
            self._walk(e.body, env, vs, action, bound | set(e.params))
            return
        if isinstance(e, (A.Quant, A.FnLit, A.SetMap)):
            for b in e.bounds:
                self._walk(b.set, env, vs, action, bound)
            inner = bound | {n for b in e.bounds for n in b.names}
            self._walk(e.body if not isinstance(e, A.SetMap) else e.expr, env, vs, action, inner)
            return
        if isinstance(e, A.SetFilter):
            self._walk(e.bound.set, env, vs, action, bound)
            self._walk(e.pred, env, vs, action, bound | set(e.bound.names))
            return
        if isinstance(e, A.Choose):
            if e.set is not None:
                self._walk(e.set, env, vs, action, bound)
            self._walk(e.body, env, vs, action, bound | set(e.names))
            return
        if isinstance(e, A.UnboundedQuant):
            self._walk(e.body, env, vs, action, bound | set(e.names))
            return
        for child in _children(e):
            self._walk(child, env, vs, action, bound)

    def _walk_sym(self, sym: Any, env: Env, vs: set[int], action: list[bool]) -> None:
        if id(sym) in self.sym_overrides:
            sym = self.sym_overrides[id(sym)]
        if isinstance(sym, VarSym):
            vs.add(sym.index)
        elif isinstance(sym, DefSym):
            i = self.def_info(sym)
            vs.update(i.vars)
            action[0] = action[0] or i.action
        elif isinstance(sym, SubstSym):
            sub_env = Env(sym.scope, env.frame)
            self._walk(sym.expr, sub_env, vs, action, set(sym.instance_params))
        elif isinstance(sym, BuiltinSym) and sym.builtin.name in ("TLCGet", "TLCSet"):
            vs.add(SEARCH_STATE)  # reads the search's counters: never a constant

    def _prefixed_info(self, e: A.Prefixed, env: Env) -> Info:
        scope = self._instance_scope(e, env)
        sym = scope.lookup(e.name)
        if isinstance(sym, DefSym):
            return self.def_info(sym)
        return _NO_INFO
