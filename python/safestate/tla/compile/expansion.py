"""Expansion of an operator's body at its call site: its parameters bound by value
(into fresh frame slots, remembering an argument that reads state) or by name
(action-level arguments).  Separate from `calls.py` because the action compiler
(`actions.py`) expands operators through these too (`inline_def`, `bind_params`).
"""

from __future__ import annotations

from typing import Any, Callable

from .. import ast as A
from ..fold_memo import EXPANSION_LIMIT
from ..env import ByNameLocal, Code, Env, LazyLocal, LetOpLocal, OpLocal, SlotLocal
from ..errors import Loc, UnsupportedError
from ..modules import DefSym
from .syntax import all_names
from .host import CompilerHost


class ExpansionMixin(CompilerHost):
    """Operators expanded at their call site, and the binding of their parameters."""

    def enter_expansion(self, name: str, loc: Loc) -> None:
        """One level deeper into expanded operator bodies (the caller decrements
        `_inline_depth` when done); an expansion this deep is a recursion."""
        self._inline_depth += 1
        if self._inline_depth > EXPANSION_LIMIT:
            raise UnsupportedError(f"recursive action-level operator {name}", loc)
        if self._inline_depth > self.fold_memo.depth_peak:
            self.fold_memo.depth_peak = self._inline_depth

    def inline_let_op(self, name: str, local: LetOpLocal, args: list[A.Expr], env: Env, loc: Loc,
                      compile_body: Callable[[A.Expr, Env], Any]) -> Any:
        """Expand a LET operator at its call site (under a prime, or in an action)."""
        d = local.defn
        self._arity(name, len(d.params), args, loc)
        self.enter_expansion(name, loc)
        try:
            bindings, pre = self.bind_params(d.params, args, env, loc)
            body_env = Env(local.env.scope, env.frame, {**local.env.locals, **bindings},
                           env.init_mode, env.primed)
            return pre, compile_body(d.body, body_env)
        finally:
            self._inline_depth -= 1

    def inline_def(self, sym: DefSym, args: list[A.Expr], env: Env, loc: Loc,
                   compile_body: Callable[[A.Expr, Env], Any]) -> Any:
        """Expand an operator at its call site (action-level operators, Init, instances)."""
        d = sym.defn
        self._arity(d.name, len(d.params), args, loc)
        self.enter_expansion(d.name, loc)
        try:
            bindings, pre = self.bind_params(d.params, args, env, loc)
            inst = {p: env.locals[p] for p in sym.scope.instance_params if p in env.locals}
            body_env = Env(sym.scope, env.frame, {**inst, **bindings}, env.init_mode, env.primed)
            if d.fn_bounds is not None:
                body = compile_body(A.FnLit(d.loc, d.fn_bounds, d.body), body_env)
            else:
                body = compile_body(d.body, body_env)
        finally:
            self._inline_depth -= 1
        return pre, body

    def bind_params(self, params: list[A.Param], args: list[A.Expr], env: Env, loc: Loc) -> tuple[dict, list]:
        """Bind operator parameters: by value into fresh slots (remembering an argument
        that reads state, which a prime in the body primes), or by name for
        action-level arguments (which the body must see unevaluated)."""
        bindings: dict[str, Any] = {}
        pre: list[tuple[int, Code]] = []
        for p, a in zip(params, args):
            if p.arity:
                slot = env.frame.alloc()
                pre.append((slot, self._arg(a, p.arity, env, loc)))
                bindings[p.name] = OpLocal(slot, p.arity)
            elif self.info(a, env).action or env.init_mode:
                bindings[p.name] = ByNameLocal(a, env)
            else:
                slot = env.frame.alloc()
                pre.append((slot, self.expr(a, env)))
                bindings[p.name] = SlotLocal(slot, self.state_source(a, env))
        return bindings, pre

    def _bind_args_by_value(self, args: list[A.Expr], env: Env) -> tuple[dict, list]:
        bindings: dict[str, Any] = {}
        pre: list[tuple[int, Code]] = []
        for i, a in enumerate(args):
            slot = env.frame.alloc()
            pre.append((slot, self.expr(a, env)))
            bindings[f"$arg{i}"] = SlotLocal(slot, self.state_source(a, env))
        return bindings, pre

    def state_source(self, a: A.Expr, env: Env) -> tuple[A.Expr, Env] | None:
        """`a` and its environment if `a` reads state (see `SlotLocal.source`)."""
        if env.primed or env.init_mode:
            return None  # already evaluated in the state that a prime would select
        return (a, env) if self._reads_state(a, env) else None

    def _reads_state(self, a: A.Expr, env: Env) -> bool:
        if self.info(a, env).vars:
            return True
        # A name bound to a state-reading argument reads state too.
        locs = [env.locals.get(n) for n in all_names(a)]
        return any(isinstance(b, (SlotLocal, LazyLocal)) and b.source is not None for b in locs)
