"""LET ... IN: definitions bound lazily into frame slots, by name when action-level,
LET operators and LET INSTANCEs.  Separate because the action compiler binds LETs the
same way (`bind_let`).
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from .. import ast as A
from ..env import NOTSET, ByNameLocal, Code, Env, LazyLocal, LetOpLocal
from ..modules import Scope, let_instance_scope
from .closures import Value
from .syntax import all_names
from .host import CompilerHost


class LetMixin(CompilerHost):
    """LET expressions and their definitions."""

    def c_Let(self, e: A.Let, env: Env) -> Code:
        env2, resets = self.bind_let(e.defs, env)
        body = self.expr(e.body, env2)
        if not resets:
            return body

        def let(s: Any, t: Any, L: list) -> Value:
            for sl in resets:
                L[sl] = NOTSET
            return body(s, t, L)
        return let

    def bind_let(self, defs: list[A.OpDef | A.InstanceDef], env: Env) -> tuple[Env, list[int]]:
        resets: list[int] = []
        for d in defs:
            if isinstance(d, A.InstanceDef):
                env = replace(env, scope=self.let_scope(d, env))
                continue
            if d.params:
                local: Any = LetOpLocal(d, env, [env.frame.alloc() for _ in d.params], [])
                env = env.bind(**{d.name: local})
                local.env = env  # may call itself (RECURSIVE)
                continue
            body_expr: A.Expr = A.FnLit(d.loc, d.fn_bounds, d.body) if d.fn_bounds else d.body
            if d.fn_bounds and d.name in all_names(d.body):
                env, reset = self._let_recursive_function(d, env)
                resets.append(reset)
                continue
            if self.info(body_expr, env).action or env.init_mode:
                env = env.bind(**{d.name: ByNameLocal(body_expr, env)})
                continue
            slot = env.frame.alloc()
            code = self.expr(body_expr, env)
            env = env.bind(**{d.name: LazyLocal(slot, code, (body_expr, env),
                                                self.state_source(body_expr, env) is not None)})
            resets.append(slot)
        return env, resets

    def let_scope(self, inst: A.InstanceDef, env: Env) -> Scope:
        """The scope after ``LET I == INSTANCE M ...`` (built once per enclosing scope)."""
        key = (id(inst), id(env.scope))
        scope = self._let_scopes.get(key)
        if scope is None:
            scope = self._let_scopes[key] = let_instance_scope(env.scope, inst, tuple(env.locals))
        return scope
